// The POV-Ray scene bench_vs_povray renders beside capsim (bench/pov/): its
// text for small scenes, read without POV-Ray, which the tests do not need.

#include "pov/pov_scene.h"

#include "capsim/scene/parser.h"
#include "capsim/trace/prepared_scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>

using namespace capsim;

namespace {

std::string pov_text(const std::string& scene_text) {
  return pov::pov_scene(prepare_scene(parse_scene(scene_text, "test.csg"), {}), 5);
}

// The number that follows the first `key` at or after `from` in `text`.
double number_after(const std::string& text, const std::string& key, std::size_t from = 0) {
  const std::size_t at = text.find(key, from);
  EXPECT_NE(at, std::string::npos) << key;
  if (at == std::string::npos) return NAN;
  return std::strtod(text.c_str() + at + key.size(), nullptr);
}

const char* const kScene = R"(
camera(eye = [10, -20, 5], center = [0, 0, 1], up = [0, 0, 1], fov = 30, size = [200, 100]);
light(position = [5, -5, 10], color = [1, 0.5, 0.25]);
background(color = [0, 0, 0]);
difference() {
  material(reflect = 0.25, specular = 0.5, shininess = 16) color([1, 1, 1]) sphere(r = 2);
  translate([1, 2, 3]) color([0, 0, 1]) cube(size = [1, 2, 4]);
}
)";

TEST(PovScene, WritesTheCameraLightsAndDepth) {
  const std::string pov = pov_text(kScene);
  EXPECT_NE(pov.find("global_settings { assumed_gamma 1.0 max_trace_level 6 adc_bailout 0"), std::string::npos)
      << pov;
  EXPECT_NE(pov.find("  perspective\n  location <10, -20, 5>\n"), std::string::npos) << pov;
  // capsim's frame is right-handed: the image's right is -x in POV-Ray's
  // camera, as wide as the aspect ratio.
  EXPECT_NE(pov.find("  right -x * 2\n  up y\n"), std::string::npos) << pov;
  EXPECT_NE(pov.find("  sky <0, 0, 1>\n  look_at <0, 0, 1>\n"), std::string::npos) << pov;
  // POV-Ray's angle is horizontal: 30 degrees vertical over an aspect of 2.
  const double pi = std::acos(-1.0);
  EXPECT_NEAR(number_after(pov, "angle "), 2 * std::atan(2 * std::tan(15 * pi / 180)) * 180 / pi, 1e-12);
  EXPECT_NE(pov.find("light_source { <5, -5, 10> color rgb <1, 0.5, 0.25> }"), std::string::npos) << pov;
  EXPECT_NE(pov.find("background { rgb <0, 0, 0> }"), std::string::npos) << pov;
}

TEST(PovScene, WritesTheCsgTransformsAndMaterials) {
  const std::string pov = pov_text(kScene);
  const std::size_t difference = pov.find("difference {\n");
  ASSERT_NE(difference, std::string::npos) << pov;
  const std::size_t sphere =
      pov.find("sphere { <0, 0, 0>, 1 matrix <2, 0, 0, 0, 2, 0, 0, 0, 2, 0, 0, 0> texture { pigment { rgb <1, 1, 1> }",
               difference);
  ASSERT_NE(sphere, std::string::npos) << pov;
  // The unit cube, scaled then translated: row-vector form, translation last.
  const std::size_t box = pov.find(
      "box { <0, 0, 0>, <1, 1, 1> matrix <1, 0, 0, 0, 2, 0, 0, 0, 4, 1, 2, 3> texture { pigment { rgb <0, 0, 1> }",
      sphere);
  ASSERT_NE(box, std::string::npos) << pov;
  // The polished sphere's local light weighted by 1 - reflect, as capsim's.
  EXPECT_NEAR(number_after(pov, "ambient ", sphere), 0.1 * 0.75, 1e-15);
  EXPECT_NEAR(number_after(pov, "diffuse ", sphere), 0.8 * 0.75, 1e-15);
  EXPECT_NEAR(number_after(pov, "phong ", sphere), 0.5 * 0.75, 1e-15);
  EXPECT_EQ(number_after(pov, "phong_size ", sphere), 16);
  EXPECT_EQ(number_after(pov, "reflection { ", sphere), 0.25);
  // The cube's are the defaults, and it reflects nothing.
  EXPECT_EQ(number_after(pov, "ambient ", box), 0.1);
  EXPECT_EQ(number_after(pov, "diffuse ", box), 0.8);
  EXPECT_EQ(number_after(pov, "phong ", box), 0.3);
  EXPECT_EQ(number_after(pov, "phong_size ", box), 32);
  EXPECT_EQ(pov.find("reflection", box), std::string::npos) << pov;
}

TEST(PovScene, MergesOnlyOverlappingOperandsThatLetLightThrough) {
  const std::string apart = pov_text(
      "material(transmit = 0.5, ior = 1.3) union() { sphere(r = 1); translate([5, 0, 0]) sphere(r = 1); }\n"
      "translate([0, 5, 0]) cube(1);");
  EXPECT_EQ(apart.find("merge"), std::string::npos) << apart;
  EXPECT_NE(apart.find("pigment { rgb <0.946, 0.679, 0.025> transmit 0.5 }"), std::string::npos) << apart;
  EXPECT_NE(apart.find("interior { ior 1.3 }"), std::string::npos) << apart;
  // POV-Ray weights ambient and diffuse by 1 - transmit itself.
  EXPECT_NEAR(number_after(apart, "ambient "), 0.1 * 0.5 / 0.5, 1e-15);

  const std::string overlapping = pov_text(
      "material(transmit = 0.5) sphere(r = 1); translate([1, 0, 0]) sphere(r = 1);\n"
      "translate([0, 5, 0]) cube(1);");
  const std::size_t merge = overlapping.find("merge {\n");
  ASSERT_NE(merge, std::string::npos) << overlapping;
  // The cube, apart from both, stays out of the merge.
  const std::size_t merge_end = overlapping.find("\n}", merge);
  const std::size_t box = overlapping.find("box {");
  EXPECT_TRUE(box < merge || box > merge_end) << overlapping;
}

// capsim's shadows are opaque: a transparent object is seen without casting
// one, and an unseen, untextured copy casts it.
TEST(PovScene, TransparentObjectsCastOpaqueShadows) {
  const std::string pov = pov_text(
      "material(transmit = 0.5) sphere(r = 1);\n"
      "translate([0, 5, 0]) cube(1);");
  const std::size_t seen = pov.find("sphere { <0, 0, 0>, 1 matrix <1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0> texture {");
  ASSERT_NE(seen, std::string::npos) << pov;
  EXPECT_EQ(pov.find("interior { ior 1.5 } no_shadow }\n", seen), pov.find("interior", seen)) << pov;
  const std::size_t caster =
      pov.find("sphere { <0, 0, 0>, 1 matrix <1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0> no_image no_reflection }\n");
  EXPECT_NE(caster, std::string::npos) << pov;
  // The opaque cube is written once, casting its own shadow.
  EXPECT_EQ(pov.find("box {"), pov.rfind("box {")) << pov;
  EXPECT_EQ(pov.find("no_shadow", pov.find("box {")), std::string::npos) << pov;
}

TEST(PovScene, WritesCylindersConesAndMeshes) {
  const std::string pov = pov_text(
      "cylinder(h = 2, r = 0.5);\n"
      "translate([3, 0, 0]) cylinder(h = 1, r1 = 2, r2 = 0);\n"
      "translate([0, 3, 0]) polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],\n"
      "                                faces = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]]);");
  // The canonical frustum's radii are at most 1; the size is in the matrix.
  EXPECT_NE(pov.find("cylinder { <0, 0, 0>, <0, 0, 1>, 1 matrix <0.5, 0, 0, 0, 0.5, 0, 0, 0, 2, 0, 0, 0>"),
            std::string::npos) << pov;
  EXPECT_NE(pov.find("cone { <0, 0, 0>, 1, <0, 0, 1>, 0 matrix <2, 0, 0, 0, 2, 0, 0, 0, 1, 3, 0, 0>"),
            std::string::npos) << pov;
  EXPECT_NE(pov.find("mesh2 {\n  vertex_vectors { 4, "), std::string::npos) << pov;
  EXPECT_NE(pov.find("\n  face_indices { 4, "), std::string::npos) << pov;
  EXPECT_NE(pov.find("\n  inside_vector "), std::string::npos) << pov;
}

TEST(PovScene, RefusesARevolutionNamingIt) {
  try {
    pov_text("rotate_extrude() translate([2, 0]) square(1);");
    FAIL() << "no refusal";
  } catch (const pov::Unsupported& e) {
    EXPECT_NE(std::string(e.what()).find("test.csg:1:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("rotate_extrude"), std::string::npos) << e.what();
  }
}

}  // namespace
