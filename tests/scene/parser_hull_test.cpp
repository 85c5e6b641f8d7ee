// hull(), minkowski() and surface(): the meshes they make and every refusal
// at its FILE:LINE:COL.

#include "capsim/scene/parser.h"
#include "scene/meshes/convex_hull.h"
#include "support/cli_run.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <fstream>

namespace capsim {
namespace {

using capsim::testing::TempDir;

std::string refusal(std::string_view text, const std::string& file = "t.csg") {
  try {
    parse_scene(text, file);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "parsed without error";
}

double volume(const TriangleMesh& m) {
  double v6 = 0;
  for (const auto& t : m.triangles)
    v6 += glm::dot(m.vertices[t[0]], glm::cross(m.vertices[t[1]], m.vertices[t[2]]));
  return v6 / 6;
}

TEST(ConvexHull, OfACubesCornersAndCentreIsTheCube) {
  std::vector<glm::dvec3> p;
  for (int k = 0; k < 8; ++k) p.emplace_back(k & 1, (k >> 1) & 1, (k >> 2) & 1);
  p.emplace_back(0.5, 0.5, 0.5);
  const HullBuild h = convex_hull(p);
  ASSERT_TRUE(h.mesh.has_value());
  EXPECT_EQ(h.mesh->vertices.size(), 8u);
  EXPECT_EQ(h.mesh->triangles.size(), 12u);
  EXPECT_NEAR(volume(*h.mesh), 1.0, 1e-12);  // positive: counter-clockwise seen from outside
}

TEST(ConvexHull, FlatPointsAreRefused) {
  EXPECT_FALSE(convex_hull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 3, 0}}).mesh.has_value());
  EXPECT_FALSE(convex_hull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}).mesh.has_value());
}

TEST(Hull, OfTwoCubesIsTheirBoxWithTheColourAround) {
  const Scene s = parse_scene("color([1, 0, 0]) translate([1, 0, 0]) hull() { cube(1); translate([2, 0, 0]) cube(1); }",
                              "t.csg");
  ASSERT_EQ(s.primitives.size(), 1u);
  const Primitive& p = s.primitives[0];
  EXPECT_EQ(p.kind, PrimitiveKind::Mesh);
  EXPECT_EQ(p.mesh->bounds.lo, glm::dvec3(0));
  EXPECT_EQ(p.mesh->bounds.hi, glm::dvec3(3, 1, 1));
  EXPECT_NEAR(volume(*p.mesh), 3.0, 1e-12);
  EXPECT_EQ(glm::dvec3(p.to_world[3]), glm::dvec3(1, 0, 0));
  EXPECT_EQ(p.color.y, 0.0);
}

TEST(Hull, OfSpheresUsesOpenScadsPoints) {
  // Two spheres of 30 fragments (r = 10 at $fa = 12): 15 rings of 30 each.
  const Scene s = parse_scene("hull() { sphere(10); translate([0, 0, 50]) sphere(10); }", "t.csg");
  const TriangleMesh& m = *s.primitives[0].mesh;
  EXPECT_EQ(m.vertices.size(), 2u * 15 * 30 - 2 * 30 * 7);  // the rings inside the hull are gone
  EXPECT_DOUBLE_EQ(m.bounds.hi.x, 10.0);                   // the point at angle 0 of the equator ring
}

TEST(Hull, Refusals) {
  EXPECT_EQ(refusal("hull() { }"), "t.csg:1:1: hull() has no solid children: it encloses nothing");
  EXPECT_EQ(refusal("hull() { cube(1); %sphere(3); }\nhull() *cube(2);"),
            "t.csg:2:1: hull() has no solid children: it encloses nothing");
  EXPECT_EQ(refusal("hull() {\n  difference() { cube(2); square(1); }\n}").substr(0, 36),
            "t.csg:2:27: square() under hull() or");
  // A 2-D first child makes a 2-D hull (drawn flat): a solid after it is refused.
  EXPECT_EQ(refusal("hull() { cube(1); square(2); }").substr(0, 39), "t.csg:1:19: square() under hull() or mi");
  EXPECT_EQ(refusal("hull() !cube(1);").substr(0, 30), "t.csg:1:8: the '!' (root) modi");
  EXPECT_EQ(refusal("hull(convexity = 2, 3) cube(1);").substr(0, 11), "t.csg:1:21:");
  EXPECT_EQ(refusal("hull() sphere(1, $fn = 5000);").substr(0, 26), "t.csg:1:8: sphere would ha");
}

TEST(Minkowski, OfABoxAndASphereIsTheirSum) {
  const Scene s = parse_scene("minkowski(convexity = 2) { cube(2, center = true); sphere(1, $fn = 8); }", "t.csg");
  const TriangleMesh& m = *s.primitives[0].mesh;
  // $fn = 8: rings at 22.5 and 67.5 degrees from the poles.
  const double top = std::cos(22.5 * M_PI / 180), side = std::sin(67.5 * M_PI / 180);
  EXPECT_DOUBLE_EQ(m.bounds.hi.z, 1 + top);
  EXPECT_DOUBLE_EQ(m.bounds.hi.x, 1 + side);
  EXPECT_DOUBLE_EQ(m.bounds.lo.x, -1 - side);
}

// The sum of a union is the union of its solids' sums (tests/trace/minkowski_test.cpp
// traces them); the hull of a union is one convex part.
TEST(Minkowski, OfAUnionIsASumPerSolid) {
  EXPECT_EQ(parse_scene("minkowski() {\n  sphere(1);\n  union() { cube(1); translate([3, 0, 0]) cube(1); }\n}", "t.csg")
                .primitives.size(),
            2u);
  EXPECT_EQ(parse_scene("minkowski() { sphere(1); hull() { cube(1); translate([3, 0, 0]) cube(1); } }", "t.csg")
                .primitives.size(),
            1u);
}

TEST(Surface, ADatFileGivesOpenScadsMesh) {
  TempDir dir;
  std::ofstream(dir / "h.dat") << "# heights\n1 2\n\n3 4\n";
  const Scene s = parse_scene("surface(file = \"h.dat\", center = false, invert = false, timestamp = 3);",
                              dir / "t.csg");
  const TriangleMesh& m = *s.primitives.at(0).mesh;
  // Four corners, the cell's centre at their mean 2.5, the base at 0 (the
  // lowest height less one) with its own centre.
  EXPECT_EQ(m.vertices.size(), 10u);
  EXPECT_EQ(m.bounds.lo, glm::dvec3(0));
  EXPECT_EQ(m.bounds.hi, glm::dvec3(1, 1, 4));
  EXPECT_NEAR(volume(m), 2.5, 1e-12);  // a quarter of the cell under each triangle
  const Scene c = parse_scene("surface(\"h.dat\", true);", dir / "t.csg");
  EXPECT_EQ(c.primitives.at(0).mesh->bounds.lo, glm::dvec3(-0.5, -0.5, 0));
}

TEST(Surface, BaseIsOneBelowTheLowestHeight) {
  TempDir dir;
  std::ofstream(dir / "h.dat") << "5 5 5\n5 5 5\n";
  const Scene s = parse_scene("surface(\"h.dat\");", dir / "t.csg");
  EXPECT_EQ(s.primitives.at(0).mesh->bounds.lo.z, 0.0);
  std::ofstream(dir / "n.dat") << "-5 5 5\n5 5 5\n";
  EXPECT_EQ(parse_scene("surface(\"n.dat\");", dir / "t.csg").primitives.at(0).mesh->bounds.lo.z, -6.0);
}

// A PNG's signature and header (width by height, 8-bit grey) and an empty
// image data chunk: enough to be read as far as the size, not the pixels.
std::string png_header(std::uint32_t width, std::uint32_t height) {
  auto be32 = [](std::uint32_t v) {
    return std::string{static_cast<char>(v >> 24), static_cast<char>(v >> 16), static_cast<char>(v >> 8),
                       static_cast<char>(v)};
  };
  auto chunk = [&](const std::string& type_and_data) {
    std::uint32_t crc = 0xffffffffu;
    for (unsigned char c : type_and_data) {
      crc ^= c;
      for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1)));
    }
    return be32(static_cast<std::uint32_t>(type_and_data.size() - 4)) + type_and_data + be32(~crc);
  };
  return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR" + be32(width) + be32(height) + std::string{8, 0, 0, 0, 0}) +
         chunk("IDAT") + chunk("IEND");
}

TEST(Surface, Refusals) {
  TempDir dir;
  const std::string scene = dir / "t.csg";
  std::ofstream(dir / "bad.dat") << "1 2\n3 x4\n";
  EXPECT_EQ(refusal("surface(file = \"bad.dat\");", scene),
            fmt::format("{}:1:16: cannot read the height map: {}:2:3: 'x4' is not a height (a finite number within "
                        "1e30)",
                        scene, dir / "bad.dat"));
  std::ofstream(dir / "row.dat") << "1 2 3\n";
  EXPECT_NE(refusal("surface(\"row.dat\");", scene).find("at least 2 rows and 2 columns"), std::string::npos);
  EXPECT_NE(refusal("surface(\"none.dat\");", scene).find("cannot import 'none.dat'"), std::string::npos);
  std::ofstream(dir / "huge.png", std::ios::binary) << png_header(100000, 100000);
  EXPECT_NE(refusal("surface(\"huge.png\");", scene).find("100000 by 100000 heights, more than the 1000000"),
            std::string::npos);
  std::ofstream(dir / "cut.png", std::ios::binary) << png_header(4, 4);
  EXPECT_NE(refusal("surface(\"cut.png\");", scene).find("the PNG image is damaged"), std::string::npos);
  EXPECT_EQ(refusal("surface();", scene), scene + ":1:1: surface needs the file to read: surface(\"heights.dat\")");
  EXPECT_EQ(refusal("linear_extrude(1) surface(\"h.dat\");", scene).substr(scene.size(), 40),
            ":1:19: surface() is not a 2-D shape: lin");
}

}  // namespace
}  // namespace capsim
