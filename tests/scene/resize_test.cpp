// resize(): the scale OpenSCAD derives from the bounding box of its geometry
// of the children, read as a transform of the exact solids under it; and
// every refusal at its FILE:LINE:COL.

#include "capsim/scene/parser.h"
#include "support/scene_refusal.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace capsim {
namespace {

using capsim::testing::refusal;

Scene parse(std::string_view text) { return parse_scene(text, "t.csg"); }

// The x, y and z factors `resize` puts before `child`, its only primitive:
// the primitive's placement with the resize, after its placement without.
glm::dvec3 factors(std::string_view resize, std::string_view child) {
  const std::string text = fmt::format("{} {}", resize, child);
  const Scene s = parse(text), plain = parse(child);
  EXPECT_EQ(s.primitives.size(), 1u);
  const glm::dmat4 m = s.primitives.at(0).to_world * glm::inverse(plain.primitives.at(0).to_world);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (c != r) {
        EXPECT_NEAR(m[c][r], 0, 1e-12) << text;
      }
  return {m[0][0], m[1][1], m[2][2]};
}

// Two scenes with the same primitives, placed alike to within `tolerance`.
void expect_same_placement(std::string_view ours, std::string_view theirs, double tolerance = 1e-12) {
  const Scene a = parse(ours), b = parse(theirs);
  ASSERT_EQ(a.primitives.size(), b.primitives.size()) << ours;
  for (std::size_t k = 0; k < a.primitives.size(); ++k)
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r)
        EXPECT_NEAR(a.primitives[k].to_world[c][r], b.primitives[k].to_world[c][r], tolerance) << ours;
}

void expect_near(const glm::dvec3& got, const glm::dvec3& want) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], want[i], 1e-12) << "axis " << i;
}

TEST(Resize, NewSizesScaleEachAxisAboutTheOrigin) {
  expect_same_placement("resize([4, 6, 8]) translate([1, 1, 1]) cube([1, 2, 4]);",
                        "scale([4, 3, 2]) translate([1, 1, 1]) cube([1, 2, 4]);");
  // OpenSCAD's CSG export: auto as numbers, convexity.
  expect_same_placement("resize(newsize = [4, 0, 8], auto = [0, 0, 0], convexity = 0) cube([1, 2, 4]);",
                        "scale([4, 1, 2]) cube([1, 2, 4]);");
}

// An auto axis (newsize 0) takes the factor of the largest new size.
TEST(Resize, AutoAxesTakeTheLargestNewSizesFactor) {
  expect_near(factors("resize([10, 0, 0], auto = true)", "cube([2, 4, 1]);"), {5, 5, 5});
  expect_near(factors("resize(newsize = [0, 0, 7], auto = [1, 0, 0])", "cube([1, 2, 3]);"), {7.0 / 3, 1, 7.0 / 3});
  expect_near(factors("resize([4, 6, 0], auto = true)", "cube(2);"), {2, 3, 3});  // y's 6 is the largest
  expect_near(factors("resize([4, 6, 0], auto = [false, false, true])", "cube(2);"), {2, 3, 3});
  expect_near(factors("resize([0, 0, 0], auto = true)", "cube(2);"), {1, 1, 1});
}

// The box is that of OpenSCAD's polyhedron of a sphere: $fn = 6 makes three
// rings of six points at 0, 60, ... degrees, the middle one of radius 1, so
// the box is 2 wide in x and 2 sin 60 deep in y.
TEST(Resize, TheBoxIsOpenScadsTessellations) {
  const glm::dvec3 f = factors("resize([10, 10, 0])", "sphere(1, $fn = 6);");
  EXPECT_NEAR(f.x, 5, 1e-12);
  EXPECT_NEAR(f.y, 10 / (2 * std::sin(M_PI / 3)), 1e-12);
  EXPECT_EQ(f.z, 1);
}

// A difference's box is that of the solid it evaluates to (CGAL), not of
// its first operand; an extruded region's is its outline's, holes and all.
TEST(Resize, DifferencesAreEvaluatedExtrudedHolesAreNot) {
  expect_same_placement("resize([10, 0, 0]) difference() { cube([4, 2, 2]); translate([2, -1, -1]) cube([3, 4, 4]); }",
                        "scale([5, 1, 1]) difference() { cube([4, 2, 2]); translate([2, -1, -1]) cube([3, 4, 4]); }");
  expect_same_placement("resize([20, 0, 0], auto = true) linear_extrude(height = 2) difference() {\n"
                        "  square(10);\n"
                        "  translate([3, 3]) square(4);\n"
                        "}",
                        "scale(2) linear_extrude(height = 2) difference() {\n"
                        "  square(10);\n"
                        "  translate([3, 3]) square(4);\n"
                        "}");
}

// resize() of 2-D shapes takes the box of OpenSCAD's outline: circle(1)
// with the default $fa and $fs is a pentagon from angle 0, so x spans
// cos 144 .. 1 and y +-sin 72.
TEST(Resize, TwoDShapesTakeTheirOutlinesBox) {
  const double w = 1 - std::cos(0.8 * M_PI), h = 2 * std::sin(0.4 * M_PI);
  expect_same_placement("linear_extrude(height = 1) resize([4, 6]) circle(1);",
                        fmt::format("linear_extrude(height = 1) scale([{:.17g}, {:.17g}]) circle(1);", 4 / w, 6 / h));
  // A 2-D design alone, drawn 1 unit thick: z keeps its thickness.
  expect_same_placement("resize([4, 6]) circle(1);",
                        fmt::format("scale([{:.17g}, {:.17g}]) circle(1);", 4 / w, 6 / h));
  // Under Clipper's regions (an offset): its rounded square spans 4.
  expect_same_placement("linear_extrude(height = 1) resize([10, 0], auto = true) offset(r = 1) square(2);",
                        "linear_extrude(height = 1) scale(2.5) offset(r = 1) square(2);");
}

// Under hull(), minkowski() and projection(), resize is a transform too.
TEST(Resize, ActsUnderHullMinkowskiAndProjection) {
  const Scene hull = parse("hull() resize([4, 4, 4]) cube(1);");
  ASSERT_EQ(hull.primitives.size(), 1u);
  EXPECT_EQ(hull.primitives[0].mesh->bounds.hi, glm::dvec3(4));
  const Scene sum = parse("minkowski() { resize([2, 2, 2]) cube(1); cube(1); }");
  EXPECT_EQ(sum.primitives[0].mesh->bounds.hi, glm::dvec3(3));
  const Scene shadow = parse("linear_extrude(height = 1) projection() resize([3, 5, 1]) cube(1);");
  ASSERT_FALSE(shadow.primitives.empty());
}

TEST(ResizeRefusals, NameTheArgumentOrChild) {
  EXPECT_EQ(refusal("resize([1, -2, 3]) cube(1);"), "t.csg:1:12: argument 'newsize' of resize must not be negative, "
                                                    "got -2 for y");
  EXPECT_EQ(refusal("resize(5) cube(1);").substr(0, 70),
            "t.csg:1:8: argument 'newsize' of resize must be a vector of up to 3 si");
  EXPECT_EQ(refusal("resize([1, \"a\"]) cube(1);"),
            "t.csg:1:12: argument 'newsize' of resize must be a vector of up to 3 sizes, but element 2 is a string");
  EXPECT_EQ(refusal("resize([1, 1, 1], auto = \"yes\") cube(1);").substr(0, 60),
            "t.csg:1:26: argument 'auto' of resize must be true, false or");
  EXPECT_EQ(refusal("resize([1, 1, 1]) {\n  cube(1);\n  square(1);\n}").substr(0, 72),
            "t.csg:3:3: square() under resize() is not supported: capsim meshes spher");
  EXPECT_EQ(refusal("resize([1, 1, 1]) difference() { sphere(2, $fn = 100); sphere(1, $fn = 100); }"),
            "t.csg:1:1: resize() of these children is not supported: their difference or intersection has 19992 "
            "triangles, more than the 5000 capsim evaluates with CGAL for its bounding box");
}

}  // namespace
}  // namespace capsim
