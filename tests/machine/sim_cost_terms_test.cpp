// The table of cost terms: each counted operation once, with its profile key,
// its Table 4-3 process, what it counts and how; the shipped profiles hold
// exactly its keys.

#include "machine/costs/builtin_profiles.h"
#include "machine/costs/cost_profile.h"
#include "machine/costs/cost_terms.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <set>
#include <string>

namespace capsim::sim {
namespace {

TEST(CostTerms, EveryTermHasOneProfileKeyInItsPayersSection) {
  std::set<std::string> keys;
  for (const CostTermInfo& t : kCostTerms) {
    EXPECT_TRUE(keys.insert(profile_key(t.term)).second) << profile_key(t.term);
    EXPECT_EQ((t.cell_count != nullptr), t.payer == CostPayer::Cell) << t.key;
    EXPECT_EQ((t.voxel_count != nullptr), t.payer != CostPayer::Cell) << t.key;
    EXPECT_EQ(t.payer != CostPayer::Cell, t.category == CostCategory::VoxelGeneration) << t.key;
  }
  EXPECT_EQ(profile_key(CostTerm::CellGridVoxel), "cell_voxel_costs_us.grid_voxel");
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
  o.mesh_tests = 14;
  o.mesh_node_tests = 15;
  o.triangle_tests = 16;
  o.dda_setups = 4;
  o.dda_steps = 5;
  o.matvec = 6;
  o.tree_visits = 7;
  o.voxel_passes = 13;
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
  EXPECT_EQ(count(CostTerm::MeshTest), 14u);
  EXPECT_EQ(count(CostTerm::MeshNodeTest), 15u);
  EXPECT_EQ(count(CostTerm::TriangleTest), 16u);
  EXPECT_EQ(count(CostTerm::DdaSetup), 4u);
  EXPECT_EQ(count(CostTerm::DdaStep), 5u);
  EXPECT_EQ(count(CostTerm::VoxelVisit), 4u + 5u);  // the set-up's voxel and one per step
  EXPECT_EQ(count(CostTerm::Matvec), 6u);
  EXPECT_EQ(count(CostTerm::VoxelPass), 13u);
  EXPECT_EQ(count(CostTerm::TreeVisit), 7u);
  EXPECT_EQ(count(CostTerm::HitSort), 8u);
  EXPECT_EQ(count(CostTerm::ShadingEval), 9u);
  EXPECT_EQ(count(CostTerm::RayOther), 10u);
  EXPECT_EQ(count(CostTerm::AaSquare), 11u);
  EXPECT_EQ(count(CostTerm::PixelWrite), 12u);
}

// The host's and a cell's voxel generation count the same operations: each
// host term has its cells' twin under the same key.
TEST(CostTerms, EachVoxelTermCountsItsOperation) {
  VoxelGenCounts n;
  n.primitives = 1;
  n.matmat = 2;
  n.matvec = 3;
  n.columns = 4;
  n.voxel_entries = 5;
  n.grid_voxels = 6;
  auto count = [&](CostTerm t) { return info(t).voxel_count(n); };
  const CostTerm host[] = {CostTerm::HostPrimitive, CostTerm::HostMatmat, CostTerm::HostMatvec,
                           CostTerm::HostColumn,    CostTerm::HostEntry,  CostTerm::HostGridVoxel};
  const CostTerm cells[] = {CostTerm::CellPrimitive, CostTerm::CellMatmat, CostTerm::CellMatvec,
                            CostTerm::CellColumn,    CostTerm::CellEntry,  CostTerm::CellGridVoxel};
  for (std::uint64_t k = 0; k < 6; ++k) {
    EXPECT_EQ(count(host[k]), k + 1) << info(host[k]).key;
    EXPECT_EQ(count(cells[k]), k + 1) << info(cells[k]).key;
    EXPECT_EQ(cell_voxel_twin(host[k]), cells[k]) << info(host[k]).key;
  }
  EXPECT_THROW(cell_voxel_twin(CostTerm::SphereTest), std::logic_error);
}

// A profile's cost of a term is read from the term's key: each value of a
// file lands on its own term, as round(us x clock / 1e6) cycles.
TEST(CostTerms, EachProfileValueLandsOnItsTerm) {
  nlohmann::json file = nlohmann::json::parse(builtin_profiles()[0].json);  // cap
  ASSERT_EQ(builtin_profiles()[0].name, "cap");
  int k = 1;
  for (const CostTermInfo& t : kCostTerms) file[profile_section(t.payer)][t.key] = 1000 * k++;
  const CostProfile p = parse_cost_profile(file.dump(), "t.json");
  k = 1;
  for (const CostTermInfo& t : kCostTerms) EXPECT_EQ(p.costs[t.term], Cycles(8000 * k++)) << t.key;  // 8 MHz
}

}  // namespace
}  // namespace capsim::sim
