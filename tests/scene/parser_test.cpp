// Tests of the scene-file parser: every refusal with its message and exact
// file:line:col, the canonical placement of each primitive, OpenSCAD's transform
// and colour conventions, materials, modifiers, real OpenSCAD exports and the
// project's scene files.

#include "capsim/scene/parser.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "capsim/scene/scene.h"

namespace capsim {
namespace {

const std::string kFile = "t.csg";

Scene parse(std::string_view text) { return parse_scene(text, kFile); }

// The text is refused at exactly line:col with a message containing `fragment`.
::testing::AssertionResult Refused(std::string_view text, int line, int col,
                                   std::string_view fragment) {
  try {
    parse(text);
  } catch (const SceneError& e) {
    std::string expected_what = fmt::format("{}:{}:{}: {}", kFile, line, col, e.message());
    if (e.loc().line != line || e.loc().col != col || !e.loc().file || *e.loc().file != kFile ||
        e.message().find(fragment) == std::string::npos || expected_what != e.what()) {
      return ::testing::AssertionFailure() << "expected " << line << ":" << col << " with \""
                                           << fragment << "\", got: " << e.what();
    }
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << "parsed without error";
}

glm::dvec3 apply(const glm::dmat4& m, const glm::dvec3& p) {
  return glm::dvec3(m * glm::dvec4(p, 1.0));
}

::testing::AssertionResult Near(const glm::dvec3& got, const glm::dvec3& want, double tol = 1e-9) {
  if (glm::length(got - want) <= tol) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << fmt::format("got ({}, {}, {}), want ({}, {}, {})", got.x,
                                                      got.y, got.z, want.x, want.y, want.z);
}

// Maps object-space point p of the only primitive of `text` to world space.
glm::dvec3 world(std::string_view text, const glm::dvec3& p) {
  Scene s = parse(text);
  EXPECT_EQ(s.primitives.size(), 1u);
  return apply(s.primitives.at(0).to_world, p);
}

double linear(double srgb) {
  return srgb <= 0.04045 ? srgb / 12.92 : std::pow((srgb + 0.055) / 1.055, 2.4);
}

std::string source_path(const std::string& relative) {
  return std::string(CAPSIM_SOURCE_DIR) + "/" + relative;
}

// ---------------------------------------------------------------- basics

TEST(SceneTypes, SourceLocAndErrorFormat) {
  SourceLoc loc{std::make_shared<const std::string>("a.csg"), 3, 7};
  EXPECT_EQ(loc.str(), "a.csg:3:7");
  SceneError e(loc, "bad thing");
  EXPECT_STREQ(e.what(), "a.csg:3:7: bad thing");
  EXPECT_EQ(e.message(), "bad thing");
  EXPECT_EQ(e.loc().line, 3);
  SourceLoc whole{std::make_shared<const std::string>("b.csg"), 0, 0};
  EXPECT_EQ(whole.str(), "b.csg");
}

TEST(SceneTypes, EnumNames) {
  EXPECT_STREQ(to_string(PrimitiveKind::Sphere), "sphere");
  EXPECT_STREQ(to_string(PrimitiveKind::Box), "box");
  EXPECT_STREQ(to_string(PrimitiveKind::Cone), "cone");
  EXPECT_STREQ(to_string(CsgOp::Union), "union");
  EXPECT_STREQ(to_string(CsgOp::Intersection), "intersection");
  EXPECT_STREQ(to_string(CsgOp::Difference), "difference");
}

// ---------------------------------------------------------------- primitives

TEST(ParserPrimitives, SphereIsScaledUnitSphere) {
  Scene s = parse("sphere(2);");
  ASSERT_EQ(s.primitives.size(), 1u);
  EXPECT_EQ(s.primitives[0].kind, PrimitiveKind::Sphere);
  EXPECT_TRUE(Near(apply(s.primitives[0].to_world, {1, 0, 0}), {2, 0, 0}));
  EXPECT_TRUE(Near(apply(s.primitives[0].to_world, {0, 0, 0}), {0, 0, 0}));
  EXPECT_TRUE(Near(world("sphere(d = 3);", {0, 1, 0}), {0, 1.5, 0}));
  EXPECT_TRUE(Near(world("sphere();", {0, 0, 1}), {0, 0, 1}));
  EXPECT_TRUE(Near(world("sphere(r = 1.5e1);", {1, 0, 0}), {15, 0, 0}));
}

TEST(ParserPrimitives, CubeCenteredAndNot) {
  EXPECT_TRUE(Near(world("cube([2, 4, 6], center = true);", {0, 0, 0}), {-1, -2, -3}));
  EXPECT_TRUE(Near(world("cube([2, 4, 6], center = true);", {1, 1, 1}), {1, 2, 3}));
  EXPECT_TRUE(Near(world("cube([2, 4, 6]);", {1, 1, 1}), {2, 4, 6}));
  EXPECT_TRUE(Near(world("cube([2, 4, 6]);", {0, 0, 0}), {0, 0, 0}));
  EXPECT_TRUE(Near(world("cube(3);", {1, 1, 1}), {3, 3, 3}));
  EXPECT_TRUE(Near(world("cube();", {1, 1, 1}), {1, 1, 1}));
  EXPECT_TRUE(Near(world("cube([1, 2, 3], true);", {0, 0, 0}), {-0.5, -1, -1.5}));
  EXPECT_EQ(parse("cube();").primitives[0].kind, PrimitiveKind::Box);
}

TEST(ParserPrimitives, CylinderIsCanonicalCone) {
  Scene s = parse("cylinder(h = 4, r1 = 2, r2 = 1, center = true);");
  const Primitive& p = s.primitives.at(0);
  EXPECT_EQ(p.kind, PrimitiveKind::Cone);
  EXPECT_DOUBLE_EQ(p.cone_r1, 1.0);
  EXPECT_DOUBLE_EQ(p.cone_r2, 0.5);
  EXPECT_TRUE(Near(apply(p.to_world, {0, 0, 0}), {0, 0, -2}));
  EXPECT_TRUE(Near(apply(p.to_world, {1, 0, 1}), {2, 0, 2}));
}

TEST(ParserPrimitives, CylinderForms) {
  // Positional h, r1, r2.
  Scene s = parse("cylinder(5, 1, 2);");
  EXPECT_DOUBLE_EQ(s.primitives[0].cone_r1, 0.5);
  EXPECT_DOUBLE_EQ(s.primitives[0].cone_r2, 1.0);
  EXPECT_TRUE(Near(apply(s.primitives[0].to_world, {0, 1, 1}), {0, 2, 5}));
  // Defaults: h = 1, r = 1, not centred.
  s = parse("cylinder();");
  EXPECT_DOUBLE_EQ(s.primitives[0].cone_r1, 1.0);
  EXPECT_DOUBLE_EQ(s.primitives[0].cone_r2, 1.0);
  EXPECT_TRUE(Near(apply(s.primitives[0].to_world, {1, 0, 1}), {1, 0, 1}));
  // Diameters.
  EXPECT_TRUE(Near(world("cylinder(h = 2, d = 4);", {1, 0, 1}), {2, 0, 2}));
  s = parse("cylinder(h = 2, d1 = 4, d2 = 1);");
  EXPECT_DOUBLE_EQ(s.primitives[0].cone_r2, 0.25);
  // r sets both ends unless r1 / r2 override one.
  s = parse("cylinder(h = 1, r = 2, r2 = 1);");
  EXPECT_DOUBLE_EQ(s.primitives[0].cone_r1, 1.0);
  EXPECT_DOUBLE_EQ(s.primitives[0].cone_r2, 0.5);
  // Pointed cones either way up.
  s = parse("cylinder(h = 3, r1 = 1, r2 = 0);");
  EXPECT_DOUBLE_EQ(s.primitives[0].cone_r2, 0.0);
  s = parse("cylinder(h = 3, r1 = 0, r2 = 2);");
  EXPECT_DOUBLE_EQ(s.primitives[0].cone_r1, 0.0);
  EXPECT_DOUBLE_EQ(s.primitives[0].cone_r2, 1.0);
  EXPECT_TRUE(Near(apply(s.primitives[0].to_world, {1, 0, 1}), {2, 0, 3}));
}

TEST(ParserPrimitives, SpecialVariablesAndUndefAreAccepted) {
  Scene s = parse(
      "sphere($fn = 0, $fa = 12, $fs = 2, r = 1);\n"
      "cylinder($fn = 64, $fa = 12, $fs = 2, h = 1, r1 = 1, r2 = 1, center = false);\n"
      "sphere(r = undef);\n");
  ASSERT_EQ(s.primitives.size(), 3u);
  EXPECT_TRUE(Near(apply(s.primitives[2].to_world, {1, 0, 0}), {1, 0, 0}));
}

TEST(ParserPrimitives, NumberForms) {
  EXPECT_TRUE(Near(world("cube([1e1, 2.5E+1, .5]);", {1, 1, 1}), {10, 25, 0.5}));
  EXPECT_TRUE(Near(world("translate([-1, 5., -2e-1]) cube();", {0, 0, 0}), {-1, 5, -0.2}));
}

TEST(ParserPrimitives, PrimitiveRemembersItsLocation) {
  Scene s = parse("union() {\n  sphere();\n    cube();\n}");
  ASSERT_EQ(s.primitives.size(), 2u);
  EXPECT_EQ(s.primitives[0].loc.line, 2);
  EXPECT_EQ(s.primitives[0].loc.col, 3);
  EXPECT_EQ(s.primitives[1].loc.line, 3);
  EXPECT_EQ(s.primitives[1].loc.col, 5);
  EXPECT_EQ(*s.primitives[1].loc.file, kFile);
}

// ---------------------------------------------------------------- transforms

TEST(ParserTransforms, RotateVectorAboutXThenYThenZ) {
  EXPECT_TRUE(Near(world("rotate([90, 0, 0]) cube();", {0, 1, 0}), {0, 0, 1}, 0));
  EXPECT_TRUE(Near(world("rotate([0, 90, 0]) cube();", {0, 0, 1}), {1, 0, 0}, 0));
  // Rx first: +y -> +z, then Ry(90): +z -> +x.
  EXPECT_TRUE(Near(world("rotate([90, 90, 0]) cube();", {0, 1, 0}), {1, 0, 0}, 1e-15));
  EXPECT_TRUE(Near(world("rotate([90, 90, 0]) cube();", {1, 0, 0}), {0, 0, -1}, 1e-15));
  // Rz last: rotate([90, 0, 90]) sends +y -> +z (Rx) and leaves it there.
  EXPECT_TRUE(Near(world("rotate([90, 0, 90]) cube();", {1, 0, 0}), {0, 1, 0}, 1e-15));
}

TEST(ParserTransforms, RotateScalarIsAboutZ) {
  EXPECT_TRUE(Near(world("rotate(90) cube();", {1, 0, 0}), {0, 1, 0}, 0));
  EXPECT_TRUE(Near(world("rotate(a = -90) cube();", {1, 0, 0}), {0, -1, 0}, 0));
  EXPECT_TRUE(
      Near(world("rotate(45) cube();", {1, 0, 0}), {std::sqrt(0.5), std::sqrt(0.5), 0}, 1e-15));
}

TEST(ParserTransforms, RotateAxisAngle) {
  // A third of a turn about the diagonal permutes the axes.
  EXPECT_TRUE(Near(world("rotate(a = 120, v = [1, 1, 1]) cube();", {1, 0, 0}), {0, 1, 0}, 1e-12));
  EXPECT_TRUE(Near(world("rotate(a = 120, v = [1, 1, 1]) cube();", {0, 1, 0}), {0, 0, 1}, 1e-12));
  EXPECT_TRUE(Near(world("rotate(90, [1, 0, 0]) cube();", {0, 1, 0}), {0, 0, 1}, 1e-15));
  EXPECT_TRUE(Near(world("rotate(a = 90, v = [0, 0, -3]) cube();", {1, 0, 0}), {0, -1, 0}, 0));
}

TEST(ParserTransforms, TranslateScaleMirror) {
  EXPECT_TRUE(Near(world("translate([1, 2, 3]) sphere();", {0, 0, 0}), {1, 2, 3}));
  EXPECT_TRUE(Near(world("translate(v = [1, 2, 3]) sphere();", {1, 0, 0}), {2, 2, 3}));
  EXPECT_TRUE(Near(world("scale(2) cube();", {1, 1, 1}), {2, 2, 2}));
  EXPECT_TRUE(Near(world("scale([1, -2, 3]) cube();", {1, 1, 1}), {1, -2, 3}));
  EXPECT_TRUE(Near(world("mirror([1, 0, 0]) cube();", {1, 2, 3}), {-1, 2, 3}));
  EXPECT_TRUE(Near(world("mirror([0, 0, 5]) cube();", {1, 2, 3}), {1, 2, -3}));  // normalised
  EXPECT_TRUE(Near(world("mirror([1, 1, 0]) cube();", {1, 0, 0}), {0, -1, 0}, 1e-15));
  EXPECT_TRUE(
      Near(world("mirror() cube();", {1, 2, 3}), {-1, 2, 3}));  // OpenSCAD's default [1, 0, 0]
}

// [x, y] as OpenSCAD 2021.01 reads it (its CSG export writes the matrices):
// translate and mirror take z = 0, scale z = 1, rotate a z angle of 0.
TEST(ParserTransforms, TwoNumberVectorsTakeOpenScadsThird) {
  EXPECT_TRUE(Near(world("translate([1, 2]) sphere();", {0, 0, 1}), {1, 2, 1}));
  EXPECT_TRUE(Near(world("scale([2, 3]) cube();", {1, 1, 1}), {2, 3, 1}));
  EXPECT_TRUE(Near(world("mirror([0, 1]) cube();", {1, 2, 3}), {1, -2, 3}));
  EXPECT_TRUE(Near(world("rotate([90, 90]) cube();", {1, 2, 3}), world("rotate([90, 90, 0]) cube();", {1, 2, 3}), 0));
}

TEST(ParserTransforms, MultmatrixIsRowMajor) {
  EXPECT_TRUE(
      Near(world("multmatrix([[1, 0, 0, 5], [0, 1, 0, 6], [0, 0, 1, 7], [0, 0, 0, 1]]) cube();",
                 {0, 0, 0}),
           {5, 6, 7}));
  // Shear: x += 0.5 y.
  EXPECT_TRUE(
      Near(world("multmatrix([[1, 0.5, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) cube();",
                 {0, 1, 0}),
           {0.5, 1, 0}));
  // Three rows: the last is implicitly [0, 0, 0, 1].
  EXPECT_TRUE(
      Near(world("multmatrix(m = [[0, -1, 0, 1], [1, 0, 0, 0], [0, 0, 1, 0]]) cube();", {1, 0, 0}),
           {1, 1, 0}));
}

TEST(ParserTransforms, ComposeParentTimesChild) {
  // The child rotates first, then the parent translates.
  EXPECT_TRUE(Near(world("translate([10, 0, 0]) rotate(90) cube();", {1, 0, 0}), {10, 1, 0}));
  EXPECT_TRUE(Near(world("rotate(90) translate([10, 0, 0]) cube();", {0, 0, 0}), {0, 10, 0}));
  EXPECT_TRUE(
      Near(world("scale(2) translate([1, 0, 0]) cube([2, 4, 6], center = true);", {1, 1, 1}),
           {4, 4, 6}));
}

TEST(ParserTransforms, OneTransformOverSeveralChildren) {
  Scene s = parse("translate([0, 0, 5]) { sphere(); cube(); }");
  ASSERT_EQ(s.primitives.size(), 2u);
  EXPECT_TRUE(Near(apply(s.primitives[0].to_world, {0, 0, 0}), {0, 0, 5}));
  EXPECT_TRUE(Near(apply(s.primitives[1].to_world, {0, 0, 0}), {0, 0, 5}));
  // The children form a union under the root.
  ASSERT_EQ(s.root.children.size(), 1u);
  EXPECT_FALSE(s.root.children[0].is_leaf);
  EXPECT_EQ(s.root.children[0].op, CsgOp::Union);
  EXPECT_EQ(s.root.children[0].children.size(), 2u);
}

// ---------------------------------------------------------------- CSG tree

TEST(ParserCsg, ImplicitTopLevelUnion) {
  Scene s = parse("sphere(); cube(); cylinder();");
  EXPECT_FALSE(s.root.is_leaf);
  EXPECT_EQ(s.root.op, CsgOp::Union);
  ASSERT_EQ(s.root.children.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_TRUE(s.root.children[i].is_leaf);
    EXPECT_EQ(s.root.children[i].primitive, i);
  }
  EXPECT_EQ(s.primitives[2].kind, PrimitiveKind::Cone);
}

TEST(ParserCsg, NaryOperators) {
  Scene s = parse(
      "difference() { cube(4); sphere(); translate([4, 0, 0]) sphere(); cylinder(); }\n"
      "intersection() { cube(); sphere(); cylinder(); }\n"
      "union() { cube(); sphere(); }\n"
      "group() { cube(); }");
  ASSERT_EQ(s.root.children.size(), 4u);
  EXPECT_EQ(s.root.children[0].op, CsgOp::Difference);
  EXPECT_EQ(s.root.children[0].children.size(), 4u);
  EXPECT_EQ(s.root.children[1].op, CsgOp::Intersection);
  EXPECT_EQ(s.root.children[1].children.size(), 3u);
  EXPECT_EQ(s.root.children[2].op, CsgOp::Union);
  EXPECT_EQ(s.root.children[3].op, CsgOp::Union);  // group = union
  EXPECT_EQ(s.root.children[3].children.size(), 1u);
  EXPECT_EQ(s.primitives.size(), 10u);
  EXPECT_EQ(s.root.children[0].loc.line, 1);
  EXPECT_EQ(s.root.children[0].loc.col, 1);
}

TEST(ParserCsg, EmptyGroupsAreEmptySets) {
  Scene s = parse("group();\ngroup() {}\nunion();\ndifference() {}\ncube();");
  ASSERT_EQ(s.root.children.size(), 5u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_FALSE(s.root.children[i].is_leaf);
    EXPECT_TRUE(s.root.children[i].children.empty());
  }
  EXPECT_EQ(s.root.children[3].op, CsgOp::Difference);
}

TEST(ParserCsg, SingleChildWithoutBracesCommentsAndEmptyStatements) {
  Scene s = parse(
      "// a comment\n;;\n/* block\n comment */ translate([1, 0, 0]) /* inline */ sphere(1); // "
      "end\n"
      "{ cube(); }\n");
  EXPECT_EQ(s.primitives.size(), 2u);
  EXPECT_EQ(s.root.children.size(), 2u);
}

TEST(ParserCsg, RenderPassesThrough) {
  Scene s = parse("render(convexity = 10) difference() { cube(); sphere(); }\nrender() cube();");
  ASSERT_EQ(s.root.children.size(), 2u);
  EXPECT_EQ(s.root.children[0].op, CsgOp::Difference);
  EXPECT_TRUE(s.root.children[1].is_leaf);
}

// ---------------------------------------------------------------- modifiers

TEST(ParserModifiers, BackgroundAndDisableDrop) {
  Scene s =
      parse("%sphere(5);\ncube();\n*cylinder();\ndifference() { cube(); %sphere(); *cube(); }");
  ASSERT_EQ(s.primitives.size(), 2u);
  EXPECT_EQ(s.primitives[0].kind, PrimitiveKind::Box);
  ASSERT_EQ(s.root.children.size(), 2u);
  EXPECT_EQ(s.root.children[1].op, CsgOp::Difference);
  EXPECT_EQ(s.root.children[1].children.size(), 1u);
  EXPECT_EQ(s.root.children[1].children[0].primitive, 1);
}

TEST(ParserModifiers, DebugRendersNormally) {
  Scene s = parse("#cube(3);\n#translate([1, 0, 0]) sphere();");
  EXPECT_EQ(s.primitives.size(), 2u);
  EXPECT_EQ(s.root.children.size(), 2u);
}

TEST(ParserModifiers, RootKeepsOnlyItsSubtreeWithoutEnclosingTransforms) {
  Scene s = parse(
      "cube();\ncolor(\"red\") translate([5, 0, 0]) {\n  sphere();\n  !cube(2);\n}\ncylinder();");
  ASSERT_EQ(s.primitives.size(), 1u);
  EXPECT_EQ(s.primitives[0].kind, PrimitiveKind::Box);
  EXPECT_TRUE(Near(apply(s.primitives[0].to_world, {1, 1, 1}), {2, 2, 2}));
  EXPECT_EQ(s.primitives[0].color, Primitive{}.color);
  ASSERT_EQ(s.root.children.size(), 1u);
  EXPECT_EQ(s.root.children[0].primitive, 0);
}

TEST(ParserModifiers, RootInsideDisabledSubtreeHasNoEffect) {
  Scene s = parse("sphere();\n*translate([1, 0, 0]) !cube();");
  ASSERT_EQ(s.primitives.size(), 1u);
  EXPECT_EQ(s.primitives[0].kind, PrimitiveKind::Sphere);
}

TEST(ParserModifiers, OpenScadExportLayoutOfModifiers) {
  // OpenSCAD writes a modifier inside an indented block at the start of the line.
  Scene s = parse(
      "color([0.5, 0.5, 0.5, 1]) {\n%\tsphere($fn = 0, $fa = 12, $fs = 2, r = 1);\n}\ncube();");
  EXPECT_EQ(s.primitives.size(), 1u);
}

// ---------------------------------------------------------------- colours

TEST(ParserColors, DefaultColourStays) {
  Scene s = parse("cube();");
  EXPECT_EQ(s.primitives[0].color, Primitive{}.color);
  EXPECT_EQ(s.primitives[0].alpha, 1.0);
}

TEST(ParserColors, VectorsAreDecodedFromSrgb) {
  Scene s = parse("color([0.5, 0.25, 1]) cube();\ncolor([1, 0, 0, 0.3]) cube();");
  EXPECT_TRUE(Near(s.primitives[0].color, {linear(0.5), linear(0.25), 1}, 1e-12));
  EXPECT_NEAR(s.primitives[0].color.x, 0.214041, 1e-6);
  EXPECT_DOUBLE_EQ(s.primitives[0].alpha, 1.0);
  EXPECT_TRUE(Near(s.primitives[1].color, {1, 0, 0}));
  EXPECT_DOUBLE_EQ(s.primitives[1].alpha, 0.3);
}

TEST(ParserColors, NamesAndHex) {
  Scene s = parse(
      "color(\"red\") cube();\n"
      "color(\"SteelBlue\") cube();\n"
      "color(\"rebeccapurple\") cube();\n"
      "color(\"lightgoldenrodyellow\") cube();\n"
      "color(\"#ff000080\") cube();\n"
      "color(\"#abc\") cube();\n"
      "color(\"#12345678\") cube();\n"
      "color(\"transparent\") cube();\n"
      "color(\"darkslategrey\") cube();\n");
  EXPECT_TRUE(Near(s.primitives[0].color, {1, 0, 0}));
  EXPECT_TRUE(Near(s.primitives[1].color,
                   {linear(70 / 255.0), linear(130 / 255.0), linear(180 / 255.0)}, 1e-12));
  EXPECT_TRUE(Near(s.primitives[2].color,
                   {linear(102 / 255.0), linear(51 / 255.0), linear(153 / 255.0)}, 1e-12));
  EXPECT_TRUE(Near(s.primitives[3].color,
                   {linear(250 / 255.0), linear(250 / 255.0), linear(210 / 255.0)}, 1e-12));
  EXPECT_TRUE(Near(s.primitives[4].color, {1, 0, 0}));
  EXPECT_DOUBLE_EQ(s.primitives[4].alpha, 128 / 255.0);
  EXPECT_TRUE(Near(s.primitives[5].color, {linear(10 / 15.0), linear(11 / 15.0), linear(12 / 15.0)},
                   1e-12));
  EXPECT_TRUE(Near(s.primitives[6].color,
                   {linear(0x12 / 255.0), linear(0x34 / 255.0), linear(0x56 / 255.0)}, 1e-12));
  EXPECT_DOUBLE_EQ(s.primitives[6].alpha, 0x78 / 255.0);
  EXPECT_TRUE(Near(s.primitives[7].color, {0, 0, 0}));
  EXPECT_DOUBLE_EQ(s.primitives[7].alpha, 0.0);
  EXPECT_TRUE(Near(s.primitives[8].color,
                   {linear(47 / 255.0), linear(79 / 255.0), linear(79 / 255.0)}, 1e-12));
}

TEST(ParserColors, AlphaArgumentOverridesAndCombines) {
  Scene s = parse(
      "color(c = \"blue\", alpha = 0.5) cube();\n"
      "color(\"red\", 0.25) cube();\n"
      "color([1, 0, 0, 0.2], 0.7) cube();\n");
  EXPECT_TRUE(Near(s.primitives[0].color, {0, 0, 1}));
  EXPECT_DOUBLE_EQ(s.primitives[0].alpha, 0.5);
  EXPECT_DOUBLE_EQ(s.primitives[1].alpha, 0.25);
  EXPECT_DOUBLE_EQ(s.primitives[2].alpha, 0.7);
}

TEST(ParserColors, InnermostWins) {
  Scene s = parse("color(\"red\") { cube(); color(\"blue\", 0.5) sphere(); cylinder(); }");
  EXPECT_TRUE(Near(s.primitives[0].color, {1, 0, 0}));
  EXPECT_TRUE(Near(s.primitives[1].color, {0, 0, 1}));
  EXPECT_DOUBLE_EQ(s.primitives[1].alpha, 0.5);
  EXPECT_TRUE(Near(s.primitives[2].color, {1, 0, 0}));
  EXPECT_DOUBLE_EQ(s.primitives[2].alpha, 1.0);
}

TEST(ParserColors, OpenScadUnsetColourKeepsEnclosingColour) {
  // color(alpha = 0.5) without c: OpenSCAD writes [-1, -1, -1, 0.5].
  Scene s = parse("color(\"red\") color([-1, -1, -1, 0.5]) cube();\ncolor(alpha = 0.25) cube();");
  EXPECT_TRUE(Near(s.primitives[0].color, {1, 0, 0}));
  EXPECT_DOUBLE_EQ(s.primitives[0].alpha, 0.5);
  EXPECT_EQ(s.primitives[1].color, Primitive{}.color);
  EXPECT_DOUBLE_EQ(s.primitives[1].alpha, 0.25);
}

// ---------------------------------------------------------------- materials

TEST(ParserMaterials, DefaultsAndSubtree) {
  Scene s = parse(
      "material(reflect = 0.4, ior = 1.3) { cube(); sphere(); }\ncylinder();\n"
      "material(transmit = 0.7) cube();");
  ASSERT_EQ(s.primitives.size(), 4u);
  EXPECT_DOUBLE_EQ(s.primitives[0].material.reflect, 0.4);
  EXPECT_DOUBLE_EQ(s.primitives[0].material.ior, 1.3);
  EXPECT_DOUBLE_EQ(s.primitives[0].material.diffuse, Material{}.diffuse);
  EXPECT_DOUBLE_EQ(s.primitives[1].material.reflect, 0.4);
  EXPECT_DOUBLE_EQ(s.primitives[2].material.reflect, 0.0);
  EXPECT_DOUBLE_EQ(s.primitives[2].material.ior, Material{}.ior);
  EXPECT_DOUBLE_EQ(s.primitives[3].material.transmit, 0.7);
  // material() is not a CSG operator: one child passes through.
  EXPECT_TRUE(s.root.children[2].is_leaf);
}

TEST(ParserMaterials, InnermostWinsFieldByField) {
  Scene s = parse(
      "material(diffuse = 0.5, reflect = 0.2, shininess = 10) {\n"
      "  material(reflect = 0.6, ambient = 0, specular = 0.9) sphere();\n"
      "  cube();\n"
      "}");
  const Material& inner = s.primitives[0].material;
  EXPECT_DOUBLE_EQ(inner.reflect, 0.6);
  EXPECT_DOUBLE_EQ(inner.diffuse, 0.5);
  EXPECT_DOUBLE_EQ(inner.shininess, 10);
  EXPECT_DOUBLE_EQ(inner.ambient, 0);
  EXPECT_DOUBLE_EQ(inner.specular, 0.9);
  EXPECT_DOUBLE_EQ(s.primitives[1].material.reflect, 0.2);
  EXPECT_DOUBLE_EQ(s.primitives[1].material.specular, Material{}.specular);
}

// ---------------------------------------------------------------- settings

TEST(ParserSettings, CameraLightsBackground) {
  Scene s = parse(
      "camera(eye = [1, -10, 2], center = [0, 0, 1], up = [0, 0, 1], fov = 30, size = [640, "
      "480]);\n"
      "light(position = [5, 5, 5]);\n"
      "light(position = [-5, 0, 2], color = [0.5, 0.5, 2]);\n"
      "background(color = [0.5, 0, 1]);\n"
      "sphere();");
  ASSERT_TRUE(s.camera.has_value());
  EXPECT_TRUE(Near(s.camera->eye, {1, -10, 2}));
  EXPECT_TRUE(Near(s.camera->center, {0, 0, 1}));
  EXPECT_DOUBLE_EQ(s.camera->fov_deg, 30);
  EXPECT_EQ(s.camera->width, 640);
  EXPECT_EQ(s.camera->height, 480);
  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_TRUE(Near(s.lights[0].color, {1, 1, 1}));
  EXPECT_TRUE(Near(s.lights[1].position, {-5, 0, 2}));
  EXPECT_TRUE(Near(s.lights[1].color, {0.5, 0.5, 2}));  // intensity: linear, not decoded
  EXPECT_TRUE(Near(s.background, {linear(0.5), 0, 1}, 1e-12));
  EXPECT_EQ(s.primitives.size(), 1u);
}

TEST(ParserSettings, DefaultsWhenAbsent) {
  Scene s = parse("sphere();");
  EXPECT_FALSE(s.camera.has_value());
  EXPECT_TRUE(s.lights.empty());
  EXPECT_EQ(s.background, Scene{}.background);
  s = parse("camera(eye = [0, -10, 0]); sphere();");
  ASSERT_TRUE(s.camera.has_value());
  EXPECT_TRUE(Near(s.camera->center, Camera{}.center));
  EXPECT_DOUBLE_EQ(s.camera->fov_deg, Camera{}.fov_deg);
  EXPECT_EQ(s.camera->width, Camera{}.width);
}

TEST(ParserSettings, BackgroundByName) {
  Scene s = parse("background(\"navy\"); sphere();");
  EXPECT_TRUE(Near(s.background, {0, 0, linear(128 / 255.0)}, 1e-12));
}

// ---------------------------------------------------------------- refusals: constructs

TEST(ParserRefusesConstructs, UnsupportedModules) {
  struct Case {
    const char* name;
    const char* call;
  };
  const Case cases[] = {
      {"children", "children(0);"},
      {"parent_module", "parent_module(1);"},
      {"import_stl", "import_stl(\"a.stl\");"},
  };
  for (const Case& c : cases) {
    std::string text = std::string("cube();\n  ") + c.call;
    EXPECT_TRUE(Refused(text, 2, 3, fmt::format("'{}' is not supported", c.name))) << c.name;
    EXPECT_TRUE(Refused(text, 2, 3, "supported: sphere, cube, cylinder")) << c.name;
  }
}

TEST(ParserRefusesConstructs, UnsupportedModuleNestedInTree) {
  EXPECT_TRUE(Refused("difference() {\n  cube();\n  translate([1, 0, 0]) children(0);\n}", 3, 24,
                      "'children' is not supported: it is not part of a plain CSG tree"));
}

// The refusal says what capsim lacks for the module: 2-D shapes and the
// extrusions that turn them into solids are not refused as if they were CSG
// operators.
TEST(ParserRefusesConstructs, TwoDShapesAndExtrusionsSayWhy) {
  // 2-D shapes alone are drawn flat (tests/scene/region_2d_test.cpp).
  for (const char* shape : {"square(2);", "circle(2);", "polygon([[0, 0], [1, 0], [0, 1]]);", "offset(1) square();"})
    EXPECT_FALSE(parse_scene(shape, "t.csg").primitives.empty()) << shape;
  EXPECT_TRUE(Refused("projection() text(\"a\");", 1, 14,
                      "text() under projection() is not supported: capsim projects sphere, cube"));
  EXPECT_TRUE(Refused("linear_extrude(1) children(0);", 1, 19,
                      "'children' is not supported: it is not part of a plain CSG tree; supported:"));
}

TEST(ParserRefusesConstructs, UnknownModuleSuggestsSpelling) {
  EXPECT_TRUE(
      Refused("sphre(1);", 1, 1, "unknown module 'sphre' (did you mean 'sphere'?); supported:"));
  EXPECT_TRUE(Refused("cube();\nfoo();", 2, 1, "unknown module 'foo'; supported: sphere"));
}

TEST(ParserRefusesConstructs, LanguageStatements) {
  const char* keywords[][2] = {
      {"let", "let (a = 1) cube();"},
      {"for", "for (i = [0:3]) translate([i, 0, 0]) cube();"},
      {"if", "if (true) cube();"},
      {"module", "module m() { cube(); }"},
      {"function", "function f(x) = x;"},
      {"echo", "echo(\"x\");"},
      {"assert", "assert(true);"},
      {"include", "include <parts.scad>"},
      {"use", "use <parts.scad>"},
      {"intersection_for", "intersection_for (i = [0, 1]) cube();"},
  };
  for (auto& k : keywords) {
    EXPECT_TRUE(Refused(std::string("sphere();\n\t") + k[1], 2, 2,
                        fmt::format("'{}' is not supported", k[0])))
        << k[0];
    EXPECT_TRUE(Refused(std::string("sphere();\n\t") + k[1], 2, 2, "plain CSG tree")) << k[0];
  }
}

TEST(ParserRefusesConstructs, Assignment) {
  EXPECT_TRUE(
      Refused("size = 3;\ncube(size);", 1, 1, "variable assignment 'size = ...' is not supported"));
  EXPECT_TRUE(Refused("$fn = 32;\ncube();", 1, 1, "variable assignment '$fn = ...'"));
}

// Expressions are evaluated (scene_expression_test.cpp holds their tests);
// variables other than $t and PI are refused.
TEST(ParserReadsExpressions, ArgumentsAreEvaluated) {
  Scene s = parse("translate([1, 2 * 3, -(1 + 1)]) sphere(r = max(1, 2) % 1.5);");
  EXPECT_TRUE(Near(world("translate([1, 2 * 3, -(1 + 1)]) sphere(r = 1);", {0, 0, 0}), {1, 6, -2}));
  EXPECT_TRUE(Near(apply(s.primitives.at(0).to_world, {1, 0, 0}), {1.5, 6, -2}));
}

TEST(ParserRefusesConstructs, VariablesAndRanges) {
  EXPECT_TRUE(Refused("cube(size);", 1, 6, "unknown variable 'size'"));
  EXPECT_TRUE(Refused("sphere(r = pi);", 1, 12, "unknown variable 'pi'"));
  EXPECT_TRUE(Refused("cube(mux(1, 2));", 1, 6, "unknown function 'mux' (did you mean 'max'?)"));
  EXPECT_TRUE(
      Refused("translate([0:1:3]) cube();", 1, 13, "ranges [start:step:end] are not supported"));
}

TEST(ParserRefusesConstructs, ModifierOnSettingAndSettingsInsideObjects) {
  EXPECT_TRUE(Refused("%camera(eye = [0, -5, 0]);\ncube();", 1, 1,
                      "modifier '%' applies only to objects, not to camera()"));
  EXPECT_TRUE(Refused("translate([1, 0, 0]) {\n  light(position = [0, 0, 5]);\n}", 2, 3,
                      "light() must be at the top level of the file, not inside translate()"));
  EXPECT_TRUE(Refused("cube();\nbackground(color = [0, 0, 0]) cube();", 2, 31,
                      "background() takes no children"));
}

TEST(ParserRefusesConstructs, ConflictingAndRepeatedRootModifiers) {
  EXPECT_TRUE(Refused("!cube();\n!sphere();", 2, 1,
                      "only one '!' (root) modifier is allowed; the first is at 1:1"));
  EXPECT_TRUE(Refused("%!cube();", 1, 2, "modifiers '%' and '!' contradict each other"));
  EXPECT_TRUE(Refused("cube();\n#;", 2, 2, "expected an object after modifier '#', got ';'"));
}

// ---------------------------------------------------------------- refusals: values

TEST(ParserRefusesValues, SphereRadius) {
  EXPECT_TRUE(Refused("sphere(0);", 1, 8, "argument 'r' of sphere must be positive, got 0"));
  EXPECT_TRUE(Refused("sphere(r = -1);", 1, 12, "argument 'r' of sphere must be positive, got -1"));
  EXPECT_TRUE(Refused("sphere(d = 0);", 1, 12, "argument 'd' of sphere must be positive"));
  EXPECT_TRUE(Refused("sphere(r = 1, d = 2);", 1, 15, "sphere takes either r or d, not both"));
}

TEST(ParserRefusesValues, CylinderHeightAndRadii) {
  EXPECT_TRUE(Refused("cylinder(h = 0, r = 1);", 1, 14,
                      "argument 'h' of cylinder must be positive, got 0"));
  EXPECT_TRUE(
      Refused("cylinder(-2, 1, 1);", 1, 10, "argument 'h' of cylinder must be positive, got -2"));
  EXPECT_TRUE(Refused("cylinder(h = 1, r1 = -1, r2 = 1);", 1, 22,
                      "argument 'r1' of cylinder must not be negative"));
  EXPECT_TRUE(
      Refused("cylinder(h = 1, r1 = 0, r2 = 0);", 1, 30, "cylinder radii r1 and r2 are both zero"));
  EXPECT_TRUE(Refused("cylinder(h = 1, r = 0);", 1, 21, "both zero"));
  EXPECT_TRUE(Refused("cylinder(h = 1, r = 1, r1 = 2, r2 = 3);", 1, 17,
                      "cylinder argument 'r' has no effect: 'r1' and 'r2' override it"));
  EXPECT_TRUE(Refused("cylinder(h = 1, d = 2, r1 = 2);", 1, 24,
                      "argument 'r1' has no effect: 'd' overrides it"));
}

TEST(ParserRefusesValues, CubeSize) {
  EXPECT_TRUE(Refused("cube(0);", 1, 6, "cube size must be positive in every dimension, got 0"));
  EXPECT_TRUE(Refused("cube(size = [1, -2, 3]);", 1, 13, "got [1, -2, 3]"));
  EXPECT_TRUE(Refused("cube([1, 0, 1]);", 1, 6, "cube size must be positive"));
  EXPECT_TRUE(Refused("cube(size = [1, 2]);", 1, 13,
                      "argument 'size' of cube must be a number or a vector of 3 numbers, got a "
                      "vector of 2 elements"));
}

TEST(ParserRefusesValues, SingularTransforms) {
  EXPECT_TRUE(Refused("scale([1, 0, 1]) cube();", 1, 7, "singular transform: scale [1, 0, 1]"));
  EXPECT_TRUE(Refused("scale(0) cube();", 1, 7, "singular transform"));
  EXPECT_TRUE(Refused("scale([1e-10, 1e10, 1]) cube();", 1, 7, "is too flat"));
  EXPECT_TRUE(Refused("mirror([0, 0, 0]) cube();", 1, 8,
                      "singular transform: mirror [0, 0, 0] has no plane normal"));
  EXPECT_TRUE(
      Refused("multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [1, 1, 0, 0], [0, 0, 0, 1]]) cube();", 1, 12,
              "singular matrix"));
  EXPECT_TRUE(
      Refused("multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 1, 1]]) cube();", 1, 55,
              "the last row of multmatrix must be [0, 0, 0, 1]"));
  EXPECT_TRUE(Refused("rotate(a = 30, v = [0, 0, 0]) cube();", 1, 20,
                      "the axis v must be a non-zero vector"));
}

TEST(ParserRefusesValues, MalformedMatrix) {
  EXPECT_TRUE(Refused("multmatrix([[1, 0, 0], [0, 1, 0], [0, 0, 1]]) cube();", 1, 13,
                      "but row 1 is a vector of 3 elements"));
  EXPECT_TRUE(Refused("multmatrix([[1, 0, 0, 0], [0, 1, \"x\", 0], [0, 0, 1, 0]]) cube();", 1, 34,
                      "element [1][2] is a string"));
  EXPECT_TRUE(Refused("multmatrix(5) cube();", 1, 12, "must be a 4x4 matrix"));
}

TEST(ParserRefusesValues, PlacementThatOverflows) {
  EXPECT_TRUE(Refused("scale(1e200)\n  scale(1e200)\n    sphere();", 3, 5,
                      "sphere is placed by a singular or overflowing transform"));
}

TEST(ParserRefusesValues, NonFiniteNumbers) {
  EXPECT_TRUE(Refused("sphere(r = nan);", 1, 12, "'nan' is not a finite number"));
  EXPECT_TRUE(Refused("sphere(r = inf);", 1, 12, "'inf' is not a finite number"));
  EXPECT_TRUE(Refused("translate([0, -inf, 0]) cube();", 1, 15, "'-inf' is not a finite number"));
  EXPECT_TRUE(
      Refused("sphere(r = 1e999);", 1, 12, "number '1e999' is out of the range of a double"));
  EXPECT_TRUE(Refused("cube(1e);", 1, 6, "malformed number '1e'"));
  EXPECT_TRUE(Refused("cube(1.2.3);", 1, 6, "malformed number '1.2.3'"));
}

// ---------------------------------------------------------------- range (docs: "Range")

// The values of the report, which rendered blank with undefined behaviour,
// are refused where they are written.
TEST(ParserRange, ValuesOfTheReportAreRefusedWhereWritten) {
  EXPECT_TRUE(Refused("sphere(1e160);", 1, 8,
                      "argument 'r' of sphere must be at most 1e30, the largest length capsim "
                      "traces, got 1e+160"));
  EXPECT_TRUE(Refused("sphere(1e-300);", 1, 8,
                      "argument 'r' of sphere must be at least 1e-30, the smallest length capsim "
                      "traces, got 1e-300"));
  EXPECT_TRUE(Refused("sphere(1e-320);", 1, 8, "argument 'r' of sphere must be at least 1e-30"));
  EXPECT_TRUE(Refused("camera(eye=[1e300,0,0], center=[0,0,0], up=[0,0,1]);\nsphere(1);", 1, 12,
                      "camera eye must lie within 1e30 of the origin in every coordinate, the "
                      "farthest capsim traces, got [1e+300, 0, 0]"));
  EXPECT_TRUE(Refused("material(transmit=1, ior=1e300) sphere(1);", 1, 26,
                      "argument 'ior' of material must be between 0.001 and 1000, got 1e+300"));
  EXPECT_TRUE(Refused("translate([1.5e308,0,0]) sphere(1); translate([-1.5e308,0,0]) sphere(1);",
                      1, 26,
                      "sphere is placed beyond the coordinates capsim traces: its bounding box "
                      "reaches 1.5e+308 from the origin, past 1e30"));
}

TEST(ParserRange, LengthsOfPrimitives) {
  EXPECT_EQ(parse("sphere(1e30); sphere(1e-30); sphere(d = 2e-30);").primitives.size(), 3u);
  EXPECT_TRUE(Refused("sphere(d = 3e30);", 1, 12, "argument 'd' of sphere must be at most 1e30"));
  EXPECT_TRUE(Refused("cube([1, 2e30, 1]);", 1, 6,
                      "cube size must be at most 1e30, the largest length capsim traces, got 2e+30"));
  EXPECT_TRUE(Refused("cube(1e-31);", 1, 6, "cube size must be at least 1e-30"));
  EXPECT_TRUE(Refused("cylinder(h = 1e-31, r = 1);", 1, 14,
                      "argument 'h' of cylinder must be at least 1e-30"));
  EXPECT_TRUE(Refused("cylinder(h = 1, r1 = 1e-31, r2 = 1);", 1, 22,
                      "argument 'r1' of cylinder must be at least 1e-30"));
  EXPECT_TRUE(Refused("cylinder(h = 1, d = 1e31);", 1, 21,
                      "argument 'd' of cylinder must be at most 1e30"));
  EXPECT_EQ(parse("cylinder(h = 1e-30, r1 = 0, r2 = 1e-30); cylinder(h = 1e30, d = 1e30);")
                .primitives.size(),
            2u);
}

// What the transforms around a primitive make of it is checked at the
// primitive: its bounding box within 1e30 of the origin, its smallest
// dimension (smallest singular value of its placement) at least 1e-30.
TEST(ParserRange, PlacementsOfPrimitives) {
  EXPECT_TRUE(Refused("translate([9e29, 0, 0])\n  sphere(2e29);", 2, 3,
                      "sphere is placed beyond the coordinates capsim traces: its bounding box "
                      "reaches 1.1e+30 from the origin, past 1e30"));
  EXPECT_EQ(parse("translate([9e29, 0, 0]) sphere(1e29);").primitives.size(), 1u);
  EXPECT_TRUE(Refused("scale(1e-20) scale(1e-20) cube(1e-3);", 1, 27,
                      "cube is smaller than capsim traces: its smallest dimension is 1e-43, below "
                      "1e-30"));
  // A shear keeps every edge of the box 1e-20 long or more but makes it
  // 7e-32 thin (a flatness the singular-matrix test allows: 1e-11).
  EXPECT_TRUE(Refused("multmatrix([[1e-20, 0, 0, 0], [0, 1e-20, 1e-20, 0], [0, 0, 1e-31, 0]]) cube();",
                      1, 72, "cube is smaller than capsim traces: its smallest dimension is "
                             "7.07107e-32, below 1e-30"));
  EXPECT_EQ(parse("scale(1e-15) scale(1e-15) sphere(1);").primitives.size(), 1u);
}

TEST(ParserRange, CameraLightsAndMaterials) {
  EXPECT_TRUE(Refused("camera(eye = [0, -5, 0], center = [0, 0, -2e30]);\nsphere(1);", 1, 35,
                      "camera center must lie within 1e30 of the origin"));
  EXPECT_TRUE(Refused("light(position = [0, 0, 1e31]);\nsphere(1);", 1, 18,
                      "light position must lie within 1e30 of the origin"));
  EXPECT_TRUE(Refused("light(position = [0, 0, 9], color = [1, 2e6, 1]);\nsphere(1);", 1, 37,
                      "light color must be at most 1e6 in every component, got [1, 2000000, 1]"));
  EXPECT_TRUE(Refused("material(ior = 0.0009) sphere(1);", 1, 16,
                      "argument 'ior' of material must be between 0.001 and 1000, got 0.0009"));
  EXPECT_TRUE(Refused("material(diffuse = 1e7) sphere(1);", 1, 20,
                      "argument 'diffuse' of material must be at most 1e6, got 10000000"));
  EXPECT_TRUE(Refused("material(specular = 1e7) sphere(1);", 1, 21,
                      "argument 'specular' of material must be at most 1e6"));
  EXPECT_TRUE(Refused("material(ambient = 1e7) sphere(1);", 1, 20,
                      "argument 'ambient' of material must be at most 1e6"));
  Scene s = parse("camera(eye = [1e30, 0, 0]);\nlight(position = [-1e30, 0, 0], color = [1e6, 0, 0]);\n"
                  "material(ior = 1000, diffuse = 1e6, specular = 1e6, ambient = 1e6) sphere(1);\n"
                  "material(ior = 0.001) sphere(1);");
  EXPECT_EQ(s.primitives.size(), 2u);
  EXPECT_EQ(s.camera->loc.line, 1);
  EXPECT_EQ(s.camera->loc.col, 14);
}

TEST(ParserRefusesValues, UnknownArgumentListsAccepted) {
  EXPECT_TRUE(Refused("sphere(radius = 1);", 1, 8,
                      "unknown argument 'radius' for sphere; accepted: r, d, $fn, $fa, $fs"));
  EXPECT_TRUE(Refused(
      "cube(centre = true);", 1, 6,
      "unknown argument 'centre' for cube (did you mean 'center'?); accepted: size, center"));
  EXPECT_TRUE(
      Refused("cube();\nmaterial(reflection = 0.5) cube();", 2, 10, "did you mean 'reflect'?"));
  EXPECT_TRUE(Refused("sphere($t = 1);", 1, 8, "unknown argument '$t' for sphere"));
}

TEST(ParserRefusesValues, DuplicateAndSurplusArguments) {
  EXPECT_TRUE(Refused("sphere(r = 1, r = 2);", 1, 15,
                      "duplicate argument 'r' for sphere (first given at 1:8)"));
  EXPECT_TRUE(Refused("sphere(1, r = 2);", 1, 11,
                      "duplicate argument 'r' for sphere (first given at 1:8)"));
  EXPECT_TRUE(Refused("sphere(1, 2);", 1, 11, "sphere takes at most 1 positional argument (r)"));
  EXPECT_TRUE(Refused("union(1) cube();", 1, 7, "union takes no positional arguments"));
}

TEST(ParserRefusesValues, WrongTypes) {
  EXPECT_TRUE(Refused("sphere(r = \"a\");", 1, 12,
                      "argument 'r' of sphere must be a number, got a string"));
  EXPECT_TRUE(Refused("cube(1, center = 1);", 1, 18,
                      "argument 'center' of cube must be true or false, got a number"));
  EXPECT_TRUE(Refused("translate([1, true, 0]) cube();", 1, 15, "element 2 is a boolean"));
  EXPECT_TRUE(Refused("translate(3) cube();", 1, 11,
                      "argument 'v' of translate must be a vector of 2 or 3 numbers"));
  EXPECT_TRUE(Refused("translate([1]) cube();", 1, 11, "must be a vector of 2 or 3 numbers, got a vector of 1"));
  EXPECT_TRUE(Refused("scale([1, 2, 3, 4]) cube();", 1, 7, "must be a number or a vector of 2 or 3 numbers"));
  EXPECT_TRUE(
      Refused("sphere($fn = \"many\");", 1, 14, "argument '$fn' of sphere must be a number"));
  EXPECT_TRUE(Refused("rotate(a = [90, 0, 0], v = [1, 0, 0]) cube();", 1, 24,
                      "'v' (an axis) is used only with a scalar angle 'a'"));
  EXPECT_TRUE(
      Refused("rotate(a = \"x\") cube();", 1, 12, "must be a number or a vector of 2 or 3 numbers"));
}

TEST(ParserRefusesValues, Colours) {
  EXPECT_TRUE(Refused("color([1.5, 0, 0]) cube();", 1, 8,
                      "colour component 1 of argument 'c' of color must be in [0, 1], got 1.5"));
  EXPECT_TRUE(Refused("color([1, 0, 0, 2]) cube();", 1, 17,
                      "alpha of argument 'c' of color must be in [0, 1]"));
  EXPECT_TRUE(Refused("color(\"red\", alpha = -0.5) cube();", 1, 22,
                      "argument 'alpha' of color must be in [0, 1]"));
  EXPECT_TRUE(Refused("color(\"gren\") cube();", 1, 7,
                      "unknown colour \"gren\" (did you mean \"green\"?)"));
  EXPECT_TRUE(Refused("color(\"#12345\") cube();", 1, 7, "unknown colour \"#12345\""));
  EXPECT_TRUE(
      Refused("color([1, 0]) cube();", 1, 7, "argument 'c' of color must be a colour name"));
  EXPECT_TRUE(Refused("color(true) cube();", 1, 7, "got a boolean"));
}

TEST(ParserRefusesValues, Camera) {
  EXPECT_TRUE(Refused("camera(eye = [1, 2, 3], center = [1, 2, 3]);\ncube();", 1, 34,
                      "camera eye and center must differ"));
  EXPECT_TRUE(Refused("camera(eye = [0, 0, 5], up = [0, 0, 2]);\ncube();", 1, 30,
                      "must be non-zero and not parallel to the view direction"));
  EXPECT_TRUE(
      Refused("camera(eye = [0, -5, 0], up = [0, 0, 0]);\ncube();", 1, 31, "must be non-zero"));
  // With every orientation argument left out, the verdict is the defaults' own.
  Camera d;
  bool defaults_degenerate =
      glm::length(glm::cross(glm::normalize(d.center - d.eye), glm::normalize(d.up))) < 1e-9;
  if (defaults_degenerate) {
    EXPECT_TRUE(
        Refused("camera(size = [100, 100]);\ncube();", 1, 1, "not parallel to the view direction"));
  } else {
    EXPECT_NO_THROW(parse("camera(size = [100, 100]);\ncube();"));
  }
  EXPECT_TRUE(Refused("camera(eye = [0, -5, 0], fov = 0);\ncube();", 1, 32,
                      "camera fov must be between 0 and 180 degrees (exclusive), got 0"));
  EXPECT_TRUE(Refused("camera(eye = [0, -5, 0], fov = 180);\ncube();", 1, 32, "got 180"));
  EXPECT_TRUE(Refused("camera(eye = [0, -5, 0], size = [0, 100]);\ncube();", 1, 34,
                      "camera size must be two whole numbers of pixels in 1..16384, got 0"));
  EXPECT_TRUE(
      Refused("camera(eye = [0, -5, 0], size = [100, 16385]);\ncube();", 1, 39, "got 16385"));
  EXPECT_TRUE(
      Refused("camera(eye = [0, -5, 0], size = [100.5, 100]);\ncube();", 1, 34, "got 100.5"));
  EXPECT_TRUE(Refused("camera(eye = [0, -5, 0], size = 512);\ncube();", 1, 33,
                      "must be a vector [width, height]"));
  EXPECT_TRUE(Refused("camera(eye = [0, -5, 0]);\ncube();\ncamera(eye = [0, 5, 0]);", 3, 1,
                      "at most one camera() statement is allowed; the first is at 1:1"));
}

TEST(ParserRefusesValues, Materials) {
  EXPECT_TRUE(Refused("material(diffuse = -0.1) cube();", 1, 20,
                      "argument 'diffuse' of material must not be negative"));
  EXPECT_TRUE(Refused("material(ior = 0) cube();", 1, 16,
                      "argument 'ior' of material must be positive, got 0"));
  EXPECT_TRUE(Refused("material(reflect = 0.5, transmit = 0.6) cube();", 1, 36,
                      "material reflect + transmit must not exceed 1, got 0.5 + 0.6"));
  EXPECT_TRUE(Refused("material(transmit = 0.7) {\n  material(reflect = 0.4) cube();\n}", 2, 22,
                      "reflect + transmit must not exceed 1, got 0.4 + 0.7"));
}

TEST(ParserRefusesValues, LightsAndBackground) {
  EXPECT_TRUE(
      Refused("light(color = [1, 1, 1]);\ncube();", 1, 1, "light() needs position=[x, y, z]"));
  EXPECT_TRUE(Refused("light(position = [0, 0, 9], color = [1, -1, 1]);\ncube();", 1, 37,
                      "light color must not be negative"));
  EXPECT_TRUE(Refused("background();\ncube();", 1, 1, "background() needs color=[r, g, b]"));
  EXPECT_TRUE(
      Refused("background(\"#00000080\");\ncube();", 1, 12, "background color has no alpha"));
  EXPECT_TRUE(
      Refused("background(color = [0, 0, 2]);\ncube();", 1, 27, "must be in [0, 1], got 2"));
  EXPECT_TRUE(Refused("background([0, 0, 0]);\nbackground([1, 1, 1]);\ncube();", 2, 1,
                      "at most one background() statement is allowed"));
}

// ---------------------------------------------------------------- refusals: syntax

TEST(ParserRefusesSyntax, MissingBrace) {
  EXPECT_TRUE(Refused("union() {\n  sphere();\n  cube();\n", 4, 1,
                      "missing '}': the '{' at 1:9 is not closed"));
  EXPECT_TRUE(Refused("sphere();\n}", 2, 1,
                      "expected an object such as sphere(), cube() or cylinder(), got '}'"));
}

TEST(ParserRefusesSyntax, MissingSemicolon) {
  EXPECT_TRUE(Refused("cube();\nsphere(1)", 2, 10,
                      "unexpected end of file: expected ';', '{' or a child object after sphere(...)"));
  EXPECT_TRUE(Refused("sphere(1)\ncube(1);", 2, 1,
                      "sphere() takes no children (missing ';' after sphere(...)?)"));
  EXPECT_TRUE(Refused("union() { sphere(1) }", 1, 21,
                      "expected ';', '{' or a child object after sphere(...), got '}'"));
}

TEST(ParserRefusesSyntax, MissingParenthesisBracketOrComma) {
  EXPECT_TRUE(Refused("sphere(r = 1;", 1, 13, "expected ',' or ')', got ';'"));
  EXPECT_TRUE(Refused("cube([1, 2 3]);", 1, 12, "expected ',' or ']', got number 3"));
  EXPECT_TRUE(Refused("cube([1, 2, 3", 1, 14, "missing ']'"));
  EXPECT_TRUE(Refused("cube(", 1, 6, "missing ')': the '(' of cube at 1:5 is not closed"));
  EXPECT_TRUE(Refused("cube;", 1, 5, "expected '(' after 'cube', got ';'"));
  EXPECT_TRUE(Refused("sphere(r = );", 1, 12, "expected a value, got ')'"));
}

TEST(ParserRefusesSyntax, UnterminatedStringAndComment) {
  EXPECT_TRUE(Refused("cube();\ncolor(\"red) cube();", 2, 7, "unterminated string"));
  EXPECT_TRUE(Refused("cube();\n  /* comment\n cube();", 2, 3, "unterminated comment"));
  EXPECT_TRUE(Refused("color(\"r\\ed\") cube();", 1, 9, "unsupported escape '\\e' in string"));
}

// Strings the messages quote are shown whole and on one line: a NUL no longer
// ends the message, and bytes that are not UTF-8 are not written raw.
TEST(ParserRefusesSyntax, QuotedStringsAreEscaped) {
  using namespace std::string_literals;
  EXPECT_TRUE(Refused("cube();\n\"a\0b\";"s, 2, 1,
                      R"(expected an object such as sphere(), cube() or cylinder(), got string "a\0b")"));
  EXPECT_TRUE(Refused("color(\"re\0d\") cube();"s, 1, 7, R"(unknown colour "re\0d" (did you mean "red"?); use)"));
  EXPECT_TRUE(Refused("color(\"gr\xFCn\") cube();", 1, 7, R"(unknown colour "gr\xFCn"; use)"));
  // Well-formed UTF-8 is kept; a truncated sequence, an overlong form and a
  // surrogate are not well-formed.
  EXPECT_TRUE(Refused("color(\"gr\xC3\xBCn\") cube();", 1, 7, "unknown colour \"gr\xC3\xBCn\"; use"));
  EXPECT_TRUE(Refused("color(\"\xE2\x82\") cube();", 1, 7, R"(unknown colour "\xE2\x82"; use)"));
  EXPECT_TRUE(Refused("color(\"\xC0\xAF\") cube();", 1, 7, R"(unknown colour "\xC0\xAF"; use)"));
  EXPECT_TRUE(Refused("color(\"\xED\xA0\x80\") cube();", 1, 7, R"(unknown colour "\xED\xA0\x80"; use)"));
  // Control characters, quotes and backslashes, decoded or raw.
  EXPECT_TRUE(Refused("color(\"a\\n\\\"\\\\\x01\x7f\tb\") cube();", 1, 7,
                      R"(unknown colour "a\n\"\\\x01\x7F\tb"; use)"));
  EXPECT_TRUE(Refused("color(\"a\\\xC3\xA9\") cube();", 1, 9,
                      R"(unsupported escape '\' followed by byte 0xC3 in string)"));
  EXPECT_TRUE(Refused("color(\"a\\\0\") cube();"s, 1, 9,
                      R"(unsupported escape '\' followed by byte 0x00 in string)"));
  try {
    parse("\"\0\";"s);
    ADD_FAILURE() << "parsed";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()).size(), std::strlen(e.what()));
  }
}

// A string of any length is quoted by its start and its length, and a name of
// any length is refused as fast as a short one: the guess at a misspelling
// looks only at names that could be one (a colour name of 200,000 letters once
// took seconds under the sanitizers, each of the 140 names compared in full).
TEST(ParserRefusesSyntax, LongNamesAndStrings) {
  constexpr size_t kShown = 64;  // bytes of a long string a message shows
  const std::string long_colour(200000, 'q');
  EXPECT_TRUE(Refused("color(\"" + long_colour + "\") cube();", 1, 7,
                      "unknown colour \"" + std::string(kShown, 'q') +
                          "\"... (200000 bytes in all); use"));
  // Past twice the longest name no misspelling is guessed, but a name that
  // starts with an accepted one still names it.
  const std::string yellowish = "yellow" + std::string(100, 'x');
  EXPECT_TRUE(Refused("color(\"" + yellowish + "\") cube();", 1, 7,
                      "... (106 bytes in all) (did you mean \"yellow\"?)"));
  EXPECT_TRUE(Refused("color(\"grenn\") cube();", 1, 7, "(did you mean \"green\"?)"));
  const std::string long_module(100000, 'z');
  EXPECT_TRUE(Refused(long_module + "();", 1, 1, "unknown module '" + long_module + "'; supported"));
  // A UTF-8 character is not cut: the quote ends after the one that crosses the limit.
  const std::string accents = std::string(kShown - 1, 'a') + "\xC3\xA9" + "bbb";
  EXPECT_TRUE(Refused("color(\"" + accents + "\") cube();", 1, 7,
                      "\"" + std::string(kShown - 1, 'a') + "\xC3\xA9\"... (68 bytes in all)"));
}

TEST(ParserRefusesSyntax, StrayCharacters) {
  EXPECT_TRUE(Refused("cube();\n  @cube();", 2, 3, "unexpected character '@'"));
  EXPECT_TRUE(Refused("cube(size = 1)`;", 1, 15, "unexpected character '`'"));
  EXPECT_TRUE(Refused("cube(\xC3\xA9);", 1, 6, "unexpected byte 0xC3"));
}

TEST(ParserRefusesSyntax, EmptyFileAndNoObjects) {
  EXPECT_TRUE(Refused("", 1, 1, "empty scene file: no objects"));
  EXPECT_TRUE(Refused("\n  \n", 3, 1, "empty scene file: no objects"));
  EXPECT_TRUE(Refused("// only a comment\n", 2, 1, "empty scene file: no objects"));
  EXPECT_TRUE(Refused("camera(eye = [0, -5, 0]);\nlight(position = [1, 1, 1]);\n;", 3, 2,
                      "scene has no objects"));
}

TEST(ParserRefusesSyntax, ErrorInsideDroppedSubtreeStillRefused) {
  EXPECT_TRUE(Refused("cube();\n%sphere(r = -1);", 2, 13, "must be positive"));
  EXPECT_TRUE(Refused("cube();\n*polyhedron();", 2, 2, "polyhedron needs its points"));
}

// ---------------------------------------------------------------- nesting depth

std::string repeated(std::string_view text, int times) {
  std::string out;
  out.reserve(text.size() * static_cast<size_t>(times));
  for (int i = 0; i < times; ++i) out += text;
  return out;
}

// How many operator nodes lie above the first leaf (by first children).
int depth_of_first_leaf(const CsgNode& root) {
  int depth = 0;
  for (const CsgNode* n = &root; !n->is_leaf; n = &n->children.at(0)) ++depth;
  return depth;
}

constexpr std::string_view kTooDeep =
    "nesting deeper than 1000 levels is not supported (calls' children, { } blocks, [ ] vectors "
    "and the ( ), ? and ^ of expressions inside one another)";

// The documented limit, 1000 levels, is read whole by every kind of nesting.
TEST(ParserNesting, AThousandLevelsAreRead) {
  Scene unions = parse(repeated("union() {", 1000) + "sphere();" + repeated("}", 1000));
  EXPECT_EQ(depth_of_first_leaf(unions.root), 1001);  // the file's own union on top
  Scene moved = parse(repeated("translate([1, 0, 0])\n", 1000) + "sphere();");
  ASSERT_EQ(moved.primitives.size(), 1u);
  EXPECT_TRUE(Near(apply(moved.primitives[0].to_world, {0, 0, 0}), {1000, 0, 0}));
  EXPECT_EQ(parse(repeated("{", 1000) + "sphere();" + repeated("}", 1000)).primitives.size(), 1u);
  EXPECT_TRUE(Refused("sphere(r = " + repeated("[", 1000) + "1" + repeated("]", 1000) + ");", 1,
                      12, "argument 'r' of sphere must be a number, got a vector of 1 element"));
}

// One level more is refused where it opens, whatever the kinds that add up to
// it; the files of the report, which crashed, are refused at level 1001.
TEST(ParserNesting, DeeperIsRefusedWhereTheLimitIsPassed) {
  EXPECT_TRUE(Refused(repeated("union() {", 1001) + "sphere();" + repeated("}", 1001), 1,
                      9 * 1001, kTooDeep));
  // The vector of the 1001st translate is inside 1000 calls.
  EXPECT_TRUE(Refused(repeated("translate([1, 0, 0])\n", 1001) + "sphere();", 1001, 11, kTooDeep));
  EXPECT_TRUE(Refused(repeated("rotate(90)\n", 1001) + "sphere();", 1002, 1, kTooDeep));
  EXPECT_TRUE(Refused("sphere(r = " + repeated("[", 1001) + "1" + repeated("]", 1001) + ");", 1,
                      12 + 1000, kTooDeep));
  EXPECT_TRUE(Refused(repeated("union() {", 500) + repeated("{", 500) + "sphere(r = [1]);" +
                          repeated("}", 1000),
                      1, 9 * 500 + 500 + 12, kTooDeep));
  EXPECT_TRUE(Refused(repeated("union() {", 5000) + "sphere(1);" + repeated("}", 5000), 1,
                      9 * 1001, kTooDeep));
  EXPECT_TRUE(Refused(repeated("{", 3000), 1, 1001, kTooDeep));
  // Expressions add their levels to those of the calls around them.
  EXPECT_TRUE(Refused(repeated("union() {", 500) + "sphere(r = " + repeated("(", 501) + "1" +
                          repeated(")", 501) + ");" + repeated("}", 500),
                      1, 9 * 500 + 11 + 501, kTooDeep));
  EXPECT_TRUE(Refused("sphere(r=" + repeated("[", 100000) + "1" + repeated("]", 100000) + ");", 1,
                      10 + 1000, kTooDeep));
}

// ---------------------------------------------------------------- size limits

TEST(ParserLimits, DefaultsAreTheDocumentedOnes) {
  EXPECT_EQ(ParseLimits{}.max_file_bytes, 32u << 20);
  EXPECT_EQ(ParseLimits{}.max_primitives, 1000000u);
}

// A file past the size limit is refused as a whole before it is parsed.
TEST(ParserLimits, FileLargerThanTheLimitIsRefusedUnread) {
  std::string text = "sphere();" + std::string((32u << 20) - 9, ' ');
  EXPECT_EQ(parse(text).primitives.size(), 1u);
  text += ' ';
  try {
    parse(text);
    FAIL() << "parsed";
  } catch (const SceneError& e) {
    EXPECT_STREQ(e.what(),
                 "t.csg: the file is larger than 33554432 bytes (32 MiB), the most capsim reads "
                 "(reading takes up to about 100 bytes of memory per byte)");
    EXPECT_EQ(e.loc().line, 0);
  }
  const std::string path =
      (std::filesystem::temp_directory_path() / "capsim_parser_test_large.csg").string();
  std::ofstream(path) << "sphere(); cube(); cylinder();";
  try {
    parse_scene_file(path, ParseLimits{28, 10});
    FAIL() << "parsed";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), path + ": the file is larger than 28 bytes (0 MiB), the most "
                                            "capsim reads (reading takes up to about 100 bytes of "
                                            "memory per byte)");
  }
  EXPECT_EQ(parse_scene_file(path, ParseLimits{29, 10}).primitives.size(), 3u);
  std::filesystem::remove(path);
}

// The primitive past the limit is refused where it stands; dropped ones count,
// as they are read and held too.
TEST(ParserLimits, PrimitivePastTheLimitIsRefusedWhereItStands) {
  const ParseLimits three{1 << 20, 3};
  EXPECT_EQ(parse_scene("sphere(); cube();\n%cylinder();", kFile, three).primitives.size(), 2u);
  try {
    parse_scene("sphere(); cube();\n%cylinder(); translate([1, 0, 0]) sphere();", kFile, three);
    FAIL() << "parsed";
  } catch (const SceneError& e) {
    EXPECT_STREQ(e.what(), "t.csg:2:35: more than 3 primitives: capsim reads at most 3 (each needs "
                           "about 1.7 KB of memory until it is traced)");
  }
}

TEST(ParserFile, UnreadableFile) {
  std::string path =
      (std::filesystem::temp_directory_path() / "capsim_parser_test_missing.csg").string();
  std::filesystem::remove(path);
  try {
    parse_scene_file(path);
    FAIL() << "parsed a missing file";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), path + ": cannot read: No such file or directory");
    EXPECT_EQ(e.loc().line, 0);
  }
  std::string dir = std::filesystem::temp_directory_path().string();
  try {
    parse_scene_file(dir);
    FAIL() << "parsed a directory";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), dir + ": cannot read: Is a directory");
  }
}

TEST(ParserFile, ErrorsNameTheFile) {
  std::string path =
      (std::filesystem::temp_directory_path() / "capsim_parser_test_bad.csg").string();
  {
    std::ofstream out(path);
    out << "cube();\n  sphere(r = 0);\n";
  }
  try {
    parse_scene_file(path);
    FAIL() << "accepted r = 0";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()),
              path + ":2:14: argument 'r' of sphere must be positive, got 0");
  }
  std::filesystem::remove(path);
}

// ---------------------------------------------------------------- real files

TEST(ParserOpenScadExport, ParsesUnchangedWithOpenScadsValues) {
  Scene s = parse_scene_file(source_path("tests/data/openscad_export.csg"));
  ASSERT_EQ(s.primitives.size(), 32u);
  const auto& p = s.primitives;
  EXPECT_TRUE(Near(apply(p[0].to_world, {1, 0, 0}), {2, 0, 0}));
  EXPECT_TRUE(Near(apply(p[1].to_world, {1, 0, 0}), {1.5, 0, 0}));
  EXPECT_TRUE(Near(apply(p[3].to_world, {0, 0, 0}), {-0.5, -1, -1.5}));
  EXPECT_EQ(p[4].kind, PrimitiveKind::Cone);
  EXPECT_DOUBLE_EQ(p[4].cone_r1, 0.5);
  EXPECT_TRUE(Near(apply(p[5].to_world, {1, 0, 0}), {2, 0, -1}));
  EXPECT_DOUBLE_EQ(p[6].cone_r2, 0.0);
  EXPECT_TRUE(Near(apply(p[7].to_world, {0, 0, 0}), {1, 2, 3}));
  // OpenSCAD's own rotation matrices (written to 6 digits) agree with ours.
  Scene ours = parse(
      "rotate(45) cube();\nrotate([10, 20, 30]) cube();\nrotate(a = 30, v = [1, 1, 0]) cube();\n"
      "mirror([1, 1, 0]) cube();\nmultmatrix([[1, 0.5, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]) "
      "cube();");
  const int exported[] = {8, 9, 10, 14, 15};
  for (int i = 0; i < 5; ++i) {
    for (glm::dvec3 q : {glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1)}) {
      EXPECT_TRUE(
          Near(apply(p[exported[i]].to_world, q), apply(ours.primitives[i].to_world, q), 2e-6))
          << i;
    }
  }
  EXPECT_TRUE(Near(apply(p[11].to_world, {1, 1, 1}), {1, 1, 1}));
  EXPECT_TRUE(Near(apply(p[12].to_world, {1, 1, 1}), {2, 2, 2}));
  EXPECT_TRUE(Near(apply(p[13].to_world, {1, 1, 1}), {1, 2, 3}));
  EXPECT_TRUE(Near(p[16].color, {1, 0, 0}));
  EXPECT_TRUE(Near(p[17].color, {0, 1, 0}));
  EXPECT_NEAR(p[18].alpha, 0.501961, 1e-9);
  EXPECT_TRUE(Near(p[19].color, {0, 0, 1}));
  EXPECT_DOUBLE_EQ(p[19].alpha, 0.5);
  EXPECT_TRUE(Near(p[20].color, {linear(0.666667), linear(0.733333), linear(0.8)}, 1e-12));
  EXPECT_EQ(p[21].color, Primitive{}.color);
  EXPECT_DOUBLE_EQ(p[21].alpha, 0.25);
  EXPECT_TRUE(Near(apply(p[22].to_world, {1, 1, 1}), {3, 3, 3}));  // '#' kept, '%' dropped
  // Top level: 23 single objects, union, difference, intersection, render, pair, group(), union().
  ASSERT_EQ(s.root.children.size(), 30u);
  EXPECT_EQ(s.root.children[23].op, CsgOp::Union);
  EXPECT_EQ(s.root.children[23].children.size(), 2u);
  EXPECT_EQ(s.root.children[24].op, CsgOp::Difference);
  EXPECT_EQ(s.root.children[25].op, CsgOp::Intersection);
  EXPECT_TRUE(s.root.children[26].is_leaf);         // render() passes through
  EXPECT_EQ(s.root.children[27].op, CsgOp::Union);  // the module call: group()
  EXPECT_EQ(s.root.children[27].children.size(), 2u);
  EXPECT_TRUE(s.root.children[28].children.empty());
  EXPECT_TRUE(s.root.children[29].children.empty());
}

TEST(ParserScenes, BallsHas125SpheresAllInFrame) {
  Scene s = parse_scene_file(source_path("scenes/balls.csg"));
  ASSERT_EQ(s.primitives.size(), 125u);
  int reflective = 0, transparent = 0;
  for (const Primitive& p : s.primitives) {
    EXPECT_EQ(p.kind, PrimitiveKind::Sphere);
    reflective += p.material.reflect == 0.4;
    transparent += p.material.transmit == 0.7 && p.material.ior == 1.5;
  }
  EXPECT_GT(reflective, 0);
  EXPECT_GT(transparent, 0);
  ASSERT_TRUE(s.camera.has_value());
  EXPECT_EQ(s.camera->width, 512);
  EXPECT_EQ(s.camera->height, 512);
  EXPECT_EQ(s.lights.size(), 2u);
  // Every ball's bounding sphere lies inside the view frustum.
  const Camera& c = *s.camera;
  glm::dvec3 forward = glm::normalize(c.center - c.eye);
  glm::dvec3 right = glm::normalize(glm::cross(forward, c.up));
  glm::dvec3 up = glm::cross(right, forward);
  double half = c.fov_deg / 2 * M_PI / 180;
  double half_h = std::atan(std::tan(half) * c.width / c.height);
  for (const Primitive& p : s.primitives) {
    glm::dvec3 center = apply(p.to_world, {0, 0, 0});
    double radius = glm::length(apply(p.to_world, {1, 0, 0}) - center);
    glm::dvec3 d = center - c.eye;
    double z = glm::dot(d, forward);
    double angle_v = std::atan2(std::abs(glm::dot(d, up)), z) + std::asin(radius / glm::length(d));
    double angle_h =
        std::atan2(std::abs(glm::dot(d, right)), z) + std::asin(radius / glm::length(d));
    EXPECT_LT(angle_v, half);
    EXPECT_LT(angle_h, half_h);
  }
}

TEST(ParserScenes, ShowcaseHasAllKindsAndOperators) {
  Scene s = parse_scene_file(source_path("scenes/showcase.csg"));
  bool kinds[3] = {false, false, false};
  for (const Primitive& p : s.primitives) kinds[static_cast<int>(p.kind)] = true;
  EXPECT_TRUE(kinds[0] && kinds[1] && kinds[2]);
  bool ops[3] = {false, false, false};
  auto visit = [&](auto&& self, const CsgNode& n) -> void {
    if (n.is_leaf) return;
    if (!(n.op == CsgOp::Union && &n == &s.root)) ops[static_cast<int>(n.op)] = true;
    for (const CsgNode& c : n.children) self(self, c);
  };
  visit(visit, s.root);
  EXPECT_TRUE(ops[0] && ops[1] && ops[2]);
  EXPECT_TRUE(s.camera.has_value());  // the pinned view (docs/models.md); the default light
  EXPECT_TRUE(s.lights.empty());
}

TEST(ParserScenes, EveryProjectSceneParses) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(source_path("scenes"))) {
    if (entry.path().extension() != ".csg") continue;
    ++count;
    Scene s;
    EXPECT_NO_THROW(s = parse_scene_file(entry.path().string())) << entry.path();
    EXPECT_FALSE(s.primitives.empty()) << entry.path();
  }
  EXPECT_GE(count, 2);
}

}  // namespace
}  // namespace capsim
