// OpenSCAD's meshes of sphere, cylinder and cube: their points and faces, and
// the same against OpenSCAD's own STL export of each primitive.

#include "scene/extrusions/openscad_tessellation.h"

#include "capsim/scene/parser.h"
#include "support/cli_run.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>

namespace capsim {
namespace {

using capsim::testing::TempDir;
using namespace capsim::scene_file;

TEST(OpenScadTessellation, FragmentsFollowFnFaFs) {
  const Loc at;
  EXPECT_EQ(fragments_for(10, {0, 12, 2}, at), 30);  // 360 / 12 beats 2 pi 10 / 2
  EXPECT_EQ(fragments_for(1, {0, 12, 2}, at), 5);    // never below 5
  EXPECT_EQ(fragments_for(1, {7.9, 12, 2}, at), 7);  // $fn truncated
  EXPECT_EQ(fragments_for(1, {2, 12, 2}, at), 3);    // and at least 3
  EXPECT_THROW(fragments_for(1, {2e6, 12, 2}, at), SceneError);
}

TEST(OpenScadTessellation, CircleStartsAtAngleZeroWithExactQuarterPoints) {
  const auto c = openscad_circle(2, 4);
  ASSERT_EQ(c.size(), 4u);
  EXPECT_EQ(c[0], glm::dvec2(2, 0));
  EXPECT_EQ(c[1], glm::dvec2(0, 2));
  EXPECT_EQ(c[2], glm::dvec2(-2, 0));
  EXPECT_EQ(c[3], glm::dvec2(0, -2));
}

TEST(OpenScadTessellation, SphereHasRingsOfFragmentsAndIsClosed) {
  const PolygonMesh m = openscad_sphere(1, 8);  // 4 rings of 8
  EXPECT_EQ(m.points.size(), 32u);
  EXPECT_EQ(m.faces.size(), 2u + 3 * 16);  // two caps, 16 triangles between each pair of rings
  // The top ring at 180 / 8 degrees from the pole.
  EXPECT_DOUBLE_EQ(m.points[0].z, std::cos(22.5 * M_PI / 180));
  EXPECT_TRUE(build_closed_mesh(m).mesh.has_value());
}

TEST(OpenScadTessellation, ConeApexIsOnePoint) {
  const PolygonMesh m = openscad_cylinder(2, 1, 0, true, 6);
  EXPECT_EQ(m.points.size(), 7u);
  EXPECT_EQ(m.faces.size(), 7u);
  const MeshBuild b = build_closed_mesh(m);
  ASSERT_TRUE(b.mesh.has_value());
  EXPECT_EQ(b.mesh->bounds.lo.z, -1);
  EXPECT_EQ(b.mesh->bounds.hi.z, 1);
}

TEST(OpenScadTessellation, CubeIsEightPointsSixQuads) {
  const PolygonMesh m = openscad_cube({1, 2, 3}, true);
  EXPECT_EQ(m.points.size(), 8u);
  EXPECT_EQ(m.faces.size(), 6u);
  ASSERT_TRUE(build_closed_mesh(m).mesh.has_value());
  EXPECT_EQ(build_closed_mesh(m).mesh->bounds.lo, glm::dvec3(-0.5, -1, -1.5));
}

bool have_openscad() { return std::system("command -v openscad >/dev/null 2>&1") == 0; }

// The hull of one primitive is that primitive's mesh: its corners must be
// the points of OpenSCAD's STL export of it, one for one.
void expect_points_of_openscads_stl(const std::string& primitive) {
  TempDir dir;
  const std::string scad = dir / "p.scad", stl = dir / "p.stl";
  std::ofstream(scad) << primitive << "\n";
  ASSERT_EQ(std::system(fmt::format("openscad -o '{}' '{}' >/dev/null 2>&1", stl, scad).c_str()), 0);
  const Scene theirs = parse_scene(fmt::format("import(\"{}\");", stl), "t.csg");
  const Scene ours = parse_scene(fmt::format("hull() {}", primitive), "t.csg");
  const auto& a = ours.primitives.at(0).mesh->vertices;
  const auto& b = theirs.primitives.at(0).mesh->vertices;
  EXPECT_EQ(a.size(), b.size()) << primitive;
  for (const glm::dvec3& p : a) {
    double nearest = 1e300;
    for (const glm::dvec3& q : b) nearest = std::min(nearest, glm::length(p - q));
    EXPECT_LT(nearest, 1e-5) << primitive << " point " << p.x << " " << p.y << " " << p.z;
  }
}

TEST(OpenScadTessellation, PointsAreThoseOfOpenScadsExport) {
  if (!have_openscad()) GTEST_SKIP() << "openscad not installed";
  for (const char* p : {"sphere(r = 10);", "sphere(r = 3, $fn = 7);", "sphere(d = 5, $fa = 5, $fs = 0.5);",
                        "cylinder(h = 4, r1 = 2, r2 = 1, center = true, $fn = 9);", "cylinder(h = 3, r = 2);",
                        "cylinder(h = 3, r1 = 2, r2 = 0);", "cube([1, 2, 3], center = true);"})
    expect_points_of_openscads_stl(p);
}

}  // namespace
}  // namespace capsim
