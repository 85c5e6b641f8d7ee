// The reference-oracle test: random CSG scenes built again in Embree 3 (as user
// geometries intersected by the oracle's own exact code), every crossing along
// each ray classified by a brute-force top-down (Roth) evaluation, and the
// visible distance, primitive, side and normal compared with the grid +
// status-tree tracer. docs/testing.md ("Oracle test") states the tolerances and
// what counts as grazing.

#include "oracle/oracle_compare.h"
#include "oracle/oracle_csg_text.h"
#include "oracle/oracle_embree.h"
#include "oracle/oracle_random.h"
#include "oracle/oracle_roth.h"

#include "capsim/trace/prepared_scene.h"
#include "capsim/trace/tracer.h"

#include <fmt/core.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

using namespace oracle;

namespace {

constexpr std::uint64_t kSeed = 0x5eed0f0ca9;
constexpr int kTrees = 500;
constexpr int kRaysPerTree = 1000;
constexpr int kMaxDepth = 6;
// Grid divisions per axis the tracer is run with: one voxel (no culling at all),
// two (every primitive straddles planes), the automatic choice, an odd count,
// and fine grids where primitives span many voxels (voxel generation must stay
// conservative) and rays take many 3DDDA steps.
constexpr std::array<int, 6> kGrids = {1, 2, 0, 7, 24, 64};

capsim::Ray ray_at(double ox, double oy, double oz, double dx, double dy, double dz) {
  return capsim::Ray{{ox, oy, oz}, {dx, dy, dz}, 0.0, kInfinity};
}

capsim::Primitive placed(capsim::PrimitiveKind kind, const glm::dmat4& m, double r1 = 1,
                         double r2 = 1) {
  capsim::Primitive p;
  p.kind = kind;
  p.to_world = m;
  p.cone_r1 = r1;
  p.cone_r2 = r2;
  return p;
}

capsim::CsgNode leaf(int p) {
  capsim::CsgNode n;
  n.is_leaf = true;
  n.primitive = p;
  return n;
}

capsim::CsgNode op(capsim::CsgOp o, std::vector<capsim::CsgNode> children) {
  capsim::CsgNode n;
  n.op = o;
  n.children = std::move(children);
  return n;
}

bool structurally_empty(const capsim::CsgNode& n) {
  if (n.is_leaf) return false;
  if (n.children.empty()) return true;
  switch (n.op) {
    case capsim::CsgOp::Union:
      for (const auto& c : n.children)
        if (!structurally_empty(c)) return false;
      return true;
    case capsim::CsgOp::Intersection:
      for (const auto& c : n.children)
        if (structurally_empty(c)) return true;
      return false;
    case capsim::CsgOp::Difference: return structurally_empty(n.children.front());
  }
  return true;
}

// One random test case: scene, the oracle's view of its primitives, the
// universe the rays are aimed at, and the rays.
struct Case {
  RandomScene random;
  std::vector<OraclePrimitive> prims;
  capsim::Aabb universe;
  std::vector<capsim::Ray> rays;  // ray k is of kind kind_of_ray(k)
};

// Rays by kind, in a fixed rotation: 40% from outside, 15% axis-parallel, 10%
// parallel to a coordinate plane, a quarter from inside primitives, 5% skimming
// a surface, 5% passing by an edge.
RayKind kind_of_ray(int k) {
  const int r = k % 20;
  if (r < 8) return RayKind::Outside;
  if (r < 9) return RayKind::Silhouette;
  if (r < 10) return RayKind::Edge;
  if (r < 13) return RayKind::AxisParallel;
  if (r < 15) return RayKind::Planar;
  return RayKind::Inside;
}

Case make_case(int index, int rays) {
  Rng rng(kSeed + static_cast<std::uint64_t>(index));
  Case c;
  // Depth limits cycle through 1..6 so that every depth is tested equally often;
  // a draw that is the empty set by construction (nothing to render) is redrawn.
  const int max_depth = 1 + index % kMaxDepth;
  do c.random = random_scene(rng, max_depth);
  while (structurally_empty(c.random.scene.root));
  for (const capsim::Primitive& p : c.random.scene.primitives) {
    c.prims.push_back(make_oracle_primitive(p));
    c.universe.extend(c.prims.back().world_bounds);
  }
  for (int k = 0; k < rays; ++k) {
    c.rays.push_back(random_ray(rng, c.random.scene, c.universe, kind_of_ray(k)));
  }
  return c;
}

// The tracer's verdicts, in total and by kind of ray.
struct Tally {
  Counts total;
  std::array<Counts, kRayKinds> by_kind{};
  Tally& operator+=(const Tally& o) {
    total += o.total;
    for (int k = 0; k < kRayKinds; ++k) by_kind[k] += o.by_kind[k];
    return *this;
  }
};

std::vector<OracleAnswer> oracle_answers(Oracle& oracle, const Case& c) {
  std::vector<OracleAnswer> answers;
  answers.reserve(c.rays.size());
  for (const capsim::Ray& r : c.rays) answers.push_back(oracle.answer(r));
  return answers;
}

// Runs the tracer on every ray of the case with grid division count `grid` and
// judges each answer against the oracle's (which the self-checks below build
// from a deliberately falsified scene).
Tally check_case(const Case& c, Oracle& oracle, const std::vector<OracleAnswer>& answers, int grid,
                 std::vector<std::string>* failures, std::size_t max_failures = 3) {
  capsim::PrepareOptions options;
  options.grid = grid;
  options.width = 64;
  options.height = 64;
  const capsim::PreparedScene prepared = capsim::prepare_scene(c.random.scene, options);
  const capsim::Tracer tracer(prepared, capsim::TraceOptions{});
  capsim::Tracer::Scratch scratch(prepared);
  const Tolerance tol;
  Tally tally_out;
  for (std::size_t k = 0; k < c.rays.size(); ++k) {
    capsim::Hit h;
    capsim::OpCounts ops;
    const bool hit = tracer.first_hit(c.rays[k], scratch, ops, h);
    const Judgement j = judge(answers[k], oracle, hit, h, c.rays[k], c.universe, tol);
    tally(tally_out.total, answers[k], j);
    tally(tally_out.by_kind[static_cast<int>(kind_of_ray(static_cast<int>(k)))], answers[k], j);
    if (j.verdict == Verdict::Disagree && failures && failures->size() < max_failures)
      failures->push_back(fmt::format("grid {} (tracer's n = {}), ray {}:\n{}\n", grid,
                                      prepared.grid.n, k, j.detail));
  }
  return tally_out;
}

}  // namespace

// --- The oracle's own parts, against hand-computed answers. -------------------

TEST(OracleGeometry, HandComputedSpans) {
  // Unit sphere, scaled by 2 along x only.
  OraclePrimitive s = make_oracle_primitive(
      placed(capsim::PrimitiveKind::Sphere, scaling({2, 1, 1})));
  Span sp = line_span(s, ray_at(-5, 0, 0, 1, 0, 0));
  EXPECT_DOUBLE_EQ(sp.t_enter, 3);
  EXPECT_DOUBLE_EQ(sp.t_exit, 7);
  EXPECT_TRUE(line_span(s, ray_at(-5, 1.0000001, 0, 1, 0, 0)).empty());
  // A direction of length 2 halves t.
  sp = line_span(s, ray_at(-5, 0, 0, 2, 0, 0));
  EXPECT_DOUBLE_EQ(sp.t_enter, 1.5);

  // Box [1,3] x [0,1] x [0,1], mirrored in x (the same set, negative determinant).
  OraclePrimitive b = make_oracle_primitive(
      placed(capsim::PrimitiveKind::Box, translation({3, 0, 0}) * scaling({-2, 1, 1})));
  sp = line_span(b, ray_at(0, 0.5, 0.5, 1, 0, 0));
  EXPECT_DOUBLE_EQ(sp.t_enter, 1);
  EXPECT_DOUBLE_EQ(sp.t_exit, 3);
  EXPECT_EQ(world_normal(b, ray_at(0, 0.5, 0.5, 1, 0, 0), 1, sp.enter_surface),
            glm::dvec3(-1, 0, 0));
  // Axis-parallel, outside the y slab: no division by the zero component.
  EXPECT_TRUE(line_span(b, ray_at(0, 1.5, 0.5, 1, 0, 0)).empty());
  // Close to an edge: the margin is the t-gap to the other face's plane.
  sp = line_span(b, ray_at(0, 0.5, -0.25, 1, 0, 0.25));
  EXPECT_DOUBLE_EQ(sp.t_enter, 1);
  EXPECT_DOUBLE_EQ(sp.enter_margin, 0);

  // Frustum radius 1 at z=0 to 0.5 at z=1, height 2 (world radius 2..1).
  OraclePrimitive f = make_oracle_primitive(
      placed(capsim::PrimitiveKind::Cone, scaling({2, 2, 2}), 1, 0.5));
  sp = line_span(f, ray_at(-5, 0, 1, 1, 0, 0));  // at world z=1 the radius is 1.5
  EXPECT_NEAR(sp.t_enter, 3.5, 1e-12);
  EXPECT_NEAR(sp.t_exit, 6.5, 1e-12);
  EXPECT_EQ(sp.enter_surface, 0);
  sp = line_span(f, ray_at(0, 0, 5, 0, 0, -1));  // down the axis: both caps
  EXPECT_DOUBLE_EQ(sp.t_enter, 3);
  EXPECT_DOUBLE_EQ(sp.t_exit, 5);
  EXPECT_EQ(sp.enter_surface, 2);
  EXPECT_EQ(sp.exit_surface, 1);
  EXPECT_EQ(world_normal(f, ray_at(0, 0, 5, 0, 0, -1), 3, 2), glm::dvec3(0, 0, 1));

  // Pointed cone (apex at z=1): a line through the apex plane misses the other
  // nappe; a steep line through both nappes keeps only the solid's piece.
  OraclePrimitive pc = make_oracle_primitive(placed(capsim::PrimitiveKind::Cone, glm::dmat4(1.0), 1, 0));
  EXPECT_TRUE(line_span(pc, ray_at(-5, 0, 1.01, 1, 0, 0)).empty());
  sp = line_span(pc, ray_at(0.1, 0, -1, 0, 0, 1));
  EXPECT_DOUBLE_EQ(sp.t_enter, 1);
  EXPECT_NEAR(sp.t_exit, 1.9, 1e-12);
  sp = line_span(pc, ray_at(-0.05, 0, 3, 0.01, 0, -1));  // crosses the upper nappe first
  EXPECT_NEAR(sp.t_enter, 2.05 / 1.01, 1e-12);
  EXPECT_DOUBLE_EQ(sp.t_exit, 3);

  // Cylinder along its own axis: the quadric degenerates (A = B = 0).
  OraclePrimitive cyl = make_oracle_primitive(placed(capsim::PrimitiveKind::Cone, scaling({1, 1, 3})));
  sp = line_span(cyl, ray_at(0.5, 0, -1, 0, 0, 1));
  EXPECT_DOUBLE_EQ(sp.t_enter, 1);
  EXPECT_DOUBLE_EQ(sp.t_exit, 4);
  EXPECT_TRUE(line_span(cyl, ray_at(1.5, 0, -1, 0, 0, 1)).empty());
}

TEST(OracleRoth, HandComputedClassification) {
  // Spans along one ray: A = [1, 5], B = [3, 7], C = [4, 4.5].
  const std::vector<PrimSpan> spans = {{0, {1, 5, 0, 0}}, {1, {3, 7, 0, 0}}, {2, {4, 4.5, 0, 0}}};
  using capsim::CsgOp;
  auto first = [&](const capsim::CsgNode& root, double tmin = 0, double tmax = kInfinity) {
    return first_visible(root, 3, spans, tmin, tmax);
  };
  Visible v = first(op(CsgOp::Union, {leaf(0), leaf(1)}));
  EXPECT_TRUE(v.hit && v.crossing.t == 1 && v.crossing.primitive == 0 && v.root_entering);
  v = first(op(CsgOp::Intersection, {leaf(0), leaf(1)}));
  EXPECT_TRUE(v.hit && v.crossing.t == 3 && v.crossing.primitive == 1);
  v = first(op(CsgOp::Difference, {leaf(1), leaf(0)}));  // B - A = [5, 7]: entered by leaving A
  EXPECT_TRUE(v.hit && v.crossing.t == 5 && v.crossing.primitive == 0 && !v.crossing.entering &&
              v.root_entering);
  v = first(op(CsgOp::Difference, {leaf(0), leaf(1), leaf(2)}));  // n-ary: A - B - C = [1, 3]
  EXPECT_TRUE(v.hit && v.crossing.t == 1);
  v = first(op(CsgOp::Difference, {leaf(0), leaf(1), leaf(2)}), 2);  // from inside: exit at 3
  EXPECT_TRUE(v.hit && v.crossing.t == 3 && v.starts_inside && !v.root_entering);
  // (A & B) - C = [3, 4] u [4.5, 5]: seen from 4.2, inside C, the solid starts at 4.5.
  v = first(op(CsgOp::Difference, {op(CsgOp::Intersection, {leaf(0), leaf(1)}), leaf(2)}), 4.2);
  EXPECT_TRUE(v.hit && v.crossing.t == 4.5 && v.crossing.primitive == 2 && v.root_entering);
  // tmax before the surface: no hit.
  EXPECT_FALSE(first(op(CsgOp::Intersection, {leaf(0), leaf(1)}), 0, 2.5).hit);
  // The empty set: an operator without children, alone or inside an intersection.
  EXPECT_FALSE(first(op(CsgOp::Union, {})).hit);
  EXPECT_FALSE(first(op(CsgOp::Intersection, {leaf(0), op(CsgOp::Union, {})})).hit);
  v = first(op(CsgOp::Union, {op(CsgOp::Difference, {}), leaf(2)}));
  EXPECT_TRUE(v.hit && v.crossing.t == 4 && v.crossing.primitive == 2);
  // A single-child intersection or difference is its child.
  v = first(op(CsgOp::Intersection, {leaf(1)}));
  EXPECT_TRUE(v.hit && v.crossing.t == 3);
}

// Embree's BVH only culls; it must never drop a primitive the ray meets.
TEST(OracleEmbree, CollectsEveryPrimitiveTheRayMeets) {
  std::uint64_t rays = 0, spans = 0;
  for (int i = 0; i < 40; ++i) {
    const Case c = make_case(i, 500);
    EmbreeCollector collector(c.prims);
    std::vector<PrimSpan> by_embree, by_hand;
    for (const capsim::Ray& r : c.rays) {
      collector.collect(r, by_embree);
      collector.collect_brute_force(r, by_hand);
      // Drop spans wholly behind the origin: the Embree segment starts at t = 0.
      std::erase_if(by_hand, [](const PrimSpan& s) { return s.span.t_exit < 0; });
      std::erase_if(by_embree, [](const PrimSpan& s) { return s.span.t_exit < 0; });
      std::sort(by_embree.begin(), by_embree.end(),
                [](const PrimSpan& a, const PrimSpan& b) { return a.primitive < b.primitive; });
      ASSERT_EQ(by_embree.size(), by_hand.size()) << "tree " << i;
      for (std::size_t k = 0; k < by_hand.size(); ++k) {
        ASSERT_EQ(by_embree[k].primitive, by_hand[k].primitive);
        ASSERT_EQ(by_embree[k].span.t_enter, by_hand[k].span.t_enter);
        ASSERT_EQ(by_embree[k].span.t_exit, by_hand[k].span.t_exit);
      }
      ++rays;
      spans += by_hand.size();
    }
  }
  EXPECT_GT(spans, rays);  // the rays do meet primitives: on average more than one
}

// The judge's tolerance, on a unit sphere: exact answers agree, a tracer answer
// off by more than the tolerance does not, and a miss is excused only where the
// ray skims the silhouette.
TEST(OracleCompare, GrazingIsExcusedOnlyAtTheSilhouette) {
  Oracle oracle({make_oracle_primitive(placed(capsim::PrimitiveKind::Sphere, glm::dmat4(1.0)))},
                op(capsim::CsgOp::Union, {leaf(0)}));
  const capsim::Aabb universe{glm::dvec3(-1), glm::dvec3(1)};
  const Tolerance tol;
  const capsim::Hit miss;
  auto hit_at = [](double t, glm::dvec3 n) {
    capsim::Hit h;
    h.t = t;
    h.primitive = 0;
    h.normal = n;
    h.entering = true;
    return h;
  };
  // Through the centre: enters at t = 4 with normal -x.
  const capsim::Ray central = ray_at(-5, 0, 0, 1, 0, 0);
  const OracleAnswer a = oracle.answer(central);
  ASSERT_TRUE(a.visible.hit);
  EXPECT_EQ(judge(a, oracle, true, hit_at(4 + 1e-12, {-1, 0, 0}), central, universe, tol).verdict,
            Verdict::Agree);
  EXPECT_EQ(judge(a, oracle, true, hit_at(4 + 1e-6, {-1, 0, 0}), central, universe, tol).verdict,
            Verdict::Disagree);
  EXPECT_EQ(judge(a, oracle, true, hit_at(4, {1, 0, 0}), central, universe, tol).verdict,
            Verdict::Disagree);
  EXPECT_EQ(judge(a, oracle, false, miss, central, universe, tol).verdict, Verdict::Disagree);
  // 1e-14 inside the silhouette: the chord is 3e-7 long, under 1e-7 of the ray's
  // scale (about 8.5), so the oracle's hit may be missed.
  const capsim::Ray skim = ray_at(-5, 1 - 1e-14, 0, 1, 0, 0);
  const OracleAnswer b = oracle.answer(skim);
  ASSERT_TRUE(b.visible.hit);
  EXPECT_EQ(judge(b, oracle, false, miss, skim, universe, tol).verdict, Verdict::Grazing);
  // 1e-3 inside, the chord is long and a miss is a failure.
  const capsim::Ray near = ray_at(-5, 1 - 1e-3, 0, 1, 0, 0);
  EXPECT_EQ(judge(oracle.answer(near), oracle, false, miss, near, universe, tol).verdict,
            Verdict::Disagree);
}

// --- The tracer against the oracle. ------------------------------------------

TEST(OracleTracer, RandomCsgTreesAgreeWithRothClassification) {
  Tally all;
  std::array<Counts, kGrids.size()> by_grid{};
  std::array<int, kMaxDepth + 1> depths{};
  std::array<int, 3> ops{}, kinds{};
  int empty_groups = 0, cones_pointed = 0, starts_inside = 0;
  std::size_t max_prims = 0;
  std::vector<std::string> failures;
  for (int i = 0; i < kTrees; ++i) {
    const Case c = make_case(i, kRaysPerTree);
    Oracle oracle(c.prims, c.random.scene.root);
    const std::vector<OracleAnswer> answers = oracle_answers(oracle, c);
    ++depths[c.random.shape.depth];
    for (int k = 0; k < 3; ++k) ops[k] += c.random.shape.ops[k], kinds[k] += c.random.shape.kinds[k];
    empty_groups += c.random.shape.empty_groups;
    max_prims = std::max(max_prims, c.prims.size());
    for (const OraclePrimitive& p : c.prims)
      if (p.kind == capsim::PrimitiveKind::Cone && (p.r1 == 0 || p.r2 == 0)) ++cones_pointed;
    for (const OracleAnswer& a : answers) starts_inside += a.visible.starts_inside;
    for (std::size_t g = 0; g < kGrids.size(); ++g) {
      std::vector<std::string> here;
      const Tally t = check_case(c, oracle, answers, kGrids[g], &here);
      by_grid[g] += t.total;
      all += t;
      if (!here.empty() && failures.size() < 10) {
        std::string text = fmt::format("tree {} (seed {:#x}):\n{}", i, kSeed + i, csg_text(c.random.scene));
        for (const std::string& f : here) text += f;
        failures.push_back(text);
      }
    }
  }
  const Counts& total = all.total;
  fmt::print("oracle: {} trees x {} rays x {} grid sizes = {} ray checks\n", kTrees, kRaysPerTree,
             kGrids.size(), total.rays);
  fmt::print("oracle: {} agree, {} grazing exemptions, {} disagree; visible surface found in {}; "
             "normals not compared (edge, apex) {}\n",
             total.agreements, total.grazing, total.disagreements, total.oracle_hits,
             total.normals_at_edges);
  for (std::size_t g = 0; g < kGrids.size(); ++g)
    fmt::print("oracle: grid {:>4}: {} agree, {} grazing, {} disagree\n",
               kGrids[g] == 0 ? std::string("auto") : std::to_string(kGrids[g]),
               by_grid[g].agreements, by_grid[g].grazing, by_grid[g].disagreements);
  const char* kind_names[kRayKinds] = {"outside", "axis-parallel", "planar", "inside a primitive",
                                       "silhouette", "edge"};
  for (int k = 0; k < kRayKinds; ++k)
    fmt::print("oracle: {:>18} rays: {} checks, {} hits, {} agree, {} grazing, {} disagree\n",
               kind_names[k], all.by_kind[k].rays, all.by_kind[k].oracle_hits,
               all.by_kind[k].agreements, all.by_kind[k].grazing, all.by_kind[k].disagreements);
  fmt::print("oracle: rays starting inside the CSG solid: {} (per grid size)\n", starts_inside);
  fmt::print("oracle: tree depths 1..6: {} {} {} {} {} {}; union/intersection/difference nodes "
             "{}/{}/{}; sphere/box/cone {}/{}/{} ({} pointed); empty groups {}; max primitives {}\n",
             depths[1], depths[2], depths[3], depths[4], depths[5], depths[6], ops[0], ops[1],
             ops[2], kinds[0], kinds[1], kinds[2], cones_pointed, empty_groups, max_prims);
  for (const std::string& f : failures) fmt::print("DISAGREEMENT in {}\n", f);

  // What the test promises to have covered.
  EXPECT_EQ(total.rays, std::uint64_t{kTrees} * kRaysPerTree * kGrids.size());
  for (int d = 1; d <= kMaxDepth; ++d) EXPECT_GT(depths[d], 0) << "no tree of depth " << d;
  for (int k = 0; k < 3; ++k) {
    EXPECT_GT(ops[k], 0);
    EXPECT_GT(kinds[k], 0);
  }
  EXPECT_GT(cones_pointed, 0);
  EXPECT_GT(empty_groups, 0);
  EXPECT_GT(starts_inside, kTrees * kRaysPerTree / 20);
  EXPECT_GT(total.oracle_hits, total.rays / 4);
  // The verdict: grazing is rare away from the silhouette and edge rays that
  // seek it, and nothing disagrees outside the grazing tolerance.
  EXPECT_LT(total.grazing - all.by_kind[static_cast<int>(RayKind::Silhouette)].grazing -
                all.by_kind[static_cast<int>(RayKind::Edge)].grazing,
            total.rays / 100000 + 10);
  EXPECT_EQ(total.disagreements, 0u);
}

// --- The comparison can fail: falsified oracles must be caught. ---------------

namespace {

// The first operator node found depth-first gets another operator.
bool change_first_operator(capsim::CsgNode& n) {
  if (n.is_leaf) return false;
  if (n.children.size() >= 2) {
    n.op = n.op == capsim::CsgOp::Union ? capsim::CsgOp::Intersection : capsim::CsgOp::Union;
    return true;
  }
  for (auto& c : n.children)
    if (change_first_operator(c)) return true;
  return false;
}

}  // namespace

TEST(OracleTracer, CatchesAWrongOperator) {
  Counts total;
  int trees = 0;
  for (int i = 0; i < 40; ++i) {
    const Case c = make_case(i, 300);
    capsim::CsgNode wrong = c.random.scene.root;
    if (!change_first_operator(wrong)) continue;
    ++trees;
    Oracle oracle(c.prims, wrong);
    total += check_case(c, oracle, oracle_answers(oracle, c), 0, nullptr).total;
  }
  fmt::print("oracle self-check, wrong operator: {} rays, {} disagreements, {} grazing\n",
             total.rays, total.disagreements, total.grazing);
  ASSERT_GT(trees, 20);
  EXPECT_GT(total.disagreements, total.rays / 50);
  EXPECT_LT(total.grazing, total.disagreements / 10 + 1);
}

TEST(OracleTracer, CatchesGeometryMovedBeyondTheTolerance) {
  Counts total;
  for (int i = 0; i < 20; ++i) {
    const Case c = make_case(i, 300);
    std::vector<OraclePrimitive> moved = c.prims;
    // Every primitive 1e-6 of the universe's size further along x: far less than
    // a pixel, far more than the 1e-9 agreement tolerance.
    const double shift = 1e-6 * glm::length(c.universe.extent());
    for (OraclePrimitive& p : moved) {
      capsim::Primitive q;
      q.kind = p.kind;
      q.cone_r1 = p.r1;
      q.cone_r2 = p.r2;
      q.to_world = translation({shift, 0, 0}) * p.to_world;
      p = make_oracle_primitive(q);
    }
    Oracle oracle(moved, c.random.scene.root);
    total += check_case(c, oracle, oracle_answers(oracle, c), 0, nullptr).total;
  }
  fmt::print("oracle self-check, moved geometry: {} rays, {} oracle hits, {} disagreements, "
             "{} grazing\n", total.rays, total.oracle_hits, total.disagreements, total.grazing);
  // Every hit whose surface is not parallel to x moves; most must be caught.
  EXPECT_GT(total.disagreements, total.oracle_hits / 2);
}
