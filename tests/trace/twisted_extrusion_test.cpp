// Twisted and unevenly scaled linear_extrude: OpenSCAD's slices and
// tessellation, checked against its STL export and against the exact
// twisted surface.

#include "capsim/scene/parser.h"
#include "scene/extrusions/twisted_extrusion.h"
#include "support/cli_run.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>

namespace capsim {
namespace {

using capsim::testing::TempDir;

const TriangleMesh& lone_mesh(const std::string& text) {
  static Scene s;
  s = parse_scene(text, "t.csg");
  EXPECT_EQ(s.primitives.size(), 1u);
  return *s.primitives.at(0).mesh;
}

TEST(TwistedExtrusion, SlicesFollowOpenScad) {
  // twist 90 at $fa = 12: 8 slices ($fs would allow 14); 9 rings of 4 corners.
  EXPECT_EQ(lone_mesh("linear_extrude(height = 20, twist = 90) square([20, 10], center = true);").vertices.size(),
            36u);
  // $fn = 12: a twelfth of a turn per slice.
  EXPECT_EQ(lone_mesh("linear_extrude(height = 5, twist = 180, $fn = 12) square(2);").vertices.size(), 4u * 7);
  // Given slices win; scale 0 closes the top at one point.
  EXPECT_EQ(lone_mesh("linear_extrude(height = 40, twist = -360, scale = 0, slices = 200) square([20, 10], center = "
                      "true);")
                .vertices.size(),
            4u * 200 + 1);
  // Different scales without a twist: the longest path over $fs.
  const scene_file::Sweep s{10, 0, {1, 2}, 1, false};
  EXPECT_EQ(scene_file::openscad_slices(0, 4, s, 0, 12, 2), 6);  // sqrt(4 + 100) / 2 = 5.1
}

TEST(TwistedExtrusion, CornersLieOnTheExactSurfaceAndQuadCentresWithinTheMeasuredError) {
  // The Basics example's twisted square: 8 slices of 11.25 degrees.
  const TriangleMesh& m = lone_mesh("linear_extrude(height = 20, twist = 90) square([20, 10], center = true);");
  for (const glm::dvec3& v : m.vertices) {
    const double turn = -90 * v.z / 20 * M_PI / 180;  // clockwise
    const glm::dvec2 back(std::cos(-turn) * v.x - std::sin(-turn) * v.y, std::sin(-turn) * v.x + std::cos(-turn) * v.y);
    EXPECT_NEAR(std::abs(back.x), 10, 1e-12);
    EXPECT_NEAR(std::abs(back.y), 5, 1e-12);
  }
  // The exact surface at the middle of each side quad against the middle of
  // the diagonal the quad is split along (where the split strays most).
  double worst = 0;
  const glm::dvec2 c[4] = {{-10, -5}, {10, -5}, {10, 5}, {-10, 5}};
  for (int j = 0; j < 8; ++j)
    for (int k = 0; k < 4; ++k) {
      const auto at = [](glm::dvec2 p, double deg) {
        const double a = -deg * M_PI / 180;
        return glm::dvec2(std::cos(a) * p.x - std::sin(a) * p.y, std::sin(a) * p.x + std::cos(a) * p.y);
      };
      const glm::dvec2 a = c[k], b = c[(k + 1) % 4];
      const glm::dvec2 exact = at((a + b) / 2.0, 11.25 * (j + 0.5));
      const glm::dvec2 d1 = (at(a, 11.25 * j) + at(b, 11.25 * (j + 1))) / 2.0;
      const glm::dvec2 d2 = (at(b, 11.25 * j) + at(a, 11.25 * (j + 1))) / 2.0;
      worst = std::max(worst, std::min(glm::length(exact - d1), glm::length(exact - d2)));
    }
  std::printf("twisted square: the split strays up to %.4f from the exact surface (of a half-width 11.18)\n", worst);
  EXPECT_LT(worst, 0.96);  // 0.956 on the long faces: docs/scene-format.md
}

bool have_openscad() { return std::system("command -v openscad >/dev/null 2>&1") == 0; }

TEST(TwistedExtrusion, TheMeshIsOpenScadsExport) {
  if (!have_openscad()) GTEST_SKIP() << "openscad not installed";
  for (const char* model : {"linear_extrude(height = 20, twist = 90) square([20, 10], center = true);",
                            "linear_extrude(height = 10, twist = -200, scale = [0.5, 1.5]) translate([2, 0, 0]) "
                            "circle(3, $fn = 7);"}) {
    TempDir dir;
    const std::string scad = dir / "p.scad", stl = dir / "p.stl";
    std::ofstream(scad) << model << "\n";
    ASSERT_EQ(std::system(fmt::format("openscad -o '{}' '{}' >/dev/null 2>&1", stl, scad).c_str()), 0);
    const Scene theirs = parse_scene(fmt::format("import(\"{}\");", stl), "t.csg");
    const TriangleMesh& b = *theirs.primitives.at(0).mesh;
    const TriangleMesh& a = lone_mesh(model);
    EXPECT_EQ(a.vertices.size(), b.vertices.size()) << model;
    EXPECT_EQ(a.triangles.size(), b.triangles.size()) << model;
    for (const glm::dvec3& p : a.vertices) {
      double nearest = 1e300;
      for (const glm::dvec3& q : b.vertices) nearest = std::min(nearest, glm::length(p - q));
      EXPECT_LT(nearest, 1e-4) << model;
    }
  }
}

TEST(TwistedExtrusion, SeveralLeavesAreCutAtTheCaps) {
  // A twisted ring: the circle less a smaller one, each swept, the caps cut by a slab.
  const Scene s = parse_scene("linear_extrude(height = 4, twist = 60) difference() { circle(5); circle(2); }", "t.csg");
  ASSERT_EQ(s.primitives.size(), 3u);
  EXPECT_EQ(s.primitives[0].kind, PrimitiveKind::Box);
  EXPECT_LT(s.primitives[1].mesh->bounds.lo.z, 0.0);  // the collar below the bottom
  EXPECT_GT(s.primitives[1].mesh->bounds.hi.z, 4.0);
}

}  // namespace
}  // namespace capsim
