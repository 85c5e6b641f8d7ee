#include "paper/lattice_scene.h"

#include "capsim/parser.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace capsim::sim {

LatticeShape lattice_shape(int spheres) {
  if (spheres < 1 || spheres > kMaxLatticeSpheres)
    throw std::invalid_argument(
        fmt::format("a lattice of {} spheres: the count must be 1 to {}", spheres, kMaxLatticeSpheres));
  int side = 1;
  for (int a = 2; a * a * a <= spheres; ++a)
    if (spheres % (a * a) == 0) side = a;
  return {side, side, spheres / (side * side)};
}

std::string lattice_scene_text(const LatticeShape& shape, int width, int height) {
  // The camera frames the near face of the reference lattice: its span across
  // the shorter screen side, from sphere edge to sphere edge, at 40 degrees.
  const double fov = 40;
  const double span = (kLatticeViewSide - 1) * kLatticeSpacing + 2 * kLatticeRadius;
  const double aspect = static_cast<double>(width) / height;
  const double half_height = 0.5 * std::max(span, span / aspect);
  const double distance = half_height / std::tan(fov / 2 * std::acos(-1.0) / 180);
  std::string text = fmt::format(
      "// Table 4-2 test model: {} spheres, {} x {} in the near face, {} deep (capsim lattice {}).\n"
      "// Radius {}, centres {} apart; the camera frames a {} x {} near face.\n"
      "camera(eye = [0, 0, {}], center = [0, 0, {}], up = [0, 1, 0], fov = {}, size = [{}, {}]);\n"
      "union() {{\n",
      shape.count(), shape.nx, shape.ny, shape.nz, shape.count(), kLatticeRadius, kLatticeSpacing,
      kLatticeViewSide, kLatticeViewSide, kLatticeRadius + distance, kLatticeRadius, fov, width, height);
  for (int z = 0; z < shape.nz; ++z)
    for (int y = 0; y < shape.ny; ++y)
      for (int x = 0; x < shape.nx; ++x)
        text += fmt::format("  translate([{}, {}, {}]) sphere(r = {});\n",
                            (x - 0.5 * (shape.nx - 1)) * kLatticeSpacing,
                            (y - 0.5 * (shape.ny - 1)) * kLatticeSpacing, 0.0 - z * kLatticeSpacing, kLatticeRadius);
  text += "}\n";
  return text;
}

Scene make_sphere_lattice(const LatticeShape& shape, int width, int height) {
  return parse_scene(lattice_scene_text(shape, width, height),
                     fmt::format("lattice {}x{}x{}", shape.nx, shape.ny, shape.nz));
}

}  // namespace capsim::sim
