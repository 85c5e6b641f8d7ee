// Unit tests of the tracer's parts: exact intersections, the 3DDDA, the status
// tree, voxel generation and the operation counts of whole rays.

#include "capsim/scene/parser.h"
#include "capsim/trace/dda.h"
#include "capsim/trace/render.h"
#include "capsim/trace/status_tree.h"
#include "capsim/trace/tracer.h"
#include "support/scene_builders.h"

#include <gtest/gtest.h>

#include <atomic>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <random>
#include <span>
#include <string>

using namespace capsim;
using namespace capsim::testing;

namespace {

Ray ray(glm::dvec3 o, glm::dvec3 d) { return Ray{o, d, 0.0, kInfinity}; }

}  // namespace

TEST(PrimitiveGeometry, SphereSpanIsExact) {
  const PreparedPrimitive p = prepare_primitive(sphere({1, 2, 3}, 2));
  LineSpan s;
  OpCounts ops;
  ASSERT_TRUE(intersect_line(p, ray({1, 2, -10}, {0, 0, 1}), s, ops));
  EXPECT_DOUBLE_EQ(s.t_enter, 11);
  EXPECT_DOUBLE_EQ(s.t_exit, 15);
  EXPECT_EQ(ops.sphere_tests, 1u);
  EXPECT_FALSE(intersect_line(p, ray({3.5, 2, -10}, {0, 0, 1}), s, ops));
  EXPECT_EQ(ops.sphere_tests, 2u);
}

// The walk tests a round sphere from its packed slot: the same span, to
// the bit, as intersect_line's test of the primitive, on random spheres
// (near and far, tiny and huge) and rays; a sphere that is not round in
// world space has no slot.
TEST(PrimitiveGeometry, RoundSphereSlotsTestAsThePrimitive) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> unit(-1, 1), scale(-12, 12);
  for (int k = 0; k < 20000; ++k) {
    const glm::dvec3 centre = glm::dvec3(unit(rng), unit(rng), unit(rng)) * std::pow(10.0, scale(rng) / 3);
    const PreparedPrimitive p = prepare_primitive(sphere(centre, std::pow(10.0, scale(rng) / 4)));
    const RoundSphereSlot slot = round_sphere_slot(p);
    ASSERT_GE(slot.r2, 0);
    const glm::dvec3 origin = centre + glm::dvec3(unit(rng), unit(rng), unit(rng)) * std::pow(10.0, scale(rng) / 3);
    const glm::dvec3 aim = centre + glm::dvec3(unit(rng), unit(rng), unit(rng)) * std::pow(10.0, scale(rng) / 4);
    if (aim == origin) continue;
    const Ray r = ray(origin, glm::normalize(aim - origin));
    LineSpan by_primitive, by_slot;
    OpCounts ops;
    const bool met = intersect_line(p, r, by_primitive, ops);
    EXPECT_EQ(intersect_round_sphere(r.origin - slot.center, r.dir, slot.r2, by_slot), met) << k;
    if (!met) continue;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(by_slot.t_enter), std::bit_cast<std::uint64_t>(by_primitive.t_enter)) << k;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(by_slot.t_exit), std::bit_cast<std::uint64_t>(by_primitive.t_exit)) << k;
  }
  Primitive squashed = sphere({0, 0, 0}, 1);
  squashed.to_world[2][2] = 2;
  EXPECT_LT(round_sphere_slot(prepare_primitive(squashed)).r2, 0);
  EXPECT_LT(round_sphere_slot(prepare_primitive(box({0, 0, 0}, {1, 1, 1}))).r2, 0);
}

TEST(PrimitiveGeometry, BoxSpanNamesTheFaces) {
  const PreparedPrimitive p = prepare_primitive(box({0, 0, 0}, {2, 4, 6}));
  LineSpan s;
  OpCounts ops;
  ASSERT_TRUE(intersect_line(p, ray({-1, 1, 1}, {1, 0, 0}), s, ops));
  EXPECT_DOUBLE_EQ(s.t_enter, 1);
  EXPECT_DOUBLE_EQ(s.t_exit, 3);
  EXPECT_EQ(s.enter_surface, 0);  // -x
  EXPECT_EQ(s.exit_surface, 1);   // +x
  // Axis-parallel ray outside the slab of a zero direction component.
  EXPECT_FALSE(intersect_line(p, ray({-1, 5, 1}, {1, 0, 0}), s, ops));
  EXPECT_EQ(ops.box_tests, 2u);
  const glm::dvec3 n = world_normal(p, {2, 1, 1}, 1, ops);
  EXPECT_EQ(n, glm::dvec3(1, 0, 0));
}

TEST(PrimitiveGeometry, ConeSideAndCaps) {
  // Frustum of height 2 from radius 2 at z=0 to radius 1 at z=2.
  const PreparedPrimitive p = prepare_primitive(cone({0, 0, 0}, 2, 2, 1));
  LineSpan s;
  OpCounts ops;
  // Along the x axis at z = 1: radius 1.5.
  ASSERT_TRUE(intersect_line(p, ray({-5, 0, 1}, {1, 0, 0}), s, ops));
  EXPECT_NEAR(s.t_enter, 3.5, 1e-12);
  EXPECT_NEAR(s.t_exit, 6.5, 1e-12);
  EXPECT_EQ(s.enter_surface, 0);
  // Down the axis: through both caps.
  ASSERT_TRUE(intersect_line(p, ray({0, 0, 5}, {0, 0, -1}), s, ops));
  EXPECT_DOUBLE_EQ(s.t_enter, 3);
  EXPECT_DOUBLE_EQ(s.t_exit, 5);
  EXPECT_EQ(s.enter_surface, 2);
  EXPECT_EQ(s.exit_surface, 1);
  EXPECT_EQ(ops.cone_tests, 2u);
  // A pointed cone seen from beside its apex misses above it.
  const PreparedPrimitive pointed = prepare_primitive(cone({0, 0, 0}, 1, 1, 0));
  EXPECT_FALSE(intersect_line(pointed, ray({-5, 0, 1.01}, {1, 0, 0}), s, ops));
  ASSERT_TRUE(intersect_line(pointed, ray({-5, 0, 0.5}, {1, 0, 0}), s, ops));
  EXPECT_NEAR(s.t_enter, 4.5, 1e-12);
  // A cylinder along its own axis (A = 0, B = 0).
  const PreparedPrimitive cyl = prepare_primitive(cone({0, 0, 0}, 3, 1, 1));
  ASSERT_TRUE(intersect_line(cyl, ray({0.5, 0, -1}, {0, 0, 1}), s, ops));
  EXPECT_DOUBLE_EQ(s.t_enter, 1);
  EXPECT_DOUBLE_EQ(s.t_exit, 4);
  EXPECT_FALSE(intersect_line(cyl, ray({1.5, 0, -1}, {0, 0, 1}), s, ops));
}

TEST(Dda3, AxisParallelRayVisitsARowOfVoxels) {
  const VoxelGrid g = unit_voxel_grid(4);
  Dda3 dda;
  ASSERT_TRUE(dda.setup(g, ray({-1, 1.5, 2.5}, {1, 0, 0})));
  std::vector<int> xs = {dda.vx()};
  EXPECT_DOUBLE_EQ(dda.t_in(), 1);
  EXPECT_DOUBLE_EQ(dda.t_out(), 2);
  while (dda.step()) {
    xs.push_back(dda.vx());
    EXPECT_EQ(dda.vy(), 1);  // a zero direction component never changes its index
    EXPECT_EQ(dda.vz(), 2);
  }
  EXPECT_EQ(xs, (std::vector<int>{0, 1, 2, 3}));
}

TEST(Dda3, DiagonalRayStepsOneAxisAtATime) {
  const VoxelGrid g = unit_voxel_grid(8);
  Dda3 dda;
  ASSERT_TRUE(dda.setup(g, ray({0.5, 0.25, 0.1}, glm::normalize(glm::dvec3(1, 0.7, 0.3)))));
  int steps = 0;
  int prev = dda.vx() + dda.vy() + dda.vz();
  double t_prev = dda.t_in();
  while (dda.step()) {
    ++steps;
    EXPECT_EQ(dda.vx() + dda.vy() + dda.vz(), prev + 1);
    prev = dda.vx() + dda.vy() + dda.vz();
    EXPECT_GE(dda.t_in(), t_prev);
    t_prev = dda.t_in();
  }
  EXPECT_EQ(dda.vx(), 7);
  EXPECT_GT(steps, 7);
  EXPECT_FALSE(dda.setup(g, ray({-1, -1, -1}, {-1, 0, 0})));
}

// The voxel index of any double, NaN and infinities included, is a voxel of
// the grid; converting such values to int directly is undefined.
TEST(Dda3, VoxelIndexIsDefinedForEveryDouble) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(clamped_voxel_index(nan, 8), 0);
  EXPECT_EQ(clamped_voxel_index(-nan, 8), 0);
  EXPECT_EQ(clamped_voxel_index(-kInfinity, 8), 0);
  EXPECT_EQ(clamped_voxel_index(kInfinity, 8), 7);
  EXPECT_EQ(clamped_voxel_index(1e300, 8), 7);
  EXPECT_EQ(clamped_voxel_index(-1e300, 8), 0);
  EXPECT_EQ(clamped_voxel_index(-0.5, 8), 0);
  EXPECT_EQ(clamped_voxel_index(0, 8), 0);
  EXPECT_EQ(clamped_voxel_index(3.999, 8), 3);
  EXPECT_EQ(clamped_voxel_index(7.999, 8), 7);
  EXPECT_EQ(clamped_voxel_index(8, 8), 7);
}

// A direction component below the least normal double (its reciprocal
// overflows) is walked as zero. It made the next plane crossing 0 * inf =
// NaN for a ray starting on a voxel plane, and then no crossing was ever
// inside the voxel: the ray missed what it hit.
TEST(Dda3, SubnormalDirectionComponentIsWalkedAsZero) {
  const VoxelGrid g = unit_voxel_grid(4);
  Dda3 dda;
  ASSERT_TRUE(dda.setup(g, ray({3, -1, 2.5}, {-1e-310, 1, 0})));
  EXPECT_DOUBLE_EQ(dda.t_in(), 1);
  EXPECT_DOUBLE_EQ(dda.t_out(), 2);
  std::vector<int> ys = {dda.vy()};
  while (dda.step()) {
    ys.push_back(dda.vy());
    EXPECT_EQ(dda.vx(), 3);
    EXPECT_EQ(dda.vz(), 2);
  }
  EXPECT_EQ(ys, (std::vector<int>{0, 1, 2, 3}));
}

TEST(StatusTree, DifferenceStopsEarlyWhenStatusDoesNotChange) {
  // (A - B): entering B while outside A changes nothing above B's parent.
  const CsgNode root = op(CsgOp::Union, {op(CsgOp::Difference, {leaf(0), leaf(1)})});
  StatusTree t(root, 2);
  OpCounts ops;
  EXPECT_FALSE(t.toggle(1, ops));  // into B: A - B stays outside
  EXPECT_EQ(ops.tree_visits, 2u);  // leaf + the difference node, then the early stop
  EXPECT_FALSE(t.toggle(0, ops));  // into A while in B: still outside
  EXPECT_TRUE(t.toggle(1, ops));   // out of B while in A: now inside
  EXPECT_TRUE(t.root_inside());
  t.reset();
  EXPECT_FALSE(t.root_inside());
  EXPECT_FALSE(t.leaf_inside(0));
  EXPECT_TRUE(t.toggle(0, ops));
}

TEST(StatusTree, EmptySetsAreSimplifiedAway) {
  // intersection(A, group()) is empty; union with C leaves only C.
  const CsgNode root = op(CsgOp::Union, {op(CsgOp::Intersection, {leaf(0), op(CsgOp::Union, {})}),
                                         op(CsgOp::Difference, {op(CsgOp::Union, {}), leaf(1)}), leaf(2)});
  StatusTree t(root, 3);
  EXPECT_FALSE(t.present(0));
  EXPECT_FALSE(t.present(1));
  EXPECT_TRUE(t.present(2));
  EXPECT_TRUE(t.nodes().empty());  // C alone is the whole tree
  OpCounts ops;
  EXPECT_TRUE(t.toggle(2, ops));
  EXPECT_EQ(ops.tree_visits, 1u);
  EXPECT_TRUE(StatusTree(op(CsgOp::Union, {op(CsgOp::Union, {})}), 0).empty());
}

TEST(Tracer, OperationCountsOfOneRayThroughOneSphere) {
  PrepareOptions o;
  o.grid = 1;
  const PreparedScene ps = prepare_scene(make_scene({sphere({0, 0, 0}, 1)}), o);
  const Tracer tracer(ps, {});
  Tracer::Scratch s(ps);
  OpCounts ops;
  Hit h;
  ASSERT_TRUE(tracer.first_hit(ray({0, 0, -5}, {0, 0, 1}), s, ops, h));
  EXPECT_DOUBLE_EQ(h.t, 4);
  EXPECT_EQ(h.primitive, 0u);
  EXPECT_TRUE(h.entering);
  EXPECT_EQ(h.normal, glm::dvec3(0, 0, -1));
  OpCounts want;
  want.sphere_tests = 1;
  want.dda_setups = 1;
  want.voxel_passes = 1;  // the one voxel holds the sphere
  want.hits_sorted = 2;  // entry and exit
  want.tree_visits = 1;  // the leaf is the root
  want.matvec = 2;       // the normal: point to object space, normal to world
  EXPECT_EQ(ops, want);
}

TEST(Tracer, PartialEvaluationStopsInTheFirstVisibleVoxel) {
  // Two spheres one behind the other along x; 4 divisions. The far sphere's
  // voxels are never reached.
  PrepareOptions o;
  o.grid = 4;
  const PreparedScene ps = prepare_scene(make_scene({sphere({1, 0, 0}, 0.9), sphere({7, 0, 0}, 0.9)}), o);
  const Tracer tracer(ps, {});
  Tracer::Scratch s(ps);
  OpCounts ops;
  Hit h;
  ASSERT_TRUE(tracer.first_hit(ray({-3, 0, 0}, {1, 0, 0}), s, ops, h));
  EXPECT_EQ(h.primitive, 0u);
  EXPECT_NEAR(h.t, 3.1, 1e-12);
  EXPECT_EQ(ops.sphere_tests, 1u);
  EXPECT_EQ(ops.dda_steps, 0u);
  EXPECT_EQ(ops.voxel_passes, 1u);
}

// Partial evaluation passes through every voxel the ray visits that holds
// primitives (Algorithm-4 applied in that voxel), and through no empty one.
TEST(Tracer, EveryVisitedVoxelThatHoldsPrimitivesIsOnePass) {
  PrepareOptions o;
  o.grid = 6;
  const PreparedScene ps = prepare_scene(
      make_scene({sphere({1, 0, 0}, 0.9), sphere({7, 0, 0}, 0.9), box({3, -1, -1}, {0.5, 2, 2})}), o);
  const Tracer tracer(ps, {});
  Tracer::Scratch s(ps);
  int rays_with_passes = 0, rays_with_empty_voxels = 0;
  for (double y : {-0.95, -0.6, -0.2, 0.3, 0.7, 0.95})
    for (double z : {-0.95, -0.1, 0.5, 0.95}) {
      const Ray r = ray({-1, y, z}, {1, 0.01, 0.02});
      OpCounts ops;
      Hit h;
      const bool hit = tracer.first_hit(r, s, ops, h);
      // The voxels it visited, by the same 3DDDA, up to the hit's voxel.
      Dda3 dda;
      ASSERT_TRUE(dda.setup(ps.grid, r));
      std::uint64_t visited = 1, nonempty = 0;
      for (;;) {
        if (!ps.grid.voxel(dda.voxel()).empty()) ++nonempty;
        if (hit && dda.t_out() >= h.t) break;
        if (!dda.step()) break;
        ++visited;
      }
      EXPECT_EQ(ops.dda_setups + ops.dda_steps, visited) << y << " " << z;
      EXPECT_EQ(ops.voxel_passes, nonempty) << y << " " << z;
      rays_with_passes += ops.voxel_passes > 1;
      rays_with_empty_voxels += ops.voxel_passes < visited;  // stepped through, no pass
    }
  EXPECT_GT(rays_with_passes, 0);
  EXPECT_GT(rays_with_empty_voxels, 0);
}

TEST(Tracer, RayFromInsideFindsTheExit) {
  // Inside A - B, where B is a ball inside A: the ray from A's inside leaves
  // the solid where it enters B.
  const Scene sc = make_scene({box({-2, -2, -2}, {4, 4, 4}), sphere({1, 0, 0}, 0.5)},
                              op(CsgOp::Difference, {leaf(0), leaf(1)}));
  for (int n : {1, 3, 7}) {
    PrepareOptions o;
    o.grid = n;
    const PreparedScene ps = prepare_scene(sc, o);
    const Tracer tracer(ps, {});
    Tracer::Scratch s(ps);
    OpCounts ops;
    Hit h;
    ASSERT_TRUE(tracer.first_hit(ray({-1, 0, 0}, {1, 0, 0}), s, ops, h));
    EXPECT_EQ(h.primitive, 1u);
    EXPECT_NEAR(h.t, 1.5, 1e-12);
    EXPECT_FALSE(h.entering);
    // The solid's outward normal on the cavity wall points into the cavity.
    EXPECT_NEAR(h.normal.x, 1.0, 1e-12);
  }
}

TEST(Tracer, SubtractedSurfaceNormalFacesOut) {
  // A cube with a ball bitten out of its -x face, seen from -x through the bite.
  const Scene sc = make_scene({box({0, -1, -1}, {2, 2, 2}), sphere({0, 0, 0}, 0.5)},
                              op(CsgOp::Difference, {leaf(0), leaf(1)}));
  const PreparedScene ps = prepare_scene(sc, {});
  const Tracer tracer(ps, {});
  Tracer::Scratch s(ps);
  OpCounts ops;
  Hit h;
  ASSERT_TRUE(tracer.first_hit(ray({-5, 0, 0}, {1, 0, 0}), s, ops, h));
  EXPECT_EQ(h.primitive, 1u);
  EXPECT_NEAR(h.t, 5.5, 1e-12);
  EXPECT_TRUE(h.entering);
  EXPECT_NEAR(h.normal.x, -1.0, 1e-12);
}

TEST(VoxelGeneration, IsConservativeAndTighterThanBoundingBoxes) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-4, 4), r(0.2, 1.5), ang(0, 6.283185307179586);
  std::vector<Primitive> prims;
  for (int i = 0; i < 30; ++i) {
    Primitive p = i % 3 == 0 ? sphere({u(rng), u(rng), u(rng)}, r(rng))
                  : i % 3 == 1 ? box({u(rng), u(rng), u(rng)}, {r(rng), r(rng), r(rng)})
                               : cone({u(rng), u(rng), u(rng)}, r(rng), r(rng), i % 2 ? 0.0 : r(rng));
    p.to_world = glm::rotate(glm::dmat4(1.0), ang(rng), glm::normalize(glm::dvec3(u(rng), u(rng), 1))) *
                 glm::scale(glm::dmat4(1.0), glm::dvec3(1, 0.5 + r(rng), 1)) * p.to_world;
    prims.push_back(p);
  }
  const Scene sc = make_scene(prims);
  for (int n : {1, 5, 16}) {
    PrepareOptions o;
    o.grid = n;
    const PreparedScene ps = prepare_scene(sc, o);
    const VoxelGrid aabb = generate_voxels_aabb(ps.prims, ps.placed, ps.grid.universe, n);
    EXPECT_LE(ps.grid.entries(), aabb.entries());
    if (n == 16) {
      EXPECT_LT(ps.grid.entries(), aabb.entries());
    }
    // Points on every primitive's surface lie in voxels that list it.
    const Tracer tracer(ps, {});
    for (std::size_t p = 0; p < ps.prims.size(); ++p) {
      for (int k = 0; k < 200; ++k) {
        const glm::dvec3 c = ps.prims[p].world_bounds.center();
        const glm::dvec3 d = glm::normalize(glm::dvec3(u(rng), u(rng), u(rng)));
        LineSpan span;
        OpCounts ops;
        if (!intersect_line(ps.prims[p], ray(c, d), span, ops)) continue;
        for (double t : {span.t_enter, span.t_exit}) {
          const glm::dvec3 q = c + t * d;
          const glm::ivec3 v = glm::clamp(glm::ivec3(glm::floor((q - ps.grid.universe.lo) / ps.grid.voxel_size)),
                                          glm::ivec3(0), glm::ivec3(n - 1));
          const auto list = ps.grid.voxel(ps.grid.index(v.x, v.y, v.z));
          EXPECT_TRUE(std::find(list.begin(), list.end(), p) != list.end())
              << "primitive " << p << " missing from voxel " << v.x << "," << v.y << "," << v.z;
        }
      }
    }
  }
}

// Many copies of one shape: at auto_grid_divisions' 25 divisions each of 2000
// coincident spheres would fill the whole grid (31 million entries, growing
// as the square of the copies); the automatic grid takes fewer divisions and
// keeps to 512 entries per primitive.
TEST(VoxelGeneration, CoincidentPrimitivesKeepTheAutomaticGridSmall) {
  const Scene sc = make_scene(std::vector<Primitive>(2000, sphere({0, 0, 0}, 1)));
  PrepareOptions o;
  o.width = o.height = 8;
  const PreparedScene ps = prepare_scene(sc, o);
  EXPECT_EQ(auto_grid_divisions(2000), 25);
  EXPECT_EQ(ps.grid.n, 8);
  EXPECT_LE(ps.grid.entries(), kAutoVoxelEntriesPerPrimitive * 2000);
  EXPECT_LE(bounding_box_entries(ps.prims, ps.placed, ps.grid.universe, 8), kAutoVoxelEntriesPerPrimitive * 2000);
  EXPECT_GT(bounding_box_entries(ps.prims, ps.placed, ps.grid.universe, 9), kAutoVoxelEntriesPerPrimitive * 2000);
  // Their crossings, all at one t, still give the first sphere's surface.
  const Tracer tracer(ps, {});
  Tracer::Scratch scratch(ps);
  OpCounts ops;
  Hit hit;
  ASSERT_TRUE(tracer.first_hit(ray({0, -5, 0.25}, {0, 1, 0}), scratch, ops, hit));
  EXPECT_EQ(hit.primitive, 0u);
  EXPECT_DOUBLE_EQ(hit.t, 5 - std::sqrt(1 - 0.25 * 0.25));
  EXPECT_EQ(ops.sphere_tests, 2000u);
  EXPECT_EQ(ops.hits_sorted, 4000u);
}

// Where primitives overlap little the automatic grid is auto_grid_divisions'.
TEST(VoxelGeneration, SeparatePrimitivesKeepTheAutomaticDivisions) {
  std::vector<Primitive> prims;
  for (int x = 0; x < 10; ++x)
    for (int y = 0; y < 10; ++y)
      for (int z = 0; z < 10; ++z) prims.push_back(sphere({2.0 * x, 2.0 * y, 2.0 * z}, 0.8));
  PrepareOptions o;
  o.width = o.height = 8;
  const PreparedScene ps = prepare_scene(make_scene(prims), o);
  EXPECT_EQ(ps.grid.n, auto_grid_divisions(1000));
  EXPECT_EQ(ps.grid.n, 20);
  EXPECT_EQ(ps.grid.entries(), 8000u);
}

// A grid chosen with --grid that would pass kMaxVoxelEntries is refused with
// the reason, not built: three boxes filling a 256^3 grid need 50 million.
TEST(VoxelGeneration, ExplicitGridPastTheEntryLimitIsRefused) {
  EXPECT_EQ(kMaxVoxelEntries, 33554432u);
  const Scene sc = make_scene({box({0, 0, 0}, {1, 1, 1}), box({0, 0, 0}, {1, 1, 1}), box({0, 0, 0}, {1, 1, 1})});
  PrepareOptions o;
  o.width = o.height = 8;
  o.grid = 256;
  try {
    prepare_scene(sc, o);
    FAIL() << "prepared";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "--grid 256: a voxel grid of 256x256x256 would hold more than 33554432 (voxel, "
                 "primitive) entries, the most capsim allows; use fewer divisions, or --grid auto, "
                 "which keeps within it");
  }
  o.grid = 128;  // 3 x 128^3 = 6.3 million
  EXPECT_EQ(prepare_scene(sc, o).grid.entries(), 3u * 128 * 128 * 128);
}

TEST(Tracer, GridSizeDoesNotChangeTheImage) {
  std::vector<Primitive> prims;
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 3; ++y) prims.push_back(sphere({x * 2.0, y * 2.0, 0}, 0.9));
  prims.push_back(box({-1, -1, -1.5}, {6, 6, 0.5}));
  prims.back().material.reflect = 0.5;
  prims[4].material.transmit = 0.6;
  const Scene sc = make_scene(prims);
  std::vector<PixelSample> reference;
  for (int n : {1, 2, 5, 13}) {
    PrepareOptions o;
    o.grid = n;
    o.width = 48;
    o.height = 32;
    const PreparedScene ps = prepare_scene(sc, o);
    const Tracer tracer(ps, {});
    Tracer::Scratch s(ps);
    std::vector<PixelSample> img;
    for (int j = 0; j < 32; ++j)
      for (int i = 0; i < 48; ++i) {
        OpCounts ops;
        img.push_back(tracer.trace_pixel(i, j, s, ops));
      }
    if (reference.empty()) {
      reference = img;
      continue;
    }
    for (std::size_t k = 0; k < img.size(); ++k) {
      ASSERT_EQ(img[k].primitive, reference[k].primitive) << "grid " << n << " pixel " << k;
      ASSERT_EQ(img[k].color, reference[k].color) << "grid " << n << " pixel " << k;
      ASSERT_EQ(img[k].depth, reference[k].depth) << "grid " << n << " pixel " << k;
    }
  }
}

TEST(Render, RowsComeOnceEachAndMatchTheFramebuffer) {
  std::vector<Primitive> prims;
  for (int x = 0; x < 3; ++x) prims.push_back(sphere({x * 2.0, 0, 0}, 0.9));
  prims[1].material.reflect = 0.5;
  PrepareOptions o;
  o.width = 40;
  o.height = 30;
  const PreparedScene ps = prepare_scene(make_scene(prims), o);
  const Tracer tracer(ps, {});
  RenderStats fb_stats, row_stats;
  const Framebuffer fb = render(tracer, 1, &fb_stats);
  std::vector<std::vector<PixelSample>> rows(o.height);
  std::vector<std::atomic<int>> calls(o.height);
  render_rows(
      tracer, 2,
      [&](int j, std::span<const PixelSample> row) {
        ++calls[j];
        rows[j].assign(row.begin(), row.end());
      },
      &row_stats);
  EXPECT_EQ(row_stats.ops, fb_stats.ops);
  EXPECT_GT(row_stats.ops.secondary_rays, 0u);
  for (int j = 0; j < o.height; ++j) {
    ASSERT_EQ(calls[j], 1) << "row " << j;
    ASSERT_EQ(rows[j].size(), static_cast<std::size_t>(o.width));
    for (int i = 0; i < o.width; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * o.width + i;
      EXPECT_EQ(static_cast<float>(rows[j][i].color.x), fb.rgba[4 * k]);
      EXPECT_EQ(static_cast<float>(rows[j][i].color.z), fb.rgba[4 * k + 2]);
      EXPECT_EQ(rows[j][i].alpha, fb.rgba[4 * k + 3]);
      EXPECT_EQ(static_cast<float>(rows[j][i].depth), fb.depth[k]);
      EXPECT_EQ(static_cast<float>(rows[j][i].primitive), fb.id[k]);
    }
  }
}

// The host's Algorithm-3 counts of a prepared scene: one placement per
// primitive, the grid's entries as built, and every voxel of the N^3 grid.
TEST(VoxelGeneration, CountsThePrimitivesTheEntriesAndTheGridsVoxels) {
  for (int n : {1, 3, 8}) {
    PrepareOptions o;
    o.grid = n;
    const PreparedScene ps =
        prepare_scene(make_scene({sphere({1, 0, 0}, 0.9), sphere({7, 0, 0}, 0.9), box({3, -1, -1}, {0.5, 2, 2})}), o);
    EXPECT_EQ(ps.voxel_counts.primitives, 3u) << n;
    EXPECT_EQ(ps.voxel_counts.voxel_entries, ps.grid.entries()) << n;
    EXPECT_EQ(ps.voxel_counts.grid_voxels, static_cast<std::uint64_t>(n * n * n)) << n;
  }
}

// A shadow ray asks only whether it is blocked: any_hit skips the hit's point
// and normal but counts them as first_hit does, so the simulated machine's
// cycles do not depend on which one a ray used. Random rays through a scene
// of every kind of primitive (a round sphere, a stretched one, a box, a
// cylinder, a cone, a mesh and a revolution), in and out of its CSG operators.
TEST(Tracer, AnyHitAnswersAndCountsAsFirstHit) {
  for (const int grid : {1, 4, 9}) {
    PrepareOptions o;
    o.grid = grid;
    const PreparedScene ps = prepare_scene(parse_scene(kEveryKindDifference, "kinds.csg"), o);
    const Tracer tracer(ps, {});
    Tracer::Scratch first_scratch(ps), any_scratch(ps);
    std::mt19937_64 rng(grid);
    std::uniform_real_distribution<double> u(-6, 6);
    int hits = 0;
    for (int k = 0; k < 4000; ++k) {
      const glm::dvec3 from(u(rng), u(rng), u(rng)), to(u(rng), u(rng), u(rng));
      if (from == to) continue;
      const Ray r{from, glm::normalize(to - from), 1e-9, k % 2 ? glm::length(to - from) : kInfinity};
      OpCounts first_ops, any_ops;
      Hit h;
      const bool met = tracer.first_hit(r, first_scratch, first_ops, h);
      ASSERT_EQ(tracer.any_hit(r, any_scratch, any_ops), met) << grid << " " << k;
      ASSERT_EQ(any_ops, first_ops) << grid << " " << k;
      hits += met;
    }
    EXPECT_GT(hits, 1000) << grid;
  }
}

// The machine's cost of a hit's normal, in matrix-vector products: into the
// primitive's space where the normal is worked out there (a sphere, round or
// not, a cone's side, a revolution), and out with the normal matrix (every
// kind). world_normal counts what world_normal_matvecs says, which any_hit
// counts for the normals it never works out.
TEST(PrimitiveGeometry, NormalMatvecCountsOfEveryKind) {
  const std::string text =
      "sphere(r = 1);\n"
      "scale([1, 2, 1]) sphere(r = 1);\n"
      "cube(1);\n"
      "cylinder(h = 2, r1 = 1, r2 = 0.5);\n"
      "cylinder(h = 2, r1 = 1, r2 = 0);\n"
      "polyhedron(points = [[0,0,0],[2,0,0],[0,2,0],[0,0,2]], faces = [[0,2,1],[0,1,3],[0,3,2],[1,2,3]]);\n"
      "rotate_extrude() translate([2, 0, 0]) square(1);\n";
  // Surfaces 0 to 3 of each: a cone's 1 and 2 are its caps, flat in its space.
  const std::uint64_t expected[7][4] = {{2, 2, 2, 2}, {2, 2, 2, 2}, {1, 1, 1, 1}, {2, 1, 1, 2},
                                        {2, 1, 1, 2}, {1, 1, 1, 1}, {2, 2, 2, 2}};
  const Scene scene = parse_scene(text, "kinds.csg");
  ASSERT_EQ(scene.primitives.size(), 7u);
  for (std::size_t k = 0; k < scene.primitives.size(); ++k) {
    const PreparedPrimitive p = prepare_primitive(scene.primitives[k]);
    for (SurfaceId s = 0; s < 4; ++s) {
      OpCounts ops;
      world_normal(p, {0.25, 0.5, 0.75}, s, ops);
      EXPECT_EQ(ops.matvec, expected[k][s]) << static_cast<int>(p.kind) << " surface " << s;
      EXPECT_EQ(world_normal_matvecs(p, s), expected[k][s]) << static_cast<int>(p.kind) << " surface " << s;
    }
  }
}
