// linear_extrude of square, circle, polygon and text, read and traced: the
// exact solids each 2-D leaf becomes, the 2-D tree as the 3-D one with the caps cut once, and
// every refusal at its FILE:LINE:COL.

#include "capsim/scene/parser.h"
#include "capsim/trace/tracer.h"
#include "support/scene_refusal.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace capsim {
namespace {

using testing::refusal;

// The first hit straight down from above (x, y), +inf on a miss.
double depth_from_above(const std::string& text, double x, double y) {
  PrepareOptions options;
  options.width = options.height = 8;
  const PreparedScene ps = prepare_scene(parse_scene(text, "t.csg"), options);
  const Tracer tracer(ps, {});
  Tracer::Scratch s(ps);
  OpCounts ops;
  Hit h;
  return tracer.first_hit(Ray{{x, y, 100}, {0, 0, -1}, 0, kInfinity}, s, ops, h) ? h.t : kInfinity;
}

TEST(ParserExtrusion, ACircleExtrudedIsTheCylinderToTheBit) {
  const std::pair<const char*, const char*> same[] = {
      {"linear_extrude(height = 3, center = true) circle(r = 2);", "cylinder(h = 3, r = 2, center = true);"},
      {"linear_extrude(height = 3, scale = [0.5, 0.5]) circle(d = 4);", "cylinder(h = 3, r1 = 2, r2 = 1);"},
      {"linear_extrude(height = 3, scale = 2) circle(1);", "cylinder(h = 3, r1 = 1, r2 = 2);"},
      {"linear_extrude(3, scale = 0) circle(1);", "cylinder(h = 3, r1 = 1, r2 = 0);"},
  };
  for (const auto& [extruded, cylinder] : same) {
    const Scene a = parse_scene(extruded, "t.csg"), b = parse_scene(cylinder, "t.csg");
    ASSERT_EQ(a.primitives.size(), 1u) << extruded;
    EXPECT_EQ(a.primitives[0].kind, PrimitiveKind::Cone);
    EXPECT_EQ(a.primitives[0].to_world, b.primitives[0].to_world) << extruded;
    EXPECT_EQ(a.primitives[0].cone_r1, b.primitives[0].cone_r1) << extruded;
    EXPECT_EQ(a.primitives[0].cone_r2, b.primitives[0].cone_r2) << extruded;
  }
}

TEST(ParserExtrusion, ASquareExtrudedIsABoxAndScaledAFrustum) {
  const Scene a = parse_scene("linear_extrude(height = 3) square(size = [1, 2], center = true);", "t.csg");
  const Scene b = parse_scene("translate([-0.5, -1, 0]) cube([1, 2, 3]);", "t.csg");
  ASSERT_EQ(a.primitives.size(), 1u);
  EXPECT_EQ(a.primitives[0].kind, PrimitiveKind::Box);
  EXPECT_EQ(a.primitives[0].to_world, b.primitives[0].to_world);
  // Scaled by a half about the origin: the top is the square [0, 0.5]^2 at z = 4.
  const std::string frustum = "linear_extrude(height = 4, scale = 0.5) translate([0.5, 0.5, 0]) square(1, center = true);";
  const Scene f = parse_scene(frustum, "t.csg");
  ASSERT_EQ(f.primitives.size(), 1u);
  EXPECT_EQ(f.primitives[0].kind, PrimitiveKind::Mesh);
  EXPECT_EQ(f.primitives[0].mesh->bounds.hi, glm::dvec3(1, 1, 4));
  EXPECT_DOUBLE_EQ(depth_from_above(frustum, 0.25, 0.25), 96);
  EXPECT_DOUBLE_EQ(depth_from_above(frustum, 0.75, 0.25), 98);  // the side x = 1 - z / 8, at z = 2
}

TEST(ParserExtrusion, TwoDBooleansAreTheSolidsBooleansWithTheCapsCutOnce) {
  // A plate less a circle and less a triangle that has a hole of its own.
  const std::string plate =
      "linear_extrude(height = 2) difference() {\n"
      "  square(10);\n"
      "  translate([3, 3, 0]) circle(r = 1);\n"
      "  polygon(points = [[6, 6], [9, 6], [6, 9], [6.5, 6.5], [7.5, 6.5], [6.5, 7.5]], paths = [[0, 1, 2], [3, 4, 5]]);\n"
      "}";
  const Scene s = parse_scene(plate, "t.csg");
  // The slab, the square, the circle and the polygon's two paths.
  ASSERT_EQ(s.primitives.size(), 5u);
  EXPECT_EQ(s.root.children[0].op, CsgOp::Intersection);
  EXPECT_DOUBLE_EQ(depth_from_above(plate, 1, 1), 98);            // the plate's top
  EXPECT_EQ(depth_from_above(plate, 3, 3), kInfinity);             // through the round hole
  // The triangle with a hole is subtracted: its rim cuts through, its hole keeps the plate.
  EXPECT_EQ(depth_from_above(plate, 7.2, 7.2), kInfinity);
  EXPECT_EQ(depth_from_above(plate, 6.2, 6.2), kInfinity);
  EXPECT_DOUBLE_EQ(depth_from_above(plate, 6.7, 6.7), 98);
  EXPECT_DOUBLE_EQ(depth_from_above("linear_extrude(2) intersection() { square(4); circle(1); }", 0.5, 0.5), 98);
}

// OpenSCAD's even-odd rule: a point is in the polygon when an odd number of
// its paths hold it: two outlines apart, and an island in a hole.
TEST(ParserExtrusion, PolygonPathsFollowTheEvenOddRule) {
  const std::string nested =
      "linear_extrude(height = 1) polygon(points = [[0, 0], [10, 0], [10, 10], [0, 10], [2, 2], [8, 2], [8, 8], "
      "[2, 8], [4, 4], [6, 4], [6, 6], [4, 6], [20, 0], [22, 0], [22, 2], [20, 2]], paths = [[0, 1, 2, 3], "
      "[4, 5, 6, 7], [8, 9, 10, 11], [12, 13, 14, 15]]);";
  EXPECT_DOUBLE_EQ(depth_from_above(nested, 1, 1), 99);    // the outline
  EXPECT_EQ(depth_from_above(nested, 3, 3), kInfinity);     // its hole
  EXPECT_DOUBLE_EQ(depth_from_above(nested, 5, 5), 99);    // the island in the hole
  EXPECT_DOUBLE_EQ(depth_from_above(nested, 21, 1), 99);   // the outline apart
  EXPECT_EQ(depth_from_above(nested, 15, 1), kInfinity);    // between them
  EXPECT_EQ(parse_scene(nested, "t.csg").primitives.size(), 5u);  // four paths and the slab
}

TEST(ParserExtrusion, Refusals) {
  EXPECT_EQ(refusal("linear_extrude(height = 3, twist = 90, slices = 1e6) square(1);"),
            "t.csg:1:49: 1000000 slices are more than the 100000 capsim tessellates");
  EXPECT_EQ(refusal("linear_extrude(height = 3, twist = 90, slices = 90000) circle(1, $fn = 1000);"),
            "t.csg:1:56: this twisted or unevenly scaled extrusion would have 9.0003e+07 points (90000 slices of "
            "1000), more than the 4000000 capsim tessellates");
  // Under hull() (or any call that meshes its children) the same count holds
  // it, before any point is made: 100,000 slices of 1,000 points once ran for
  // minutes.
  EXPECT_EQ(refusal("hull() linear_extrude(height = 1, twist = 90, slices = 100000) circle(10, $fn = 100);"),
            "t.csg:1:8: linear_extrude() under hull() or minkowski() would have 1.00003e+07 points (100000 slices of "
            "100), more than the 4000000 capsim tessellates");
  EXPECT_EQ(refusal("linear_extrude(1) polygon([[0, 0], [1, 0], [2, 0]]);"),
            "t.csg:1:27: polygon outline crosses itself or encloses no area: capsim extrudes simple outlines only");
  // Paths that cross are clipped (tests/scene/region_2d_test.cpp), not refused.
  EXPECT_EQ(refusal("linear_extrude(1) polygon([[0, 0], [4, 0], [0, 4], [1, 1], [5, 1], [1, 5]], [[0, 1, 2], "
                    "[3, 4, 5]]);"),
            "parsed without error");
  EXPECT_EQ(refusal("linear_extrude(1) sphere(1);"),
            "t.csg:1:19: sphere() is not a 2-D shape: linear_extrude() extrudes square, circle, polygon and text");
  EXPECT_EQ(refusal("linear_extrude(1) import(\"a.stl\");"),
            "t.csg:1:19: import() of a mesh (STL, OFF, AMF, 3MF) is not a 2-D shape: linear_extrude() extrudes square, "
            "circle, polygon, text, offset, projection and 2-D imports (DXF, SVG)");
  EXPECT_EQ(refusal("linear_extrude(1) !square(1);"),
            "t.csg:1:19: the '!' (root) modifier is not supported inside linear_extrude()");
  EXPECT_EQ(refusal("linear_extrude(height = 0) square(1);"),
            "t.csg:1:25: argument 'height' of linear_extrude must be positive, got 0");
  EXPECT_EQ(refusal("linear_extrude(1) scale([1, 0, 1]) square(1);"),
            "t.csg:1:25: singular transform: scale [1, 0, 1] flattens space (every factor must be non-zero)");
}

// text() extruded: a prism per glyph contour, with the glyphs' holes (the
// counter of an "O") subtracted; OpenSCAD's own drawing of the same text is
// compared in tests/scene/text_glyphs_test.cpp and tests/oracle.
TEST(ParserExtrusion, TextIsAPrismPerContourWithItsHolesSubtracted) {
  const Scene scene = parse_scene("linear_extrude(2) text(\"O\", size = 10, halign = \"center\", valign = \"center\");",
                                  "t.csg");
  // The outline, its hole, and the box that cuts the caps.
  std::vector<PrimitiveKind> kinds;
  for (const Primitive& p : scene.primitives) kinds.push_back(p.kind);
  std::sort(kinds.begin(), kinds.end());
  EXPECT_EQ(kinds, (std::vector<PrimitiveKind>{PrimitiveKind::Box, PrimitiveKind::Mesh, PrimitiveKind::Mesh}));
  // Down through the ring of the "O" hits its top; through its counter, nothing.
  const std::string o = "linear_extrude(2) text(\"O\", size = 10, halign = \"center\", valign = \"center\");";
  EXPECT_EQ(depth_from_above(o, 0, 0), kInfinity);
  double ring = kInfinity;
  for (double x = 2.5; x < 5 && ring == kInfinity; x += 0.1) ring = depth_from_above(o, x, 0);
  EXPECT_NEAR(ring, 98, 1e-9);
}

TEST(ParserExtrusion, TextRefusalsNameTheirPlace) {
  EXPECT_EQ(refusal("linear_extrude(1) text(3);"),
            "t.csg:1:24: argument 'text' of text must be a string, got a number");
  EXPECT_EQ(refusal("linear_extrude(1) text(\"a\", size = -1);"),
            "t.csg:1:36: size must be positive and at most 1e30, got -1");
  EXPECT_EQ(refusal("linear_extrude(1) text(\" \");"),
            "t.csg:1:19: text() draws nothing here (an empty text, or only spaces)");
  EXPECT_EQ(refusal("linear_extrude(1) text(\"a\", $fa = 0, $fs = 0);"),
            "t.csg:1:19: $fn = 0, $fa = 0, $fs = 0 give more than 1000000 fragments");
  EXPECT_EQ(refusal("linear_extrude(1) text(\"capsim\", $fn = 4000);"),
            "t.csg:1:19: text() has 55652 outline vertices, more than the 20000 capsim checks: use a shorter text or "
            "a smaller $fn");
  EXPECT_EQ(refusal("linear_extrude(1) text(\"ab\", spacing = 1e300);"),
            "t.csg:1:19: text() reaches beyond 1e30 from the origin (its size or spacing is too large)");
}

}  // namespace
}  // namespace capsim
