// Cost profiles: the shipped files, unit conversion, strict parsing, and the
// cycle arithmetic of a pixel and of voxel generation.

#include "cost_profile.h"
#include "heatmap.h"

#include "capsim/image_io.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>

namespace capsim::sim {
namespace {

TEST(CostProfile, BothShippedProfilesAreBuiltIn) {
  EXPECT_EQ(builtin_profile_names(), (std::vector<std::string>{"cap", "m380"}));
}

TEST(CostProfile, CapHoldsTable41AtEightMegahertz) {
  const CostProfile p = load_cost_profile("cap");
  EXPECT_EQ(p.name, "cap");
  EXPECT_EQ(p.clock_hz, 8'000'000u);
  EXPECT_EQ(p.cell.sphere_test, Cycles(2980 * 8));
  EXPECT_EQ(p.cell.cone_test, Cycles(5783 * 8));
  EXPECT_EQ(p.cell.box_test, Cycles(5580 * 8));
  EXPECT_EQ(p.cell.dda_setup, Cycles(4237 * 8));
  EXPECT_EQ(p.cell.dda_step, Cycles(160 * 8));
  EXPECT_EQ(p.cell.matvec, Cycles(597 * 8));
  EXPECT_EQ(p.host.matmat, Cycles(3134 * 8));
  EXPECT_EQ(p.bus.bytes_per_second, 2'000'000u);
  EXPECT_EQ(p.link.bits_per_second, 15'000'000u);
}

TEST(CostProfile, M380HoldsTable41AtFiftyMegahertz) {
  const CostProfile p = load_cost_profile("m380");
  EXPECT_EQ(p.clock_hz, 50'000'000u);
  EXPECT_EQ(p.cell.sphere_test, Cycles(910));   // 18.2 us
  EXPECT_EQ(p.cell.cone_test, Cycles(1590));    // 31.8 us
  EXPECT_EQ(p.cell.box_test, Cycles(2110));     // 42.2 us
  EXPECT_EQ(p.cell.dda_setup, Cycles(1690));    // 33.8 us
  EXPECT_EQ(p.cell.dda_step, Cycles(70));       // 1.4 us
  EXPECT_EQ(p.cell.matvec, Cycles(180));        // 3.6 us
  EXPECT_EQ(p.host.matmat, Cycles(925));        // 18.5 us
  EXPECT_EQ(p.cell.ray_other, Cycles(2520));    // 50.4 us, fitted
}

std::string minimal_profile_text() {
  return nlohmann::json::parse(R"({
    "name": "t", "description": "d", "clock_hz": 1000000,
    "cell_costs_us": {"sphere_test": 1, "cone_test": 2, "box_test": 3, "dda_setup": 4,
                      "dda_step": 5, "matvec": 6, "tree_visit": 7, "hit_sort": 8,
                      "shading_eval": 9, "ray_other": 10, "pixel_write": 11,
                      "aa_square": 12},
    "host_costs_us": {"primitive": 1, "matmat": 2, "matvec": 3, "voxel_column": 4, "voxel_entry": 5},
    "bus": {"bytes_per_second": 1000, "arbitration_us": 1.4, "latency_us": 1.6},
    "link": {"bits_per_second": 8000, "latency_us": 0, "topology": "mesh"},
    "cell_memory_bytes": 4096, "program_bytes": 1024})").dump();
}

TEST(CostProfile, ConvertsMicrosecondsToRoundedCycles) {
  const CostProfile p = parse_cost_profile(minimal_profile_text(), "test");
  EXPECT_EQ(p.bus.arbitration, Cycles(1));  // 1.4 us at 1 MHz
  EXPECT_EQ(p.bus.latency, Cycles(2));      // 1.6 us
  EXPECT_EQ(p.bus_data_cycles(3), Cycles(3000));
  EXPECT_EQ(p.link_data_cycles(3), Cycles(3000));
}

void expect_refused(const std::string& text, const std::string& fragment) {
  try {
    parse_cost_profile(text, "bad.json");
    FAIL() << "accepted a profile that should fail with: " << fragment;
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("bad.json"), std::string::npos) << e.what();
  }
}

TEST(CostProfile, RefusesUnknownMissingAndBadValues) {
  nlohmann::json j = nlohmann::json::parse(minimal_profile_text());
  nlohmann::json unknown = j;
  unknown["cell_costs_us"]["sphere_tset"] = 1;
  expect_refused(unknown.dump(), "cell_costs_us.sphere_tset");
  nlohmann::json missing = j;
  missing["bus"].erase("latency_us");
  expect_refused(missing.dump(), "latency_us");
  nlohmann::json negative = j;
  negative["cell_costs_us"]["dda_step"] = -1;
  expect_refused(negative.dump(), "cell_costs_us.dda_step");
  nlohmann::json zero_clock = j;
  zero_clock["clock_hz"] = 0;
  expect_refused(zero_clock.dump(), "clock_hz");
  nlohmann::json topology = j;
  topology["link"]["topology"] = "ring";
  expect_refused(topology.dump(), "link.topology");
  expect_refused("{ not json", "not valid JSON");
}

TEST(CostProfile, UnknownNameThatIsNoFileIsRefused) {
  try {
    load_cost_profile("no-such-profile");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cap, m380"), std::string::npos) << e.what();
  }
}

TEST(CostProfile, PixelCostIsEachCountTimesItsCost) {
  const CostProfile p = parse_cost_profile(minimal_profile_text(), "test");
  OpCounts ops;
  ops.sphere_tests = 3;
  ops.cone_tests = 2;
  ops.box_tests = 1;
  ops.dda_setups = 1;
  ops.dda_steps = 7;
  ops.tree_visits = 4;
  ops.hits_sorted = 5;
  ops.shading_evals = 2;
  ops.matvec = 1;
  ops.rays = 2;
  ops.aa_squares = 3;
  const CostBreakdown b = pixel_cost(ops, p.cell);
  EXPECT_EQ(b[CostCategory::Intersection], Cycles(3 * 1 + 2 * 2 + 1 * 3));
  EXPECT_EQ(b[CostCategory::Dda], Cycles(1 * 4 + 7 * 5));
  EXPECT_EQ(b[CostCategory::Csg], Cycles(4 * 7 + 5 * 8));
  EXPECT_EQ(b[CostCategory::Other], Cycles(1 * 6 + 2 * 9 + 2 * 10 + 3 * 12 + 11));
  EXPECT_EQ(b[CostCategory::VoxelGeneration], Cycles(0));
  EXPECT_EQ(b.total(), Cycles(10 + 39 + 68 + 91));
}

TEST(CostProfile, VoxelGenerationCostIsEachCountTimesItsHostCost) {
  const CostProfile p = parse_cost_profile(minimal_profile_text(), "test");
  VoxelGenCounts n;
  n.primitives = 10;
  n.matmat = 10;
  n.matvec = 80;
  n.columns = 50;
  n.voxel_entries = 200;
  const CostBreakdown b = voxel_generation_cost(n, p.host);
  EXPECT_EQ(b[CostCategory::VoxelGeneration], Cycles(10 * 1 + 10 * 2 + 80 * 3 + 50 * 4 + 200 * 5));
  EXPECT_EQ(b.total(), b[CostCategory::VoxelGeneration]);
}

TEST(Heatmap, ColoursSurviveTheSrgbEncodingOfPngOutput) {
  for (int v = 0; v < 256; ++v)
    EXPECT_EQ(linear_to_srgb8(srgb8_to_linear(static_cast<unsigned char>(v))), v);
}

}  // namespace
}  // namespace capsim::sim
