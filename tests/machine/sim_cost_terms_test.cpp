// The table of cost terms: each counted operation once, with its profile key,
// its Table 4-3 process, what it counts and how; the shipped profiles hold
// exactly its keys.

#include "machine/cost_profile.h"
#include "machine/cost_terms.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace capsim::sim {
namespace {

TEST(CostTerms, EveryTermHasOneProfileKeyInItsPayersSection) {
  std::set<std::string> keys;
  for (const CostTermInfo& t : kCostTerms) {
    EXPECT_TRUE(keys.insert(profile_key(t.term)).second) << profile_key(t.term);
    EXPECT_EQ((t.cell_count != nullptr), t.payer == CostPayer::Cell) << t.key;
    EXPECT_EQ((t.host_count != nullptr), t.payer == CostPayer::Host) << t.key;
    EXPECT_EQ(t.payer == CostPayer::Host, t.category == CostCategory::VoxelGeneration) << t.key;
  }
  EXPECT_EQ(profile_key(CostTerm::SphereTest), "cell_costs_us.sphere_test");
  EXPECT_EQ(profile_key(CostTerm::HostColumn), "host_costs_us.voxel_column");
  EXPECT_EQ(std::string(to_string(CostCategory::Dda)), "3DDDA (incl. set-up)");
  EXPECT_EQ(std::string(json_key(CostCategory::VoxelGeneration)), "voxel_generation");
}

TEST(CostTerms, EachCellTermCountsItsOperation) {
  OpCounts o;
  o.sphere_tests = 1;
  o.cone_tests = 2;
  o.box_tests = 3;
  o.dda_setups = 4;
  o.dda_steps = 5;
  o.matvec = 6;
  o.tree_visits = 7;
  o.hits_sorted = 8;
  o.shading_evals = 9;
  o.rays = 10;
  o.aa_squares = 11;
  o.primary_rays = 100;  // counted by the tracer, charged through rays
  const std::uint64_t pixels = 12;
  auto count = [&](CostTerm t) { return info(t).cell_count(o, pixels); };
  EXPECT_EQ(count(CostTerm::SphereTest), 1u);
  EXPECT_EQ(count(CostTerm::ConeTest), 2u);
  EXPECT_EQ(count(CostTerm::BoxTest), 3u);
  EXPECT_EQ(count(CostTerm::DdaSetup), 4u);
  EXPECT_EQ(count(CostTerm::DdaStep), 5u);
  EXPECT_EQ(count(CostTerm::VoxelVisit), 4u + 5u);  // the set-up's voxel and one per step
  EXPECT_EQ(count(CostTerm::Matvec), 6u);
  EXPECT_EQ(count(CostTerm::TreeVisit), 7u);
  EXPECT_EQ(count(CostTerm::HitSort), 8u);
  EXPECT_EQ(count(CostTerm::ShadingEval), 9u);
  EXPECT_EQ(count(CostTerm::RayOther), 10u);
  EXPECT_EQ(count(CostTerm::AaSquare), 11u);
  EXPECT_EQ(count(CostTerm::PixelWrite), 12u);
}

TEST(CostTerms, EachHostTermCountsItsOperation) {
  VoxelGenCounts n;
  n.primitives = 1;
  n.matmat = 2;
  n.matvec = 3;
  n.columns = 4;
  n.voxel_entries = 5;
  auto count = [&](CostTerm t) { return info(t).host_count(n); };
  EXPECT_EQ(count(CostTerm::HostPrimitive), 1u);
  EXPECT_EQ(count(CostTerm::HostMatmat), 2u);
  EXPECT_EQ(count(CostTerm::HostMatvec), 3u);
  EXPECT_EQ(count(CostTerm::HostColumn), 4u);
  EXPECT_EQ(count(CostTerm::HostEntry), 5u);
}

// A profile's cost of a term is read from the term's key: each shipped value
// lands on its own term.
TEST(CostTerms, TheShippedProfilesFillEveryTerm) {
  for (const std::string& name : builtin_profile_names()) {
    const CostProfile p = load_cost_profile(name);
    for (const CostTermInfo& t : kCostTerms) EXPECT_GT(p.costs[t.term].count(), 0u) << name << " " << t.key;
  }
  const CostProfile cap = load_cost_profile("cap");
  EXPECT_EQ(cap.costs[CostTerm::HostColumn], Cycles(1791 * 8));
  EXPECT_EQ(cap.costs[CostTerm::AaSquare], Cycles(597 * 8));
  EXPECT_EQ(cap.costs[CostTerm::PixelWrite], Cycles(199 * 8));
}

}  // namespace
}  // namespace capsim::sim
