#include "lattice_scene.h"

#include <fmt/core.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <memory>

namespace capsim::sim {

Scene make_sphere_lattice(int nx, int ny, int nz, int width, int height) {
  Scene scene;
  SourceLoc loc;
  loc.file = std::make_shared<const std::string>(fmt::format("lattice {}x{}x{}", nx, ny, nz));
  scene.root.is_leaf = false;
  scene.root.op = CsgOp::Union;
  scene.root.loc = loc;
  for (int z = 0; z < nz; ++z)
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) {
        Primitive p;
        p.kind = PrimitiveKind::Sphere;
        p.to_world = glm::translate(glm::dmat4(1.0), glm::dvec3(x, y, -z) * kLatticeSpacing);
        p.loc = loc;
        CsgNode leaf;
        leaf.is_leaf = true;
        leaf.primitive = static_cast<int>(scene.primitives.size());
        leaf.loc = loc;
        scene.root.children.push_back(leaf);
        scene.primitives.push_back(p);
      }

  // The near face spans [-1, (n - 1) * spacing + 1] in x and y, at z = +1.
  const double span_x = (nx - 1) * kLatticeSpacing + 2;
  const double span_y = (ny - 1) * kLatticeSpacing + 2;
  const double aspect = static_cast<double>(width) / height;
  const double half_height = 0.5 * std::max(span_y, span_x / aspect);  // the face fits, and fills one axis
  Camera cam;
  cam.fov_deg = 40;
  const double distance = half_height / std::tan(glm::radians(cam.fov_deg / 2));
  const glm::dvec3 centre(0.5 * (nx - 1) * kLatticeSpacing, 0.5 * (ny - 1) * kLatticeSpacing, 1.0);
  cam.eye = centre + glm::dvec3(0, 0, distance);
  cam.center = centre;
  cam.up = {0, 1, 0};
  cam.width = width;
  cam.height = height;
  scene.camera = cam;
  return scene;
}

}  // namespace capsim::sim
