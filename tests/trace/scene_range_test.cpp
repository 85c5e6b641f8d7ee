// The scene-relative range (capsim/trace/scene_range.h), checked as a scene is
// prepared: located at the primitive or the camera.

#include "capsim/scene/parser.h"
#include "capsim/trace/prepared_scene.h"

#include <gtest/gtest.h>

#include <string_view>

namespace capsim {
namespace {

// Bounds relative to the scene's size S (the largest extent of what is placed)
// are checked when the scene is prepared, at the primitive or the camera.
TEST(SceneRange, RelativeToTheSceneWhenPrepared) {
  const auto prepared = [](std::string_view text) {
    PrepareOptions o;
    o.width = o.height = 8;
    return prepare_scene(parse_scene(text, "t.csg"), o);
  };
  EXPECT_EQ(prepared("sphere(1);\ntranslate([2, 0, 0]) cube([1, 1, 1e-5]);").grid.n, 8);
  try {
    prepared("sphere(1);\ntranslate([3, 0, 0]) sphere(1e-6);");
    FAIL() << "prepared";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.loc().line, 2);
    EXPECT_EQ(e.loc().col, 22);
    EXPECT_EQ(e.message(), "this sphere is too small for the scene: its smallest dimension 1e-06 is "
                           "less than 1e-6 times the scene's size 4.00001, the finest detail capsim "
                           "traces");
  }
  try {  // a mesh's own size counts, not only its placement
    prepared("sphere(1);\npolyhedron([[0, 0, 0], [1e-7, 0, 0], [0, 1e-7, 0], [0, 0, 1e-7]], [[0, 1, 2], [0, 3, 1], "
             "[0, 2, 3], [1, 3, 2]]);");
    FAIL() << "prepared";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.loc().line, 2);
    EXPECT_EQ(e.message().rfind("this mesh is too small for the scene: its smallest dimension 1e-07 is", 0), 0u)
        << e.message();
  }
  try {
    prepared("sphere(1);\ntranslate([1e7, 0, 0]) sphere(2);");
    FAIL() << "prepared";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.loc().line, 1);  // the first one too small for the scene of both
    EXPECT_NE(e.message().find("this sphere is too small for the scene"), std::string::npos);
  }
  try {
    prepared("translate([1e7, 0, 0]) sphere(1);");
    FAIL() << "prepared";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.loc().col, 24);
    EXPECT_EQ(e.message(), "this sphere reaches 1e+07 from the origin, more than 1e6 times the "
                           "scene's size 2, the farthest capsim traces; move the scene "
                           "nearer the origin");
  }
  try {
    prepared("camera(eye = [0, -3e6, 0]);\nsphere(1);");
    FAIL() << "prepared";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.loc().line, 1);
    EXPECT_EQ(e.loc().col, 14);
    EXPECT_EQ(e.message(), "the camera eye is 3e+06 from the origin, more than 1e6 times the "
                           "scene's size 2, the farthest capsim traces from; move the eye "
                           "nearer");
  }
  EXPECT_EQ(prepared("camera(eye = [0, -2e6, 0], fov = 1e-4);\nsphere(1);").camera.fov_deg, 1e-4);
}

}  // namespace
}  // namespace capsim
