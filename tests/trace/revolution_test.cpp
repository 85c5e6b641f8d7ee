// rotate_extrude read and traced: a revolved square is a tube whose depths are
// its closed form, a revolved circle a torus (its quartic measured against a
// long-double reference), partial turns cut by their wedge, shapes at x < 0
// turned as OpenSCAD turns them, and every refusal at its FILE:LINE:COL.

#include "capsim/scene/parser.h"
#include "capsim/trace/polynomial_roots.h"
#include "capsim/trace/tracer.h"
#include "support/scene_refusal.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

namespace capsim {
namespace {

using testing::refusal;

// The first hit along the ray, +inf on a miss.
double depth(const std::string& text, const glm::dvec3& origin, const glm::dvec3& dir) {
  PrepareOptions options;
  options.width = options.height = 8;
  const PreparedScene ps = prepare_scene(parse_scene(text, "t.csg"), options);
  const Tracer tracer(ps, {});
  Tracer::Scratch s(ps);
  OpCounts ops;
  Hit h;
  return tracer.first_hit(Ray{origin, dir, 0, kInfinity}, s, ops, h) ? h.t : kInfinity;
}

double from_above(const std::string& text, double x, double y) { return depth(text, {x, y, 100}, {0, 0, -1}); }

// The crossings of the scene's only leaf with a line.
std::vector<LineCrossing> crossings(const std::string& text, const glm::dvec3& o, const glm::dvec3& d,
                                    OpCounts& ops) {
  const Scene scene = parse_scene(text, "t.csg");
  EXPECT_EQ(scene.primitives.size(), 1u);
  const PreparedPrimitive p = prepare_primitive(scene.primitives.at(0));
  EXPECT_EQ(p.kind, PrimitiveKind::Revolution);
  std::vector<LineCrossing> out, work;
  leaf_crossings(p, Ray{o, d, 0, kInfinity}, out, work, ops);
  return out;
}

const std::string kTube = "rotate_extrude() translate([10, 0, 0]) square(5);";

TEST(Revolution, ASquareTurnedIsATubeAtItsClosedFormDepths) {
  // Straight down onto the top annulus z = 5, and through the hole.
  EXPECT_EQ(from_above(kTube, 12, 0), 95);
  EXPECT_EQ(from_above(kTube, 0, -14.5), 95);
  EXPECT_EQ(from_above(kTube, 5, 5), kInfinity);
  EXPECT_EQ(from_above(kTube, 11, 11), kInfinity);  // radius 15.56: outside
  // Along x at height 2.5: the outer cylinder, the inner, the inner, the outer.
  OpCounts ops;
  const auto c = crossings(kTube, {-100, 0, 2.5}, {1, 0, 0}, ops);
  ASSERT_EQ(c.size(), 4u);
  const double expected[] = {85, 90, 110, 115};
  for (int i = 0; i < 4; ++i) {
    EXPECT_DOUBLE_EQ(c[static_cast<std::size_t>(i)].t, expected[i]);
    EXPECT_EQ(c[static_cast<std::size_t>(i)].enter, i % 2 == 0);
  }
  EXPECT_EQ(ops.revolution_tests, 1u);
  EXPECT_EQ(ops.revolution_edge_tests, 4u);
  // Off the axis by y = 3: x = -sqrt(15^2 - 9) on the outer cylinder.
  EXPECT_NEAR(depth(kTube, {-100, 3, 2.5}, {1, 0, 0}), 100 - std::sqrt(216.0), 1e-12);
  // Slanted down at 45 degrees from (-27, 0, 17.5): it passes x = -15 at
  // z = 5.5, above the tube, and comes down to z = 5 at x = -14.5, on the
  // top annulus, after 12.5 sqrt(2).
  const glm::dvec3 slant = glm::normalize(glm::dvec3(1, 0, -1));
  EXPECT_NEAR(depth(kTube, {-27, 0, 17.5}, slant), 12.5 * std::sqrt(2.0), 1e-12);
}

TEST(Revolution, TheTubeRendersAsItsOwnExactDepthsNotAMesh) {
  const Scene s = parse_scene(kTube, "t.csg");
  ASSERT_EQ(s.primitives.size(), 1u);
  const Primitive& p = s.primitives[0];
  EXPECT_EQ(p.kind, PrimitiveKind::Revolution);
  // Its box: radius 15 all round, z from 0 to 5.
  EXPECT_EQ(object_bounds(p).lo, glm::dvec3(-15, -15, 0));
  EXPECT_EQ(object_bounds(p).hi, glm::dvec3(15, 15, 5));
}

// The torus (rho - 10)^2 + z^2 = 9 along x at height h, offset y0: rho =
// 10 +- sqrt(9 - h^2), x = +-sqrt(rho^2 - y0^2).
TEST(Revolution, ACircleTurnedIsATorusAtItsClosedFormDepths) {
  const std::string torus = "rotate_extrude($fn = 80) translate([10, 0, 0]) circle(r = 3);";
  for (const double h : {0.0, 1.0, 2.5, -2.9}) {
    for (const double y0 : {0.0, 4.0, 8.5}) {
      const double w = std::sqrt(9 - h * h);
      std::vector<double> xs;
      for (const double rho : {10 - w, 10 + w})
        if (rho > y0) xs.push_back(std::sqrt(rho * rho - y0 * y0));
      std::vector<double> expected;
      if (xs.size() == 2) expected = {-xs[1], -xs[0], xs[0], xs[1]};
      if (xs.size() == 1) expected = {-xs[0], xs[0]};
      OpCounts ops;
      const auto c = crossings(torus, {-50, y0, h}, {1, 0, 0}, ops);
      ASSERT_EQ(c.size(), expected.size()) << h << " " << y0;
      for (std::size_t i = 0; i < c.size(); ++i) EXPECT_NEAR(c[i].t - 50, expected[i], 1e-12) << h << " " << y0;
      EXPECT_EQ(ops.quartic_tests, 1u);
    }
  }
  // Its normal at the outermost point is +x, at the top -z's opposite.
  const Scene s = parse_scene(torus, "t.csg");
  const PreparedPrimitive p = prepare_primitive(s.primitives[0]);
  OpCounts ops;
  const glm::dvec3 n_out = world_normal(p, {13, 0, 0}, 0, ops);
  EXPECT_NEAR(n_out.x, 1, 1e-15);
  const glm::dvec3 n_top = world_normal(p, {0, 10, 3}, 0, ops);
  EXPECT_NEAR(n_top.z, 1, 1e-15);
}

// The torus's crossings against a reference computed in long double: the
// unsquared (rho - R)^2 + z^2 - r^2 bracketed on a fine grid and bisected.
TEST(Revolution, TheTorusQuarticIsAccurateAgainstALongDoubleReference) {
  const double R = 10, r = 3;
  const std::string torus = "rotate_extrude() translate([10, 0, 0]) circle(r = 3);";
  const Scene s = parse_scene(torus, "t.csg");
  const PreparedPrimitive p = prepare_primitive(s.primitives[0]);
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(-1, 1);
  double worst = 0;
  int lines = 0;
  for (int k = 0; k < 400; ++k) {
    const glm::dvec3 o(60 * u(rng), 60 * u(rng), 60 * u(rng));
    const glm::dvec3 target(14 * u(rng), 14 * u(rng), 4 * u(rng));
    const glm::dvec3 d = glm::normalize(target - o);
    auto g = [&](long double t) {
      const long double x = o.x + t * d.x, y = o.y + t * d.y, z = o.z + t * d.z;
      const long double a = std::sqrt(x * x + y * y) - R;
      return a * a + z * z - static_cast<long double>(r) * r;
    };
    std::vector<long double> reference;
    // The whole line that can reach the torus: |t| <= 200 from an origin
    // within 104 of it.
    const int steps = 40000;
    const long double t_end = 200;
    for (int i = -steps / 2; i < steps / 2; ++i) {
      long double lo = 2 * t_end * i / steps, hi = 2 * t_end * (i + 1) / steps;
      if ((g(lo) < 0) == (g(hi) < 0)) continue;
      const bool lo_neg = g(lo) < 0;
      for (int b = 0; b < 80; ++b) {
        const long double mid = (lo + hi) / 2;
        ((g(mid) < 0) == lo_neg ? lo : hi) = mid;
      }
      reference.push_back((lo + hi) / 2);
    }
    std::vector<LineCrossing> out, work;
    OpCounts ops;
    leaf_crossings(p, Ray{o, d, 0, kInfinity}, out, work, ops);
    // Grazing lines whose two crossings the grid cannot tell apart are left out.
    if (out.size() != reference.size()) {
      bool close_pair = false;
      for (std::size_t i = 0; i + 1 < out.size(); ++i) close_pair = close_pair || out[i + 1].t - out[i].t < 0.02;
      EXPECT_TRUE(close_pair) << "line " << k << ": " << out.size() << " crossings, reference " << reference.size();
      continue;
    }
    ++lines;
    for (std::size_t i = 0; i < out.size(); ++i)
      worst = std::max(worst, static_cast<double>(std::abs(static_cast<long double>(out[i].t) - reference[i])));
  }
  std::printf("torus crossings on %d lines: largest error %.3g (torus radius %g)\n", lines, worst, R);
  EXPECT_GT(lines, 100);
  EXPECT_LT(worst, 1e-9 * R);
}

TEST(Revolution, QuarticRootsAreIsolatedAndPolished) {
  // (t - 1)(t - 2)(t - 3)(t - 4) and (t^2 + 1)(t - 5)(t + 5).
  Polynomial a;
  a.degree = 4;
  a.c = {24, -50, 35, -10, 1};
  std::array<double, 4> roots{};
  ASSERT_EQ(real_roots(a, roots), 4);
  // Near a root the expanded form is only known to its rounding error.
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(roots[static_cast<std::size_t>(i)], i + 1, 1e-13);
  Polynomial b;
  b.degree = 4;
  b.c = {-25, 0, -24, 0, 1};
  ASSERT_EQ(real_roots(b, roots), 2);
  EXPECT_DOUBLE_EQ(roots[0], -5);
  EXPECT_DOUBLE_EQ(roots[1], 5);
  Polynomial none;
  none.degree = 4;
  none.c = {1, 0, 0, 0, 1};
  EXPECT_EQ(real_roots(none, roots), 0);
}

TEST(Revolution, APartialTurnIsCutByItsWedgeAndTheCapsAreFaces) {
  const double c45 = 12 / std::sqrt(2.0);
  const std::string quarter = "rotate_extrude(angle = 90) translate([10, 0, 0]) square(5);";
  EXPECT_EQ(from_above(quarter, c45, c45), 95);
  EXPECT_EQ(from_above(quarter, -c45, c45), kInfinity);
  EXPECT_EQ(from_above(quarter, c45, -c45), kInfinity);
  // Along +y at x = 12: in through the cap y = 0, out where radius 15 is reached.
  OpCounts ops;
  auto c = crossings(quarter, {12, -100, 2.5}, {0, 1, 0}, ops);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_DOUBLE_EQ(c[0].t, 100);
  EXPECT_DOUBLE_EQ(c[1].t, 109);
  // The cap's normal faces -y.
  const Scene s = parse_scene(quarter, "t.csg");
  const PreparedPrimitive p = prepare_primitive(s.primitives[0]);
  EXPECT_EQ(world_normal(p, {12, 0, 2.5}, c[0].surface, ops), glm::dvec3(0, -1, 0));
  // Clockwise: the quarter below the x axis, from y = -9 to the cap y = 0.
  c = crossings("rotate_extrude(angle = -90) translate([10, 0, 0]) square(5);", {12, -100, 2.5}, {0, 1, 0}, ops);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_DOUBLE_EQ(c[0].t, 91);
  EXPECT_DOUBLE_EQ(c[1].t, 100);
  // Three quarters, all but the fourth quadrant: along +x at y = -12, in at
  // x = -9, out at the cap x = 0.
  c = crossings("rotate_extrude(angle = 270) translate([10, 0, 0]) square(5);", {-100, -12, 2.5}, {1, 0, 0}, ops);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_DOUBLE_EQ(c[0].t, 91);
  EXPECT_DOUBLE_EQ(c[1].t, 100);
  // Beyond a whole turn is a whole turn: from y = -9 to 9.
  c = crossings("rotate_extrude(angle = 400) translate([10, 0, 0]) square(5);", {12, -100, 2.5}, {0, 1, 0}, ops);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_DOUBLE_EQ(c[0].t, 91);
  EXPECT_DOUBLE_EQ(c[1].t, 109);
  // The half turn's box is the half annulus's.
  const Scene half = parse_scene("rotate_extrude(angle = 180) translate([10, 0, 0]) square(5);", "t.csg");
  EXPECT_EQ(object_bounds(half.primitives[0]).lo, glm::dvec3(-15, 0, 0));
  EXPECT_EQ(object_bounds(half.primitives[0]).hi, glm::dvec3(15, 15, 5));
}

TEST(Revolution, AShapeAtNegativeXTurnsFromTheNegativeXAxis) {
  // OpenSCAD turns a point at x < 0 to angle 180 + a: the quarter from -x to -y.
  const double c45 = 12 / std::sqrt(2.0);
  const std::string mirrored = "rotate_extrude(angle = 90) translate([-15, 0, 0]) square(5);";
  EXPECT_EQ(from_above(mirrored, -c45, -c45), 95);
  EXPECT_EQ(from_above(mirrored, c45, c45), kInfinity);
  EXPECT_EQ(from_above(mirrored, -c45, c45), kInfinity);
  // A whole turn of it is the tube.
  EXPECT_EQ(from_above("rotate_extrude() translate([-15, 0, 0]) square(5);", 12, 0), 95);
}

TEST(Revolution, TheTwoDTreeIsTheSolidsTreeAndOnlyXAtLeastZeroIsTurned) {
  // OpenSCAD's bottle top: a circle met with a square at x >= 0 is a hemisphere.
  const std::string dome = "rotate_extrude() intersection() { square(5); circle(5); }";
  EXPECT_NEAR(from_above(dome, 2, 0), 100 - std::sqrt(21.0), 1e-12);
  EXPECT_NEAR(from_above(dome, 0, -3), 96, 1e-12);
  // A spheroid (an ellipse centred on the axis, as example017's bottle has):
  // z = 2 sqrt(1 - r^2 / 16) over every radius, off any grid line.
  const std::string spheroid = "rotate_extrude() intersection() { square([4, 4]); scale([1, 0.5, 1]) circle(4); }";
  for (const double r : {0.0, 0.7, 2.0, 3.3, 3.9}) {
    const double x = r * 0.6, y = r * 0.8;
    EXPECT_NEAR(from_above(spheroid, x, y), 100 - 2 * std::sqrt(1 - r * r / 16), 1e-12) << r;
  }
  // A tube less a torus in its wall, and a polygon that touches the axis.
  const std::string grooved = "rotate_extrude() difference() { translate([10, 0, 0]) square(5); "
                              "translate([12.5, 5, 0]) circle(1); }";
  EXPECT_NEAR(from_above(grooved, 12.5, 0), 96, 1e-12);
  EXPECT_EQ(from_above(grooved, 14, 0), 95);
  const std::string cone = "rotate_extrude() polygon([[0, 0], [4, 0], [0, 8]]);";
  EXPECT_NEAR(from_above(cone, 2, 0), 96, 1e-12);
  EXPECT_NEAR(from_above(cone, 0, 1), 94, 1e-12);
  // Exactly down the axis, where the profile's edges end on it: the top disc
  // of a solid cylinder, the apex of the cone, and nothing through the
  // hourglass hollow but the point where its two cones meet.
  EXPECT_EQ(from_above("rotate_extrude() square(4);", 0, 0), 96);
  EXPECT_EQ(from_above(cone, 0, 0), 92);
  OpCounts ops;
  const auto c = crossings("rotate_extrude() polygon([[4, 10], [0, 5], [4, 0]]);", {0, 0, 100}, {0, 0, -1}, ops);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].t, 95);
  EXPECT_EQ(c[1].t, 95);
}

TEST(Revolution, TextIsTurnedAsItsGlyphsOutlines) {
  const Scene s = parse_scene("rotate_extrude() translate([5, 0, 0]) text(\"o\");", "t.csg");
  ASSERT_EQ(s.primitives.size(), 1u);
  EXPECT_EQ(s.primitives[0].kind, PrimitiveKind::Revolution);
  EXPECT_GT(s.primitives[0].revolution->edges.size(), 8u);
}

TEST(Revolution, BadInputIsRefusedAtItsPlace) {
  EXPECT_EQ(refusal("rotate_extrude()\n translate([-2, 0, 0]) square(5);"),
            "t.csg:1:1: all points for rotate_extrude() must have the same X coordinate sign (the 2-D shape reaches "
            "x = -2 to 3)");
  EXPECT_EQ(refusal("rotate_extrude() translate([2, 0, 0]) circle(3);"),
            "t.csg:1:1: all points for rotate_extrude() must have the same X coordinate sign (the 2-D shape reaches "
            "x = -1 to 5)");
  EXPECT_NE(refusal("rotate_extrude() polygon([[1, 0], [2, 0], [3, 0]]);")
                .find("t.csg:1:26: polygon outline crosses itself or encloses no area"),
            std::string::npos);
  // A polygon that crosses itself is clipped under the even-odd rule (scene/regions/region_2d.h) and revolved.
  EXPECT_EQ(refusal("rotate_extrude() polygon([[1, 0], [3, 2], [3, 0], [1, 2]]);"), "parsed without error");
  EXPECT_EQ(refusal("rotate_extrude(angle = 0) square(1);"),
            "t.csg:1:24: an angle of 0 turns the shape into no solid");
  EXPECT_NE(refusal("rotate_extrude(file = \"a.dxf\") square(1);").find("t.csg:1:23: rotate_extrude's 'file' is not"),
            std::string::npos);
  EXPECT_NE(refusal("rotate_extrude() square(0);").find("t.csg:1:25: square size must be positive"), std::string::npos);
  EXPECT_NE(refusal("rotate_extrude() cube(1);").find("t.csg:1:18: cube() is not a 2-D shape"), std::string::npos);
  EXPECT_EQ(refusal("rotate_extrude() !square(1);"),
            "t.csg:1:18: the '!' (root) modifier is not supported inside rotate_extrude()");
  EXPECT_EQ(refusal("rotate_extrude() import(\"a.dxf\");"),
            "t.csg:1:25: cannot import 'a.dxf': there is no such file beside the scene file (a.dxf) nor in the "
            "current directory");
  // A shape left out with '%' is read and checked, and decides no side.
  EXPECT_EQ(refusal("rotate_extrude() { square(1); %translate([-5, 0, 0]) square(1); }"), "parsed without error");
  EXPECT_NE(refusal("rotate_extrude() { square(1); %square(-1); }").find("t.csg:1:39: square size must be positive"),
            std::string::npos);
  // A circle that touches the axis is allowed (a horn torus).
  EXPECT_EQ(refusal("rotate_extrude() translate([5, 0, 0]) circle(5);"), "parsed without error");
}

// linear_extrude of the shadow of a torus under projection() (OpenSCAD's
// polyhedron of it, tests/scene/projection_revolve_test.cpp): a slab over the
// annulus between OpenSCAD's 30-gons of radius 7 and 13.
TEST(Revolution, AnExtrudedShadowOfOneTraces) {
  const std::string text =
      "linear_extrude(height = 2) projection() rotate_extrude($fn = 0, $fa = 12, $fs = 2) "
      "translate([10, 0, 0]) circle(r = 3, $fn = 0, $fa = 12, $fs = 2);";
  EXPECT_NEAR(from_above(text, 10, 0), 98, 1e-9);  // the top of the slab
  EXPECT_NEAR(from_above(text, 0, -10), 98, 1e-9);
  EXPECT_EQ(from_above(text, 5, 0), kInfinity);     // the hole
  EXPECT_EQ(from_above(text, 12.9, 3), kInfinity);  // beyond the 30-gon's side, inside the circle
  // Along the x axis: the 30-gon's corner at (13, 0), then from the centre its inner one at (7, 0).
  EXPECT_NEAR(depth(text, {100, 0, 1}, {-1, 0, 0}), 87, 1e-4);
  EXPECT_NEAR(depth(text, {0, 0, 1}, {1, 0, 0}), 7, 1e-4);
}

}  // namespace
}  // namespace capsim
