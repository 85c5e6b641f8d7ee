#include "paper/lattice_scene.h"

#include "paper/repro/paper_figures.h"

#include "capsim/scene/parser.h"

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

std::optional<double> table_4_2_screen_share(int spheres, int width, int height) {
  for (std::size_t row = 0; row < paper::kTable42Objects.size(); ++row) {
    if (paper::kTable42Objects[row] != spheres) continue;
    const double per_ray_us = paper::kTable42Seconds[row][0] * 1e6 / (static_cast<double>(width) * height);
    const double met_ray_us = paper::kM380DdaSetupUs + spheres * paper::kM380SphereTestUs;
    return std::min(1.0, per_ray_us / met_ray_us);
  }
  return std::nullopt;
}

namespace {

constexpr double kFieldOfView = 40;  // degrees, across the screen's height

double tan_half_fov() { return std::tan(kFieldOfView / 2 * std::acos(-1.0) / 180); }

// The camera's distance from the near face at which the lattice's universe
// (its spheres' bounds) covers `share` of the screen: the share falls as the
// distance grows, so halve the interval until it is found.
double distance_for_share(const LatticeShape& shape, double aspect, double share) {
  const double wx = 0.5 * (shape.nx - 1) * kLatticeSpacing + kLatticeRadius;
  const double wy = 0.5 * (shape.ny - 1) * kLatticeSpacing + kLatticeRadius;
  auto covered = [&](double d) {
    const double h = d * tan_half_fov();
    return std::min(1.0, wx / (h * aspect)) * std::min(1.0, wy / h);
  };
  double lo = 1e-6, hi = 1e6;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (covered(mid) >= share ? lo : hi) = mid;
  }
  return lo;
}

// The distance at which the camera frames the near face of the reference
// lattice across the shorter screen side, from sphere edge to sphere edge.
double reference_distance(double aspect) {
  const double span = (kLatticeViewSide - 1) * kLatticeSpacing + 2 * kLatticeRadius;
  const double half_height = 0.5 * std::max(span, span / aspect);
  return half_height / tan_half_fov();
}

}  // namespace

std::string lattice_scene_text(const LatticeShape& shape, int width, int height) {
  const double aspect = static_cast<double>(width) / height;
  const std::optional<double> share = table_4_2_screen_share(shape.count(), width, height);
  const double distance = share ? distance_for_share(shape, aspect, *share) : reference_distance(aspect);
  const double fov = kFieldOfView;
  const std::string view =
      share ? fmt::format("its universe covers {:.1f} % of the screen (Table 4-2's 1-division time)", 100 * *share)
            : fmt::format("the camera frames a {} x {} near face", kLatticeViewSide, kLatticeViewSide);
  std::string text = fmt::format(
      "// Table 4-2 test model: {} spheres, {} x {} in the near face, {} deep (capsim lattice {}).\n"
      "// Radius {}, centres {} apart; {}.\n"
      "camera(eye = [0, 0, {}], center = [0, 0, {}], up = [0, 1, 0], fov = {}, size = [{}, {}]);\n"
      "union() {{\n",
      shape.count(), shape.nx, shape.ny, shape.nz, shape.count(), kLatticeRadius, kLatticeSpacing, view,
      kLatticeRadius + distance, kLatticeRadius, fov, width, height);
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
