// 2-D regions through Clipper (scene/regions/region_2d.h): offsets against their
// closed forms, the even-odd rule on crossing paths, DXF files, 2-D-only
// designs, and every refusal at its FILE:LINE:COL.

#include "scene/regions/region_2d.h"

#include "capsim/scene/parser.h"
#include "capsim/scene/scene_limits.h"
#include "scene/regions/dxf_import.h"
#include "scene/reading/scene_lexer.h"
#include "support/cli_run.h"
#include "support/polygon2d_area.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <memory_resource>
#include <numbers>

namespace capsim {
namespace {

using capsim::testing::TempDir;
using scene_file::Polygon2d;
using testing::area;

// A scene text's calls, read as the parser reads them.
class Calls {
 public:
  explicit Calls(std::string_view text)
      : tokens_(scene_file::tokenize(text, std::make_shared<const std::string>("t.csg"))),
        calls_(scene_file::read_calls(tokens_, &memory_, &end_)) {}
  const scene_file::Call& first() const { return calls_.front(); }

 private:
  scene_file::Tokens tokens_;
  std::pmr::monotonic_buffer_resource memory_;
  scene_file::Loc end_;
  std::pmr::vector<scene_file::Call> calls_;
};

// The region of the first call of `text`.
Polygon2d region(std::string_view text, const std::string& dir = ".") {
  return scene_file::evaluate_region(Calls(text).first(), {dir, 1 << 20});
}

std::string refusal(std::string_view text, const std::string& file = "t.csg") {
  try {
    parse_scene(text, file);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "parsed without error";
}

void write(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

TEST(Region2d, RoundOffsetOfASquareIsItsClosedFormUpToTheTessellation) {
  // s^2 + 4 s r + pi r^2; the corners' arcs are polygons of 360 sides.
  const double s = 10, r = 2;
  const double a = area(region("offset(r = 2, $fn = 360) square(10);"));
  EXPECT_NEAR(a, s * s + 4 * s * r + std::numbers::pi * r * r, 0.001 * std::numbers::pi * r * r);
  EXPECT_LT(a, s * s + 4 * s * r + std::numbers::pi * r * r);  // the arcs' vertices lie on the circle
}

TEST(Region2d, MiterAndChamferOffsetsAreExact) {
  EXPECT_NEAR(area(region("offset(delta = 2) square(10);")), 196, 1e-6);
  // Clipper's square join cuts each corner at the offset distance from the
  // vertex: a right isosceles triangle of legs 2 (2 sqrt 2 - 2) off each.
  const double leg = 2 * std::sqrt(2.0) - 2;
  EXPECT_NEAR(area(region("offset(delta = 2, chamfer = true) square(10);")), 196 - 4 * leg * leg, 1e-3);
  EXPECT_NEAR(area(region("offset(r = -2) square(10);")), 36, 1e-6);
}

TEST(Region2d, CircleHasOpenScadsFragments) {
  // $fa = 12, $fs = 2, r = 10: 30 fragments; their polygon's area.
  const Polygon2d c = region("circle(r = 10);");
  ASSERT_EQ(c.outlines.size(), 1u);
  EXPECT_EQ(c.outlines[0].vertices.size(), 30u);
  EXPECT_NEAR(area(c), 15 * 100 * std::sin(2 * std::numbers::pi / 30), 1e-3);
}

TEST(Region2d, CrossingPathsFollowTheEvenOddRule) {
  // A bow tie: two triangles of area 25 each.
  EXPECT_NEAR(area(region("polygon([[0, 0], [10, 10], [10, 0], [0, 10]]);")), 50, 1e-6);
  // Two overlapping squares as paths of one polygon: their overlap is out.
  EXPECT_NEAR(area(region("polygon([[0, 0], [10, 0], [10, 10], [0, 10], [5, 5], [15, 5], [15, 15], [5, 15]], "
                          "[[0, 1, 2, 3], [4, 5, 6, 7]]);")),
              150, 1e-6);
  // The union of the same squares as shapes covers the overlap once.
  EXPECT_NEAR(area(region("union() { square(10); translate([5, 5, 0]) square(10); }")), 175, 1e-6);
  EXPECT_NEAR(area(region("intersection() { square(10); translate([5, 5, 0]) square(10); }")), 25, 1e-6);
  EXPECT_NEAR(area(region("difference() { square(10); translate([5, 5, 0]) square(10); }")), 75, 1e-6);
}

TEST(Region2d, CrossingPolygonIsExtrudedAsItsRegion) {
  // Two prisms meeting at the crossing, and the slab that cuts their caps.
  const Scene s = parse_scene("linear_extrude(height = 2) polygon([[0, 0], [10, 10], [10, 0], [0, 10]]);", "t.csg");
  EXPECT_EQ(s.primitives.size(), 3u);
}

// Four LINEs of a square on layer A, a CIRCLE on layer B, an open pair of
// lines on layer C, a SPLINE on layer D.
constexpr const char* kDxf =
    "0\nSECTION\n2\nENTITIES\n"
    "0\nLINE\n8\nA\n10\n0\n20\n0\n11\n10\n21\n0\n"
    "0\nLINE\n8\nA\n10\n10\n20\n0\n11\n10\n21\n10\n"
    "0\nLINE\n8\nA\n10\n10\n20\n10\n11\n0\n21\n10\n"
    "0\nLINE\n8\nA\n10\n0\n20\n10\n11\n0\n21\n0\n"
    "0\nCIRCLE\n8\nB\n10\n20\n20\n0\n40\n5\n"
    "0\nLINE\n8\nC\n10\n0\n20\n0\n11\n10\n21\n0\n"
    "0\nLINE\n8\nC\n10\n10\n20\n0\n11\n10\n21\n10\n"
    "0\nSPLINE\n8\nD\n"
    "0\nENDSEC\n0\nEOF\n";

TEST(Region2d, DxfLayersOriginAndScale) {
  TempDir dir;
  write(dir / "d.dxf", kDxf);
  EXPECT_NEAR(area(region("import(\"d.dxf\", layer = \"A\");", dir.path().string())), 100, 1e-9);
  EXPECT_NEAR(area(region("import(\"d.dxf\", layer = \"A\", scale = 2, origin = [5, 5]);", dir.path().string())), 400, 1e-9);
  const Polygon2d circle = region("import(file = \"d.dxf\", layer = \"B\", $fn = 6);", dir.path().string());
  ASSERT_EQ(circle.outlines.size(), 1u);
  EXPECT_EQ(circle.outlines[0].vertices.size(), 6u);
  EXPECT_NEAR(area(circle), 1.5 * std::sqrt(3.0) * 25, 1e-3);
  // An open outline is closed by a straight edge, as OpenSCAD closes it:
  // (0, 0) - (10, 0) - (10, 10) becomes a right triangle.
  const Polygon2d open = region("import(\"d.dxf\", layer = \"C\");", dir.path().string());
  ASSERT_EQ(open.outlines.size(), 1u);
  EXPECT_EQ(open.outlines[0].vertices.size(), 3u);
  EXPECT_NEAR(area(open), 50, 1e-9);
  // Placed by origin: x from -5 to 5.
  const Polygon2d moved = region("import(\"d.dxf\", layer = \"A\", origin = [5, 0]);", dir.path().string());
  double lo = 1e9;
  for (const auto& v : moved.outlines.at(0).vertices) lo = std::min(lo, v.x);
  EXPECT_EQ(lo, -5);
}

TEST(Region2d, DxfRefusalsNameTheFileLine) {
  TempDir dir;
  write(dir / "d.dxf", kDxf);
  const std::string scene = dir / "s.csg";
  auto refused = [&](const std::string& call) { return refusal(call, scene); };
  EXPECT_NE(refused("linear_extrude(1) import(\"d.dxf\", layer = \"D\");").find("d.dxf:88: the SPLINE entity is not read"),
            std::string::npos);
  EXPECT_NE(refused("linear_extrude(1) import(\"d.dxf\", layer = \"Q\");").find("the layer 'Q' draws no lines"),
            std::string::npos);
  EXPECT_NE(refused("linear_extrude(1) import(\"gone.dxf\");").find(":1:26: cannot import 'gone.dxf': there is no "
                                                                     "such file"),
            std::string::npos);
  write(dir / "bad.dxf", "0\nSECTION\n2\nENTITIES\n0\nLINE\n8\nA\n10\nten\n");
  EXPECT_NE(refused("linear_extrude(1) import(\"bad.dxf\");").find("bad.dxf:10: the value 'ten' is not a number"),
            std::string::npos);
  write(dir / "big.dxf", "0\nSECTION\n2\nENTITIES\n0\nCIRCLE\n8\nA\n10\n0\n20\n0\n40\n5\n0\nENDSEC\n");
  EXPECT_NE(refused("linear_extrude(1) import(\"big.dxf\", $fn = 1e8);").find("big.dxf:6: the CIRCLE entity"),
            std::string::npos);
}

TEST(Region2d, RefusalsAreLocated) {
  EXPECT_EQ(refusal("linear_extrude(1) offset(r = -10) square(10);"),
            "t.csg:1:19: offset() draws nothing: its 2-D shape encloses no area");
  EXPECT_NE(refusal("linear_extrude(1) offset(r = 1, $fn = 1e7) square(10);").find("t.csg:1:19: offset():"),
            std::string::npos);
  EXPECT_NE(refusal("linear_extrude(1) offset(1) cube(1);").find("t.csg:1:29: cube() is not a 2-D shape"),
            std::string::npos);
  EXPECT_NE(refusal("linear_extrude(1) offset(1) square(1e20);").find("t.csg:1:36: a clipped square's size"), std::string::npos);
  EXPECT_NE(refusal("offset(delta = 1e30) square(1);").find("t.csg:1:16:"), std::string::npos);
}

TEST(Region2d, FlatDesignIsOneUnitThickCentredOnZeroAndKeepsItsColours) {
  const Scene s = parse_scene("color(\"red\") square(10); translate([20, 0, 0]) color(\"blue\") circle(3);", "t.csg");
  ASSERT_EQ(s.primitives.size(), 2u);
  for (const Primitive& p : s.primitives) {
    const Aabb b = placed_bounds(p);
    EXPECT_DOUBLE_EQ(b.lo.z, -0.5);
    EXPECT_DOUBLE_EQ(b.hi.z, 0.5);
  }
  EXPECT_NE(s.primitives[0].color, s.primitives[1].color);
  // A 2-D difference is clipped or cut as one flat shape.
  const Scene d = parse_scene("difference() { square(10); translate([5, 5, 0]) offset(1) square(2); }", "t.csg");
  EXPECT_EQ(d.primitives.size(), 3u);  // the square, the clipped offset and the slab cutting the caps
}

TEST(Region2d, RegionPathsServeOtherExtrusions) {
  const Calls calls("difference() { square(10, center = true); circle(2, $fn = 8); }");
  const auto paths = scene_file::region_paths(calls.first(), {".", 1 << 20});
  ASSERT_EQ(paths.size(), 2u);  // the square's outline and the octagon's hole
  EXPECT_EQ(paths[0].size() + paths[1].size(), 12u);
}

// hull() of 2-D shapes: CGAL's hull of every outline vertex, one outline
// counter-clockwise from the lowest-x point. Two diamonds ($fn = 4 circles)
// four apart give a hexagon.
TEST(Region2d, HullIsTheConvexHullOfEveryVertex) {
  const Polygon2d h = region("hull() { circle(1, $fn = 4); translate([4, 0]) circle(1, $fn = 4); }");
  ASSERT_EQ(h.outlines.size(), 1u);
  const std::vector<glm::dvec2> want{{-1, 0}, {0, -1}, {4, -1}, {5, 0}, {4, 1}, {0, 1}};
  ASSERT_EQ(h.outlines[0].vertices.size(), want.size());
  for (std::size_t k = 0; k < want.size(); ++k) {
    EXPECT_NEAR(h.outlines[0].vertices[k].x, want[k].x, 1e-12) << k;
    EXPECT_NEAR(h.outlines[0].vertices[k].y, want[k].y, 1e-12) << k;
  }
  EXPECT_NEAR(area(h), 10, 1e-9);
}

// minkowski() of 2-D shapes, OpenSCAD's way through Clipper: a square plus
// a diamond is the octagon of the square grown by it (4 x 4 less four half
// unit corners); a frame's hole shrinks to what the diamond fits into (the
// shapes placed inside each other fill the middle); three squares add up.
TEST(Region2d, MinkowskiSumsTheShapes) {
  const Polygon2d octagon = region("minkowski() { square(2); circle(1, $fn = 4); }");
  EXPECT_EQ(octagon.outlines.size(), 1u);
  EXPECT_NEAR(area(octagon), 14, 1e-9);
  const Polygon2d frame =
      region("minkowski() { difference() { square(10); translate([3, 3]) square(4); } circle(1, $fn = 4); }");
  EXPECT_EQ(frame.outlines.size(), 2u);
  EXPECT_NEAR(area(frame), 142 - 4, 1e-9);
  EXPECT_NEAR(area(region("minkowski() { square(1); square(1); square(1); }")), 9, 1e-9);
  EXPECT_NEAR(area(region("minkowski() { square(3); }")), 9, 1e-9);
}

// Both extrude, revolve and draw alone (1 unit thick) like any 2-D shape,
// and a 3-D child among their 2-D ones is refused at the child.
TEST(Region2d, HullAndMinkowskiAreShapesEverywhere) {
  for (const char* text : {"linear_extrude(height = 2) hull() { circle(1); translate([3, 0]) square(1); }",
                           "rotate_extrude() translate([3, 0]) minkowski() { square(1); circle(0.5); }",
                           "hull() { circle(1); translate([3, 0]) circle(1); }"}) {
    const Scene s = parse_scene(text, "t.csg");
    EXPECT_FALSE(s.primitives.empty()) << text;
  }
  // Alone, as its extrusion 1 unit thick centred on z = 0.
  const Scene flat = parse_scene("minkowski() { square(2); circle(1, $fn = 4); }", "t.csg");
  const Scene slab =
      parse_scene("linear_extrude(height = 1, center = true) minkowski() { square(2); circle(1, $fn = 4); }", "t.csg");
  ASSERT_EQ(flat.primitives.size(), slab.primitives.size());
  for (std::size_t k = 0; k < flat.primitives.size(); ++k) {
    EXPECT_EQ(flat.primitives[k].kind, slab.primitives[k].kind);
    EXPECT_EQ(flat.primitives[k].to_world, slab.primitives[k].to_world);
  }
  EXPECT_EQ(refusal("linear_extrude(height = 1) hull() {\n  circle(1);\n  cube(1);\n}").substr(0, 41),
            "t.csg:3:3: cube() is not a 2-D shape: 2-D");
}

}  // namespace
}  // namespace capsim
