// Cost profiles: the shipped files, unit conversion, strict parsing, and the
// cycle arithmetic of a pixel and of voxel generation.

#include "machine/costs/cost_profile.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <array>
#include <limits>
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
  EXPECT_EQ(p.costs[CostTerm::SphereTest], Cycles(2980 * 8));
  EXPECT_EQ(p.costs[CostTerm::ConeTest], Cycles(5783 * 8));
  EXPECT_EQ(p.costs[CostTerm::BoxTest], Cycles(5580 * 8));
  EXPECT_EQ(p.costs[CostTerm::DdaSetup], Cycles(4237 * 8));
  EXPECT_EQ(p.costs[CostTerm::DdaStep], Cycles(160 * 8));
  EXPECT_EQ(p.costs[CostTerm::Matvec], Cycles(597 * 8));
  // The host is the M380's (docs/calibration.md): 18.5 us.
  EXPECT_EQ(p.costs[CostTerm::HostMatmat], Cycles(148));
  EXPECT_EQ(p.bus.bytes_per_second, 2'000'000u);
  EXPECT_EQ(p.link.bits_per_second, 15'000'000u);
}

TEST(CostProfile, M380HoldsTable41AtOneGigahertz) {
  const CostProfile p = load_cost_profile("m380");
  EXPECT_EQ(p.clock_hz, 1'000'000'000u);
  EXPECT_EQ(p.costs[CostTerm::SphereTest], Cycles(18200));  // 18.2 us
  EXPECT_EQ(p.costs[CostTerm::ConeTest], Cycles(31800));    // 31.8 us
  EXPECT_EQ(p.costs[CostTerm::BoxTest], Cycles(42200));     // 42.2 us
  EXPECT_EQ(p.costs[CostTerm::DdaSetup], Cycles(33800));    // 33.8 us
  EXPECT_EQ(p.costs[CostTerm::DdaStep], Cycles(1400));      // 1.4 us
  EXPECT_EQ(p.costs[CostTerm::Matvec], Cycles(3600));       // 3.6 us
  EXPECT_EQ(p.costs[CostTerm::HostMatmat], Cycles(18500));  // 18.5 us
}

std::string minimal_profile_text() {
  return nlohmann::json::parse(R"({
    "name": "t", "description": "d", "clock_hz": 1000000,
    "cell_costs_us": {"sphere_test": 1, "cone_test": 2, "box_test": 3, "dda_setup": 4,
                      "dda_step": 5, "voxel_visit": 13, "matvec": 6, "tree_visit": 7, "hit_sort": 8,
                      "shading_eval": 9, "ray_other": 10, "pixel_write": 11,
                      "aa_square": 12, "voxel_pass": 14, "mesh_test": 15,
                      "mesh_node_test": 16, "triangle_test": 17, "revolution_test": 18,
                      "revolution_edge_test": 19, "quartic_test": 20},
    "host_costs_us": {"primitive": 1, "matmat": 2, "matvec": 3, "voxel_column": 4, "voxel_entry": 5,
                      "grid_voxel": 6},
    "cell_voxel_costs_us": {"primitive": 21, "matmat": 22, "matvec": 23, "voxel_column": 24,
                            "voxel_entry": 25, "grid_voxel": 26},
    "bus": {"bytes_per_second": 1000, "arbitration_us": 1.4, "latency_us": 1.6},
    "link": {"bits_per_second": 8000, "latency_us": 0, "topology": "mesh"},
    "cell_memory_bytes": 4096, "program_bytes": 1024, "video_memory_bytes": 2048})").dump();
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
  nlohmann::json no_voxel_visit = j;  // a profile written before the per-voxel work was a key
  no_voxel_visit["cell_costs_us"].erase("voxel_visit");
  expect_refused(no_voxel_visit.dump(), "cell_costs_us missing key \"voxel_visit\"");
  nlohmann::json no_cell_voxels = j;  // a profile written before the cells could generate voxels
  no_cell_voxels.erase("cell_voxel_costs_us");
  expect_refused(no_cell_voxels.dump(), "cell_voxel_costs_us");
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

TEST(CostProfile, RefusesATimeWhoseCyclesA64BitCountCannotHold) {
  const nlohmann::json j = nlohmann::json::parse(minimal_profile_text());  // 1 MHz: 1 cycle per us
  // The largest double below 2^64 is accepted, exactly; 2^64 itself is not.
  nlohmann::json largest = j;
  largest["host_costs_us"]["voxel_entry"] = 18446744073709549568.0;  // 2^64 - 2^11
  EXPECT_EQ(parse_cost_profile(largest.dump(), "ok.json").costs[CostTerm::HostEntry],
            Cycles(18446744073709549568u));
  struct Case {
    const char* section;
    const char* key;
    double us;
  };
  for (const Case& c : {Case{"host_costs_us", "voxel_entry", 18446744073709551616.0},
                        Case{"cell_costs_us", "sphere_test", 1.85e19},
                        Case{"cell_costs_us", "pixel_write", 1e20},
                        Case{"host_costs_us", "voxel_column", 1e300},
                        Case{"bus", "latency_us", 2e19},
                        Case{"link", "latency_us", 1e25}}) {
    nlohmann::json too_long = j;
    too_long[c.section][c.key] = c.us;
    expect_refused(too_long.dump(), std::string(c.section) + "." + c.key + " = ");
    expect_refused(too_long.dump(), "more than a 64-bit cycle count holds");
  }
  // The same time is refused at a faster clock, and the message names the clock.
  nlohmann::json fast = j;
  fast["clock_hz"] = 18446744073709551615u;
  fast["cell_costs_us"]["ray_other"] = 1e7;  // 10 s
  expect_refused(fast.dump(), "cell_costs_us.ray_other = 10000000 us is 1.845e+20 cycles at clock_hz 18446744073709551615");
}

TEST(CostProfile, RefusesAProgramLargerThanACellsMemory) {
  nlohmann::json j = nlohmann::json::parse(minimal_profile_text());
  j["program_bytes"] = 4097;
  expect_refused(j.dump(), "program_bytes (4097) must not exceed cell_memory_bytes (4096)");
}

TEST(CostProfile, RoundingNamesTheTimesMovedByMoreThanOnePercent) {
  // At 1 MHz the minimal profile's times are whole cycles but the bus's
  // 1.4 us (1 cycle, 28.6 % off) and 1.6 us (2 cycles, 25 % off).
  const CostProfile p = parse_cost_profile(minimal_profile_text(), "test");
  EXPECT_EQ(p.times.size(), 35u);  // 20 cell, 6 host, 6 cell voxel, 2 bus, 1 link
  const std::vector<ProfileTime> off = p.rounding();
  ASSERT_EQ(off.size(), 2u);
  EXPECT_EQ(off[0].key, "bus.arbitration_us");
  EXPECT_EQ(off[0].us, 1.4);
  EXPECT_EQ(off[0].cycles, Cycles(1));
  EXPECT_NEAR(off[0].rounding_error(), 0.4 / 1.4, 1e-12);
  EXPECT_EQ(off[1].key, "bus.latency_us");
  EXPECT_EQ(off[1].cycles, Cycles(2));
  EXPECT_TRUE(p.rounding(0.3).empty());
  // At 1 kHz the CSG terms (7 and 8 us) become 0 cycles: free.
  nlohmann::json slow = nlohmann::json::parse(minimal_profile_text());
  slow["clock_hz"] = 1000;
  bool tree_visit_free = false;
  for (const ProfileTime& t : parse_cost_profile(slow.dump(), "slow").rounding())
    if (t.key == "cell_costs_us.tree_visit") tree_visit_free = t.cycles == Cycles(0) && t.rounding_error() == 1;
  EXPECT_TRUE(tree_visit_free);
  // The built-in profiles' times are whole cycles of their clocks.
  EXPECT_TRUE(load_cost_profile("cap").rounding().empty());
  EXPECT_TRUE(load_cost_profile("m380").rounding().empty());
}

TEST(CostProfile, ReadsTheVideoMemoryAsAPositiveSize) {
  EXPECT_EQ(parse_cost_profile(minimal_profile_text(), "test").video_memory_bytes, 2048u);
  EXPECT_EQ(load_cost_profile("cap").video_memory_bytes, 1u << 20);  // 1 MiB per cell
  nlohmann::json j = nlohmann::json::parse(minimal_profile_text());
  for (const nlohmann::json& bad : {nlohmann::json(0), nlohmann::json(-1), nlohmann::json(1.5), nlohmann::json("1")}) {
    j["video_memory_bytes"] = bad;
    expect_refused(j.dump(), "video_memory_bytes must be a positive whole number");
  }
  j.erase("video_memory_bytes");
  expect_refused(j.dump(), "missing key \"video_memory_bytes\"");
}

TEST(CostProfile, DataCyclesBeyondTheCounterThrowNamingTheRate) {
  CostProfile p = parse_cost_profile(minimal_profile_text(), "test");
  p.clock_hz = Cycles::kMax;
  p.bus.bytes_per_second = 1;
  EXPECT_EQ(p.bus_data_cycles(1), Cycles(Cycles::kMax));
  try {
    p.bus_data_cycles(2);
    FAIL() << "no overflow";
  } catch (const CycleOverflow& e) {
    EXPECT_EQ(e.quantity(), "2 bytes on the bus at bus.bytes_per_second 1 and clock_hz 18446744073709551615");
  }
  // One cycle per bit: 2^61 - 1 bytes take the last cycles but one byte, 2^61
  // bytes (2^64 bits) one cycle too many.
  p = parse_cost_profile(minimal_profile_text(), "test");  // 8000 bits per second
  p.clock_hz = 8000;
  EXPECT_EQ(p.link_data_cycles((std::uint64_t{1} << 61) - 1), Cycles(Cycles::kMax - 7));
  try {
    p.link_data_cycles(std::uint64_t{1} << 61);
    FAIL() << "no overflow";
  } catch (const CycleOverflow& e) {
    EXPECT_NE(e.quantity().find("on a link at link.bits_per_second 8000"), std::string::npos) << e.what();
  }
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
  const CostBreakdown b = pixel_cost(ops, p.costs);
  EXPECT_EQ(b[CostCategory::Intersection], Cycles(3 * 1 + 2 * 2 + 1 * 3));
  EXPECT_EQ(b[CostCategory::Dda], Cycles(1 * 4 + 7 * 5 + (1 + 7) * 13));  // every voxel visited
  EXPECT_EQ(b[CostCategory::Csg], Cycles(4 * 7 + 5 * 8));
  EXPECT_EQ(b[CostCategory::Other], Cycles(1 * 6 + 2 * 9 + 2 * 10 + 3 * 12 + 11));
  EXPECT_EQ(b[CostCategory::VoxelGeneration], Cycles(0));
  EXPECT_EQ(b.total(), Cycles(10 + 143 + 68 + 91));
}

TEST(CostProfile, VoxelGenerationCostIsEachCountTimesItsHostCost) {
  const CostProfile p = parse_cost_profile(minimal_profile_text(), "test");
  VoxelGenCounts n;
  n.primitives = 10;
  n.matmat = 10;
  n.matvec = 80;
  n.columns = 50;
  n.voxel_entries = 200;
  const CostBreakdown b = voxel_generation_cost(n, p.costs);
  EXPECT_EQ(b[CostCategory::VoxelGeneration], Cycles(10 * 1 + 10 * 2 + 80 * 3 + 50 * 4 + 200 * 5));
  EXPECT_EQ(b.total(), b[CostCategory::VoxelGeneration]);
}

TEST(CostProfile, APixelCostBeyondTheCounterNamesTheCategoryAndTheField) {
  CostProfile p = parse_cost_profile(minimal_profile_text(), "test");
  OpCounts ops;
  ops.box_tests = std::uint64_t{1} << 63;  // x 3 cycles
  try {
    pixel_cost(ops, p.costs);
    FAIL() << "no overflow";
  } catch (const CycleOverflow& e) {
    EXPECT_EQ(e.quantity(),
              "intersection work: 9223372036854775808 box tests x cell_costs_us.box_test (3 cycles)");
  }
  // Each product fits; their sum does not (no per-voxel work, whose product would not fit).
  p.costs[CostTerm::VoxelVisit] = Cycles(0);
  OpCounts sum;
  sum.dda_setups = std::uint64_t{1} << 61;  // x 4 cycles = 2^63
  sum.dda_steps = std::uint64_t{1} << 61;   // x 5 cycles
  try {
    pixel_cost(sum, p.costs);
    FAIL() << "no overflow";
  } catch (const CycleOverflow& e) {
    EXPECT_EQ(e.quantity(), "3DDDA (incl. set-up) work: 9223372036854775808 + 11529215046068469760 cycles");
  }
  // The voxels visited are the set-ups plus the steps, each charged voxel_visit.
  p.costs[CostTerm::VoxelVisit] = Cycles(13);
  OpCounts voxels;
  voxels.dda_setups = std::uint64_t{1} << 60;
  voxels.dda_steps = std::uint64_t{1} << 60;
  try {
    pixel_cost(voxels, p.costs);
    FAIL() << "no overflow";
  } catch (const CycleOverflow& e) {
    EXPECT_EQ(e.quantity(),
              "3DDDA (incl. set-up) work: 2305843009213693952 voxels visited x cell_costs_us.voxel_visit (13 cycles)");
  }
}

TEST(CostProfile, VoxelGenerationBeyondTheCounterNamesTheHostField) {
  const CostProfile p = parse_cost_profile(minimal_profile_text(), "test");
  VoxelGenCounts n;
  n.voxel_entries = Cycles::kMax / 5 + 1;
  try {
    voxel_generation_cost(n, p.costs);
    FAIL() << "no overflow";
  } catch (const CycleOverflow& e) {
    EXPECT_NE(e.quantity().find("voxel entries x host_costs_us.voxel_entry (5 cycles)"),
              std::string::npos)
        << e.what();
  }
}

TEST(CostProfile, VoxelGenerationOnACellCountsTheCellsVoxelCosts) {
  const CostProfile p = parse_cost_profile(minimal_profile_text(), "test");  // 1 MHz: 1 cycle per us
  VoxelGenCounts n;
  n.primitives = 1;
  n.matmat = 2;
  n.matvec = 3;
  n.columns = 4;
  n.voxel_entries = 5;
  n.grid_voxels = 6;
  EXPECT_EQ(voxel_generation_cost(n, p.costs, CostPayer::CellVoxels)[CostCategory::VoxelGeneration],
            Cycles(21 * 1 + 22 * 2 + 23 * 3 + 24 * 4 + 25 * 5 + 26 * 6));
  EXPECT_EQ(voxel_generation_cost(n, p.costs, CostPayer::Host).total(),
            Cycles(1 * 1 + 2 * 2 + 3 * 3 + 4 * 4 + 5 * 5 + 6 * 6));
  EXPECT_THROW(voxel_generation_cost(n, p.costs, CostPayer::Cell), std::logic_error);
  n = {};
  n.grid_voxels = Cycles::kMax / 26 + 1;
  try {
    voxel_generation_cost(n, p.costs, CostPayer::CellVoxels);
    FAIL() << "no overflow";
  } catch (const CycleOverflow& e) {
    EXPECT_NE(e.quantity().find("grid voxels x cell_voxel_costs_us.grid_voxel (26 cycles)"), std::string::npos)
        << e.what();
  }
}

TEST(CostProfile, BreakdownSumsBeyondTheCounterThrowAndLeaveTheSumUnchanged) {
  CostBreakdown a, b;
  a[CostCategory::Dda] = Cycles(5);
  a[CostCategory::Other] = Cycles(Cycles::kMax);
  b[CostCategory::Dda] = Cycles(1);
  b[CostCategory::Other] = Cycles(1);
  EXPECT_THROW(a += b, CycleOverflow);
  EXPECT_EQ(a[CostCategory::Dda], Cycles(5));
  EXPECT_THROW(a.total(), CycleOverflow);
}

}  // namespace
}  // namespace capsim::sim
