// The sphere lattices of Table 4-2: their shapes, their scene files (written by
// `capsim lattice`, read back unchanged), and the one view all share.

#include "paper/lattice_scene.h"
#include "support/cli_run.h"

#include "capsim/scene/parser.h"
#include "capsim/trace/prepared_scene.h"
#include "capsim/trace/render.h"

#include <fmt/core.h>
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace capsim::sim {
namespace {

using capsim::testing::read_file;
using capsim::testing::run_capsim;
using capsim::testing::TempDir;

void expect_shape(int spheres, int nx, int ny, int nz) {
  const LatticeShape s = lattice_shape(spheres);
  EXPECT_EQ(s.nx, nx) << spheres;
  EXPECT_EQ(s.ny, ny) << spheres;
  EXPECT_EQ(s.nz, nz) << spheres;
  EXPECT_EQ(s.count(), spheres);
}

TEST(Lattice, ShapesAreCubesOrTheNearestWithASquareFace) {
  expect_shape(16, 2, 2, 4);
  expect_shape(512, 8, 8, 8);
  expect_shape(1000, 10, 10, 10);
  expect_shape(4096, 16, 16, 16);
  expect_shape(6859, 19, 19, 19);
  expect_shape(1, 1, 1, 1);
  expect_shape(7, 1, 1, 7);     // a prime: one column
  expect_shape(12, 2, 2, 3);
  expect_shape(64, 4, 4, 4);
  expect_shape(128, 4, 4, 8);   // not 8 x 8 x 2: the face no wider than the depth
  EXPECT_THROW(lattice_shape(0), std::invalid_argument);
  EXPECT_THROW(lattice_shape(kMaxLatticeSpheres + 1), std::invalid_argument);
}

TEST(Lattice, SpheresSitOnTheGridCentredOnTheViewAxis) {
  const Scene s = make_sphere_lattice(lattice_shape(16), 64, 64);
  ASSERT_EQ(s.primitives.size(), 16u);
  double sx = 0, sy = 0;
  for (const Primitive& p : s.primitives) {
    EXPECT_EQ(p.kind, PrimitiveKind::Sphere);
    const glm::dvec3 c(p.to_world[3]);
    EXPECT_DOUBLE_EQ(std::abs(c.x), 1.5);  // half the spacing either side of the axis
    EXPECT_DOUBLE_EQ(std::abs(c.y), 1.5);
    EXPECT_EQ(std::fmod(-c.z, kLatticeSpacing), 0.0);  // layers 0, -3, -6, -9
    EXPECT_DOUBLE_EQ(p.to_world[0][0], kLatticeRadius);
    sx += c.x;
    sy += c.y;
  }
  EXPECT_EQ(sx, 0.0);
  EXPECT_EQ(sy, 0.0);
}

TEST(Lattice, TheScreenShareFollowsTable42sOneDivisionColumn) {
  // 102 s over 512^2 rays is 389 us a ray, more than a 3DDDA set-up and 16
  // sphere tests (325 us): all of the screen. 825 s is 3147 us a ray against
  // 9352 us for one that meets 512 spheres: about a third.
  EXPECT_EQ(table_4_2_screen_share(16, 512, 512), 1.0);
  EXPECT_NEAR(*table_4_2_screen_share(512, 512, 512), 0.3365, 1e-4);
  EXPECT_NEAR(*table_4_2_screen_share(1000, 512, 512), 0.3291, 1e-4);
  EXPECT_NEAR(*table_4_2_screen_share(4096, 512, 512), 0.6697, 1e-4);
  EXPECT_NEAR(*table_4_2_screen_share(6859, 512, 512), 0.9966, 1e-4);
  // Fewer rays for the same seconds: each ray took longer, a larger share.
  EXPECT_NEAR(*table_4_2_screen_share(512, 256, 256), 1.0, 1e-12);
  EXPECT_FALSE(table_4_2_screen_share(64, 512, 512));
}

// The share of primary rays that meet the lattice's universe (start a 3DDDA).
double screen_met(int spheres, int size) {
  PrepareOptions prep;
  prep.grid = 1;
  const PreparedScene scene = prepare_scene(make_sphere_lattice(lattice_shape(spheres), size, size), prep);
  const Tracer tracer(scene, TraceOptions{.primary_only = true});
  RenderStats stats;
  render(tracer, 1, &stats);
  return static_cast<double>(stats.ops.dda_setups) / static_cast<double>(stats.ops.primary_rays);
}

TEST(Lattice, EachRowCoversItsShareOfTheScreen) {
  EXPECT_EQ(screen_met(16, 512), 1.0);
  EXPECT_NEAR(screen_met(512, 512), *table_4_2_screen_share(512, 512, 512), 0.005);
  EXPECT_NEAR(screen_met(1000, 512), *table_4_2_screen_share(1000, 512, 512), 0.005);
}

TEST(Lattice, ACountTheTableLacksIsFramedByTheReferenceFace) {
  // 64 spheres (4 x 4 x 4) under the camera that frames a 19 x 19 face: a
  // near face 9.6 units across where the screen spans 54.6, (9.6 / 54.6)^2 =
  // 3.1 % of the screen (22 of 128 pixels across: 2.95 %).
  const double met = screen_met(64, 128);
  EXPECT_GT(met, 0.027);
  EXPECT_LT(met, 0.034);
}

TEST(CliLattice, WritesTheSceneThatRunsUse) {
  TempDir dir;
  const auto r = run_capsim("lattice 512 -o " + (dir / "l.csg") + " --size 80x60", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("512 spheres, 8 x 8 x 8"), std::string::npos) << r.out;
  const std::string text = read_file(dir / "l.csg");
  EXPECT_EQ(text, lattice_scene_text(lattice_shape(512), 80, 60));
  const Scene parsed = parse_scene_file(dir / "l.csg");
  const Scene built = make_sphere_lattice(lattice_shape(512), 80, 60);
  ASSERT_EQ(parsed.primitives.size(), built.primitives.size());
  for (std::size_t i = 0; i < built.primitives.size(); ++i)
    EXPECT_EQ(parsed.primitives[i].to_world, built.primitives[i].to_world) << i;
  EXPECT_EQ(parsed.camera->eye, built.camera->eye);
  EXPECT_EQ(parsed.camera->width, 80);
  EXPECT_EQ(parsed.camera->height, 60);
}

// The voxel generation sweep's lattices (bench/sweeps/lattices) are what
// `capsim lattice N -o FILE` writes at its default size: they can be made again.
TEST(Lattice, TheSweepsLatticeFilesAreTheGeneratorsOwn) {
  for (const int n : {16, 512, 1000, 4096, 6859}) {
    const std::string file = fmt::format("{}/bench/sweeps/lattices/lattice-{}.csg", CAPSIM_SOURCE_DIR, n);
    EXPECT_EQ(read_file(file), lattice_scene_text(lattice_shape(n), 512, 512)) << file;
  }
}

TEST(CliLattice, RefusesACountOutOfRangeAndWritesNothing) {
  TempDir dir;
  for (const char* count : {"0", "1000001"}) {
    const auto r = run_capsim(std::string("lattice ") + count + " -o " + (dir / "l.csg"), dir);
    EXPECT_EQ(r.status, 2) << count;
    EXPECT_NE(r.err.find("is out of range (accepted: a whole number from 1 to 1000000)"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "l.csg"));
  }
}

}  // namespace
}  // namespace capsim::sim
