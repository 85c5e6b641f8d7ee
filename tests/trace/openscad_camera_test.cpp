// OpenSCAD 2021.01's command-line camera as capsim resolves it (Camera.cc,
// GLView.cc): the default gimbal view, both --camera forms, --viewall and
// --autocenter, and the orthographic tracer's parallel rays.

#include "capsim/trace/csg_bounds.h"
#include "capsim/trace/openscad_camera.h"
#include "capsim/trace/prepared_scene.h"
#include "capsim/trace/tracer.h"
#include "support/scene_builders.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

using namespace capsim;
using namespace capsim::testing;

namespace {

constexpr double kPi = 3.14159265358979323846;

void expect_near(const glm::dvec3& a, const glm::dvec3& b, double tol = 1e-9) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

Aabb box_of(glm::dvec3 lo, glm::dvec3 hi) {
  Aabb b;
  b.extend(lo);
  b.extend(hi);
  return b;
}

// Without --camera: OpenSCAD's reset view ($vpr = [55, 0, 25]) with viewall
// and autocenter: from the front right, 35 degrees up, at the box's reach over
// sin(11.25 degrees).
TEST(OpenScadCamera, DefaultIsTheResetViewFramingTheBox) {
  const Aabb b = box_of({1, 2, 3}, {5, 4, 11});
  const Camera c = openscad_camera({}, b, 320, 240);
  expect_near(c.center, {3, 3, 7});
  const double distance = 0.5 * glm::length(b.extent()) / std::sin(11.25 * kPi / 180);
  const double az = 25 * kPi / 180, el = 35 * kPi / 180;
  expect_near(c.eye - c.center,
              distance * glm::dvec3(std::sin(az) * std::cos(el), -std::cos(az) * std::cos(el), std::sin(el)));
  EXPECT_EQ(c.fov_deg, kOpenScadFov);
  EXPECT_EQ(c.projection, Projection::Perspective);
  EXPECT_EQ(c.width, 320);
  EXPECT_EQ(c.height, 240);
  EXPECT_TRUE(expressible_as_openscad(c));
}

// The vector form keeps the eye and centre; up is z made perpendicular to the view.
TEST(OpenScadCamera, VectorFormKeepsEyeAndCentre) {
  OpenScadCameraOptions o;
  o.camera = {10, -20, 15, 1, 2, 3};
  const Camera c = openscad_camera(o, box_of({0, 0, 0}, {1, 1, 1}), 64, 64);
  expect_near(c.eye, {10, -20, 15});
  expect_near(c.center, {1, 2, 3});
  const glm::dvec3 forward = glm::normalize(c.center - c.eye);
  EXPECT_NEAR(glm::dot(c.up, forward), 0, 1e-12);
  EXPECT_NEAR(glm::cross(forward, c.up).z, 0, 1e-12);  // right is horizontal
  EXPECT_GT(c.up.z, 0);
  // Straight down: Camera::setup's special case, up along +y.
  o.camera = {0, 0, 10, 0, 0, 0};
  const Camera down = openscad_camera(o, box_of({0, 0, 0}, {1, 1, 1}), 64, 64);
  expect_near(down.eye, {0, 0, 10});
  expect_near(down.up, {0, 1, 0});
}

// The gimbal form reads as $vpt, $vpr and $vpd: [0, 0, 0] looks down with y
// up, [90, 0, 0] from the front, and the rotation about z turns the eye.
TEST(OpenScadCamera, GimbalFormIsVptVprVpd) {
  OpenScadCameraOptions o;
  const Aabb b = box_of({0, 0, 0}, {1, 1, 1});
  o.camera = {1, 2, 3, 0, 0, 0, 10};
  Camera c = openscad_camera(o, b, 64, 64);
  expect_near(c.center, {1, 2, 3});
  expect_near(c.eye, {1, 2, 13});
  expect_near(c.up, {0, 1, 0});
  o.camera = {0, 0, 0, 90, 0, 0, 10};
  c = openscad_camera(o, b, 64, 64);
  expect_near(c.eye, {0, -10, 0});
  expect_near(c.up, {0, 0, 1});
  o.camera = {0, 0, 0, 90, 0, 90, 10};
  c = openscad_camera(o, b, 64, 64);
  expect_near(c.eye, {10, 0, 0});
  // The same view in the vector form.
  o.camera = {10, 0, 0, 0, 0, 0};
  const Camera v = openscad_camera(o, b, 64, 64);
  expect_near(v.eye, c.eye);
  expect_near(v.up, c.up);
}

// --viewall keeps the camera's direction and centre and moves it back to the
// box's reach from the centre; with --autocenter it looks at the box's
// centre; --autocenter alone changes nothing (export_png consults it only
// within viewAll).
TEST(OpenScadCamera, ViewallAndAutocenter) {
  const Aabb b = box_of({10, 0, 0}, {12, 2, 2});
  OpenScadCameraOptions o;
  o.camera = {0, 0, 0, 90, 0, 0, 10};
  o.autocenter = true;
  expect_near(openscad_camera(o, b, 64, 64).eye, {0, -10, 0});
  o.autocenter = false;
  o.viewall = true;
  const double s = std::sin(11.25 * kPi / 180);
  const double reach = glm::length(glm::dvec3(11, 1, 1)) + std::sqrt(3.0);
  Camera c = openscad_camera(o, b, 64, 64);
  expect_near(c.center, {0, 0, 0});
  expect_near(c.eye, {0, -reach / s, 0});
  o.autocenter = true;
  c = openscad_camera(o, b, 64, 64);
  expect_near(c.center, {11, 1, 1});
  expect_near(c.eye, {11, 1 - std::sqrt(3.0) / s, 1});
}

TEST(OpenScadCamera, ArgumentsGiveTheView) {
  Camera c;
  c.eye = {1.5, -2, 3};
  c.center = {0, 0.25, 0};
  c.projection = Projection::Orthographic;
  EXPECT_EQ(camera_arguments(c), "--camera=1.5,-2,3,0,0.25,0 --projection=ortho");
  EXPECT_FALSE(expressible_as_openscad(c));  // the 40 degree field
  c.fov_deg = kOpenScadFov;
  EXPECT_TRUE(expressible_as_openscad(c));
  c.up = {1, 0, 0};
  EXPECT_FALSE(expressible_as_openscad(c));
}

// Four boxes: A [0, 4]^3, B [2, 6]^3 overlapping it, C [3, 3.5]^3 inside
// both, D [20, 21] x [0, 1]^2 apart.
std::vector<PreparedPrimitive> four_boxes() {
  std::vector<PreparedPrimitive> pp;
  for (const Primitive& p : {box({0, 0, 0}, {4, 4, 4}), box({2, 2, 2}, {4, 4, 4}), box({3, 3, 3}, {0.5, 0.5, 0.5}),
                             box({20, 0, 0}, {1, 1, 1})})
    pp.push_back(prepare_primitive(p));
  return pp;
}

void expect_box(const Aabb& b, glm::dvec3 lo, glm::dvec3 hi) {
  expect_near(b.lo, lo);
  expect_near(b.hi, hi);
}

// OpenSCAD's preview box: the solids drawn positively, an intersection's
// children all framed.
TEST(CsgBounds, PreviewBoxes) {
  const std::vector<PreparedPrimitive> pp = four_boxes();
  const CsgNode diff = op(CsgOp::Difference, {leaf(0), leaf(1)});
  expect_box(openscad_preview_bounds(diff, pp), {0, 0, 0}, {4, 4, 4});
  const CsgNode inter = op(CsgOp::Intersection, {leaf(0), leaf(1)});
  expect_box(openscad_preview_bounds(inter, pp), {0, 0, 0}, {6, 6, 6});
  const CsgNode both = op(CsgOp::Union, {op(CsgOp::Difference, {leaf(3), leaf(0)}), inter});
  expect_box(openscad_preview_bounds(both, pp), {0, 0, 0}, {21, 6, 6});
  // A - (B - C): C is drawn positively again (A and C overlap).
  const CsgNode nested = op(CsgOp::Difference, {leaf(0), op(CsgOp::Difference, {leaf(1), leaf(2)})});
  expect_box(openscad_preview_bounds(nested, pp), {0, 0, 0}, {4, 4, 4});
  const CsgNode nested_far = op(CsgOp::Difference, {leaf(0), op(CsgOp::Difference, {leaf(1), leaf(3)})});
  expect_box(openscad_preview_bounds(nested_far, pp), {0, 0, 0}, {4, 4, 4});  // B - D keeps B's box: D pruned
  // An intersection of boxes that do not meet is empty.
  EXPECT_TRUE(openscad_preview_bounds(op(CsgOp::Intersection, {leaf(0), leaf(3)}), pp).empty());
}

// What the CSG leaves: a difference its first child, an intersection the
// common part, a union everything; capsim's default view frames it.
TEST(CsgBounds, ResultBoxes) {
  const std::vector<PreparedPrimitive> pp = four_boxes();
  expect_box(csg_result_bounds(op(CsgOp::Difference, {leaf(0), leaf(3)}), pp), {0, 0, 0}, {4, 4, 4});
  expect_box(csg_result_bounds(op(CsgOp::Difference, {leaf(1), leaf(0), leaf(3)}), pp), {2, 2, 2}, {6, 6, 6});
  const CsgNode inter = op(CsgOp::Intersection, {leaf(0), leaf(1)});
  expect_box(csg_result_bounds(inter, pp), {2, 2, 2}, {4, 4, 4});
  expect_box(csg_result_bounds(op(CsgOp::Union, {inter, leaf(3)}), pp), {2, 0, 0}, {21, 4, 4});
  EXPECT_TRUE(csg_result_bounds(op(CsgOp::Intersection, {leaf(0), leaf(3)}), pp).empty());
}

// Without a camera the view frames what the CSG leaves; where the boxes show
// nothing is left, every solid.
TEST(DefaultView, FramesWhatTheCsgLeaves) {
  PrepareOptions o;
  o.width = 32;
  o.height = 24;
  const Scene cut = make_scene({box({0, 0, 0}, {4, 4, 4}), box({20, 0, 0}, {1, 1, 1})},
                               op(CsgOp::Difference, {leaf(0), leaf(1)}));
  const PreparedScene ps = prepare_scene(cut, o);
  const Camera expected = default_camera(box_of({0, 0, 0}, {4, 4, 4}), 32, 24);
  EXPECT_EQ(ps.camera.eye, expected.eye);
  EXPECT_EQ(ps.camera.center, expected.center);
  EXPECT_EQ(ps.lights.at(0).position, expected.eye);
  const Scene none = make_scene({box({0, 0, 0}, {4, 4, 4}), box({20, 0, 0}, {1, 1, 1})},
                                op(CsgOp::Intersection, {leaf(0), leaf(1)}));
  EXPECT_EQ(prepare_scene(none, o).camera.center, default_camera(box_of({0, 0, 0}, {21, 4, 4}), 32, 24).center);
}

// Orthographic: parallel rays along the view, from the eye plane, over a view
// 2 |centre - eye| tan(fov / 2) high; the perspective rays all leave the eye.
TEST(OpenScadCamera, OrthographicRaysAreParallel) {
  PrepareOptions o;
  o.width = 40;
  o.height = 20;
  Scene s = make_scene({sphere({0, 0, 0}, 1)});
  Camera cam;
  cam.eye = {0, -10, 0};
  cam.center = {0, 0, 0};
  cam.up = {0, 0, 1};
  cam.fov_deg = 30;
  cam.projection = Projection::Orthographic;
  s.camera = cam;
  const PreparedScene ps = prepare_scene(s, o);
  const Tracer t(ps, {});
  const double half = 10 * std::tan(15 * kPi / 180);
  const Ray corner = t.screen_ray(0, 0), centre = t.screen_ray(20, 10);
  expect_near(corner.dir, {0, 1, 0});
  expect_near(centre.dir, {0, 1, 0});
  expect_near(centre.origin, {0, -10, 0});
  expect_near(corner.origin, {-2 * half, -10, half});
  Scene p = s;
  p.camera->projection = Projection::Perspective;
  const PreparedScene pps = prepare_scene(p, o);
  const Tracer pt(pps, {});
  expect_near(pt.screen_ray(0, 0).origin, {0, -10, 0});
  expect_near(pt.screen_ray(0, 0).dir, glm::normalize(glm::dvec3(-2 * half / 10, 1, half / 10)));
}

// With OpenSCAD's options the camera is theirs, over a camera statement, and
// frames what OpenSCAD's preview frames.
TEST(OpenScadCamera, OptionsOverrideTheSceneCamera) {
  Scene s = make_scene({box({0, 0, 0}, {4, 4, 4}), box({2, 2, 2}, {4, 4, 4})},
                       op(CsgOp::Intersection, {leaf(0), leaf(1)}));
  s.camera = Camera{};
  PrepareOptions o;
  o.width = 32;
  o.height = 32;
  o.openscad = OpenScadCameraOptions{};
  const PreparedScene ps = prepare_scene(s, o);
  const Camera expected = openscad_camera({}, box_of({0, 0, 0}, {6, 6, 6}), 32, 32);
  expect_near(ps.camera.eye, expected.eye);
  expect_near(ps.camera.center, expected.center);
  EXPECT_EQ(ps.camera.fov_deg, kOpenScadFov);
  expect_near(ps.lights.at(0).position, expected.eye);
}

// One unit sphere seen by a camera looking from `eye` at `center` (z up) with
// the given projection, on a width x height screen.
PreparedScene sphere_seen_from(glm::dvec3 eye, glm::dvec3 center, double fov_deg, Projection projection,
                               int width, int height) {
  PrepareOptions o;
  o.width = width;
  o.height = height;
  Scene s = make_scene({sphere({0, 0, 0}, 1)});
  Camera cam;
  cam.eye = eye;
  cam.center = center;
  cam.up = {0, 0, 1};
  cam.fov_deg = fov_deg;
  cam.projection = projection;
  s.camera = cam;
  return prepare_scene(s, o);
}

// A pixel's primary ray is the screen ray through its centre, and a screen
// point's ray (antialiasing's corner and subdivision samples) the screen ray
// through it, to the bit, in both projections and on screens of odd sizes:
// the corners' and centres' offsets are worked out once, with the same
// arithmetic. Off the screen too (a pixel outside the camera's size is still a
// point of its plane).
TEST(OpenScadCamera, PrimaryRaysAreTheScreenRaysThroughPixelCentres) {
  for (const Projection projection : {Projection::Perspective, Projection::Orthographic})
    for (const auto& [width, height] : {std::pair{37, 23}, std::pair{1, 1}, std::pair{64, 48}}) {
      const PreparedScene ps = sphere_seen_from({0.3, -7.1, 2.2}, {0.1, 0, -0.4}, 41.3, projection, width, height);
      const Tracer t(ps, {});
      for (int j = -2; j < height + 2; ++j)
        for (int i = -2; i < width + 2; ++i) {
          const Ray a = t.primary_ray(i, j), b = t.screen_ray(i + 0.5, j + 0.5);
          ASSERT_EQ(a.origin, b.origin) << i << ", " << j;
          ASSERT_EQ(a.dir, b.dir) << i << ", " << j;
        }
      // Every quarter-pixel point from two pixels off each side: corners and
      // centres come from the tables, the others (and those off the screen)
      // from screen_ray itself; all are its rays.
      for (int j = -8; j <= 4 * height + 8; ++j)
        for (int i = -8; i <= 4 * width + 8; ++i) {
          const double u = 0.25 * i, v = 0.25 * j;
          const Ray a = t.screen_point_ray(u, v), b = t.screen_ray(u, v);
          ASSERT_EQ(a.origin, b.origin) << u << ", " << v;
          ASSERT_EQ(a.dir, b.dir) << u << ", " << v;
        }
    }
}

// Fills `row` through make(row), after filling it with rays no camera makes,
// and compares each ray with single(i), the one ray of column i.
template <typename Make, typename Single>
void expect_row_of_rays(std::vector<Ray>& row, Make make, Single single, const char* what, int j) {
  std::fill(row.begin(), row.end(), Ray{glm::dvec3(7), glm::dvec3(7), 7, 7});
  make(std::span<Ray>(row));
  for (int i = 0; i < static_cast<int>(row.size()); ++i) {
    const Ray want = single(i);
    const Ray& got = row[static_cast<std::size_t>(i)];
    ASSERT_EQ(got.origin, want.origin) << what << " " << i << ", " << j;
    ASSERT_EQ(got.dir, want.dir) << what << " " << i << ", " << j;
    ASSERT_EQ(got.tmin, want.tmin) << what << " " << i << ", " << j;
    ASSERT_EQ(got.tmax, want.tmax) << what << " " << i << ", " << j;
  }
}

// A row's primary rays made together are primary_ray's, and a row's corner
// rays screen_point_ray's, to the bit, in both projections: on rows wider than
// one block of the vectorized loop (64) and not a whole number of blocks, off
// the screen above and below, and past its right edge (a span longer than the
// row).
TEST(OpenScadCamera, RowsOfPrimaryRaysAreThePixelsRays) {
  for (const Projection projection : {Projection::Perspective, Projection::Orthographic})
    for (const auto& [width, height] : {std::pair{1, 1}, std::pair{64, 3}, std::pair{197, 5}}) {
      const PreparedScene ps = sphere_seen_from({-4.3, 6.1, 2.9}, {0.2, -0.1, 0.3}, 33.7, projection, width, height);
      const Tracer t(ps, {});
      std::vector<Ray> row(static_cast<std::size_t>(width) + 3);
      for (int j = -1; j <= height; ++j) {
        ASSERT_NO_FATAL_FAILURE(expect_row_of_rays(
            row, [&](std::span<Ray> r) { t.primary_rays(j, r); }, [&](int i) { return t.primary_ray(i, j); },
            "centre", j));
        // The row of corners above pixel row j, and at j = height the bottom
        // edge's: screen_point_ray's.
        ASSERT_NO_FATAL_FAILURE(expect_row_of_rays(
            row, [&](std::span<Ray> r) { t.corner_rays(j, r); }, [&](int i) { return t.screen_point_ray(i, j); },
            "corner", j));
      }
    }
}

}  // namespace
