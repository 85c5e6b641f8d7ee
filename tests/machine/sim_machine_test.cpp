// The whole machine on real scenes: cycle accounting, transfer timing, the screen
// against the tracer alone, determinism across host threads, memory refusal, and
// the load spread of the three pixel modes on BALLS.

#include "machine/parts/frame_protocol.h"
#include "machine/machine.h"
#include "machine/unit_memory.h"
#include "machine/run_figures.h"

#include "capsim/scene/parser.h"
#include "capsim/trace/render.h"

#include <fmt/core.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <span>
#include <string>

namespace capsim::sim {
namespace {

PreparedScene balls(int width, int height) {
  PrepareOptions prep;
  prep.width = width;
  prep.height = height;
  return prepare_scene(parse_scene_file(std::string(CAPSIM_SOURCE_DIR) + "/scenes/balls.csg"), prep);
}

MachineConfig config_of(CellGrid grid, PixelMode mode) {
  MachineConfig c;
  c.cells = grid;
  c.mode = mode;
  c.profile = load_cost_profile("cap");
  return c;
}

bool same_floats(std::span<const float> a, std::span<const float> b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

TEST(Machine, CellBusyCyclesAreTheSumOfItsPixelsOperationCosts) {
  const PreparedScene scene = balls(45, 38);  // not a multiple of the grid
  const Tracer tracer(scene, TraceOptions{});
  for (PixelMode mode : {PixelMode::Dot, PixelMode::Line, PixelMode::Block}) {
    const MachineConfig config = config_of({3, 5}, mode);
    const SimulationResult r = simulate_frame(tracer, config, 2, false);
    const WindowLayout layout(mode, config.cells, 45, 38);
    Tracer::Scratch scratch(scene);
    CostBreakdown all = voxel_generation_cost(scene.voxel_counts, config.profile.costs);
    for (const CellReport& c : r.cells) {
      CostBreakdown expected;
      std::uint64_t rays = 0;
      const CellWindow& w = layout.window(c.id);
      for (int k = 0; k < w.pixel_count(); ++k) {
        const ScreenPixel p = w.screen_pixel(k);
        OpCounts ops;
        tracer.trace_pixel(p.x, p.y, scratch, ops);
        expected += pixel_cost(ops, config.profile.costs);
        rays += ops.rays;
      }
      EXPECT_EQ(c.busy, expected.total()) << to_string(mode) << " cell " << c.id;
      EXPECT_EQ(c.work.cycles, expected.cycles) << to_string(mode) << " cell " << c.id;
      EXPECT_EQ(c.rays, rays);
      EXPECT_EQ(c.pixels, static_cast<std::uint64_t>(w.pixel_count()));
      EXPECT_EQ(c.idle + c.busy + c.comm, c.finish);
      all += expected;
    }
    EXPECT_EQ(r.breakdown.cycles, all.cycles) << to_string(mode);
  }
}

TEST(Machine, TransfersTakeArbitrationPlusBytesOverBandwidthPlusLatency) {
  const PreparedScene scene = balls(32, 32);
  const Tracer tracer(scene, TraceOptions{});
  const MachineConfig config = config_of({4, 4}, PixelMode::Dot);
  const SimulationResult r = simulate_frame(tracer, config, 1, false);
  const CostProfile& p = config.profile;
  auto transfer = [&](std::uint64_t bytes) { return p.bus.arbitration + p.bus_data_cycles(bytes) + p.bus.latency; };

  // The host's spans: voxel generation, then the four broadcasts back to back.
  const Cycles voxel_generation = voxel_generation_cost(scene.voxel_counts, p.costs).total();
  const std::uint64_t sizes[] = {p.program_bytes, r.footprint.scene_bytes(), r.footprint.voxel_bytes(),
                                 kStartCommandBytes};
  std::vector<TimelineSpan> host;
  for (const TimelineSpan& s : r.timeline.spans())
    if (s.track == 0) host.push_back(s);
  ASSERT_EQ(host.size(), 6u);
  EXPECT_EQ(host[0].name, "voxel generation");
  EXPECT_EQ(host[0].end, voxel_generation);
  Cycles t = voxel_generation;
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(host[1 + i].begin, t);
    EXPECT_EQ(host[1 + i].end - host[1 + i].begin, transfer(sizes[i])) << host[1 + i].name;
    EXPECT_EQ(host[1 + i].bytes, sizes[i]);
    t = host[1 + i].end;
  }
  // Every cell received the four broadcasts; its "done" waited only for the bus.
  Cycles broadcasts;
  for (std::uint64_t b : sizes) broadcasts += transfer(b);
  for (const CellReport& c : r.cells) {
    EXPECT_GE(c.comm, broadcasts + transfer(kDoneMessageBytes));
    EXPECT_EQ(c.finish, t + c.busy + (c.comm - broadcasts));
  }
  Cycles last;
  for (const CellReport& c : r.cells) last = std::max(last, c.finish);
  EXPECT_EQ(r.frame, last);
}

TEST(Machine, ScreenEqualsTheTracerAloneInEveryMode) {
  const PreparedScene scene = balls(67, 41);
  const Tracer tracer(scene, TraceOptions{});
  const Framebuffer rendered = render(tracer, 2);
  for (PixelMode mode : {PixelMode::Dot, PixelMode::Line, PixelMode::Block})
    for (CellGrid grid : {CellGrid{8, 8}, CellGrid{1, 1}, CellGrid{3, 7}, CellGrid{32, 32}}) {
      const SimulationResult r = simulate_frame(tracer, config_of(grid, mode), 2, false);
      EXPECT_TRUE(same_floats(r.screens[0].screen.rgba, rendered.rgba)) << to_string(mode) << " " << to_string(grid);
      EXPECT_TRUE(same_floats(r.screens[0].screen.depth, rendered.depth)) << to_string(mode) << " " << to_string(grid);
      EXPECT_TRUE(same_floats(r.screens[0].screen.id, rendered.id)) << to_string(mode) << " " << to_string(grid);
    }
}

TEST(Machine, ResultsDoNotDependOnHostThreads) {
  const PreparedScene scene = balls(96, 64);
  const Tracer tracer(scene, TraceOptions{});
  const MachineConfig config = config_of({8, 8}, PixelMode::Dot);
  const SimulationResult one = simulate_frame(tracer, config, 1, false);
  const SimulationResult two = simulate_frame(tracer, config, 2, false);
  EXPECT_EQ(one.timeline, two.timeline);
  EXPECT_TRUE(same_floats(one.screens[0].screen.rgba, two.screens[0].screen.rgba));
  EXPECT_TRUE(same_floats(one.screens[0].pixel_cycles, two.screens[0].pixel_cycles));
  EXPECT_EQ(one.events, two.events);
}

TEST(Machine, RefusesASceneThatDoesNotFitACell) {
  const PreparedScene scene = balls(16, 16);
  const Tracer tracer(scene, TraceOptions{});
  MachineConfig config = config_of({2, 2}, PixelMode::Dot);
  config.profile.cell_memory_bytes = 70'000;
  const SceneFootprint f = scene_footprint(scene);
  const std::uint64_t needed = config.profile.program_bytes + f.scene_bytes() + f.voxel_bytes();
  ASSERT_GT(needed, 70'000u);
  try {
    simulate_frame(tracer, config, 1, false);
    FAIL() << "a scene larger than cell memory was accepted";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(std::to_string(needed)), std::string::npos) << what;
    EXPECT_NE(what.find("70000"), std::string::npos) << what;
  }
}

TEST(Machine, MemoryNeedsBeyond64BitsDoNotWrapIntoAFit) {
  const PreparedScene scene = balls(16, 16);
  CostProfile profile = load_cost_profile("cap");
  profile.cell_memory_bytes = Cycles::kMax;
  profile.program_bytes = Cycles::kMax;  // + the scene's bytes: beyond 64 bits
  MachineConfig config = config_of({4, 4}, PixelMode::Dot);
  config.profile = profile;
  const std::vector<UnitMemory> units = unit_memories({scene_footprint(scene)}, config, 16, 16);
  ASSERT_EQ(units.size(), 1u);
  EXPECT_THROW(check_unit_memory(units[0], profile), std::runtime_error);
}

// A pixel's cost exactly, in 128 bits: the reference for overflow checks.
unsigned __int128 wide_pixel_cycles(const OpCounts& o, const CostTable& c) {
  auto t = [](std::uint64_t n, Cycles cost) { return static_cast<unsigned __int128>(n) * cost.count(); };
  return t(o.sphere_tests, c[CostTerm::SphereTest]) + t(o.cone_tests, c[CostTerm::ConeTest]) + t(o.box_tests, c[CostTerm::BoxTest]) +
         t(o.mesh_tests, c[CostTerm::MeshTest]) + t(o.mesh_node_tests, c[CostTerm::MeshNodeTest]) +
         t(o.triangle_tests, c[CostTerm::TriangleTest]) +
         t(o.dda_setups, c[CostTerm::DdaSetup]) + t(o.dda_steps, c[CostTerm::DdaStep]) + t(o.dda_setups, c[CostTerm::VoxelVisit]) +
         t(o.dda_steps, c[CostTerm::VoxelVisit]) + t(o.voxel_passes, c[CostTerm::VoxelPass]) +
         t(o.tree_visits, c[CostTerm::TreeVisit]) +
         t(o.hits_sorted, c[CostTerm::HitSort]) + t(o.matvec, c[CostTerm::Matvec]) + t(o.shading_evals, c[CostTerm::ShadingEval]) +
         t(o.rays, c[CostTerm::RayOther]) + c[CostTerm::PixelWrite].count();
}

std::string cycle_overflow_of(const Tracer& tracer, const MachineConfig& config, int threads) {
  try {
    simulate_frame(tracer, config, threads, false);
  } catch (const CycleOverflow& e) {
    return e.what();
  }
  ADD_FAILURE() << "no CycleOverflow on " << threads << " threads";
  return {};
}

TEST(Machine, APixelBeyondTheCycleCounterIsTheFirstInScreenOrderOnAnyThreadCount) {
  const PreparedScene scene = balls(40, 30);
  const Tracer tracer(scene, TraceOptions{});
  MachineConfig config = config_of({4, 4}, PixelMode::Dot);
  config.profile.source = "slow.json";
  config.profile.costs[CostTerm::SphereTest] = Cycles(Cycles::kMax / 12);
  // The reference: the first pixel in screen order whose exact cost exceeds 2^64 - 1.
  Tracer::Scratch scratch(scene);
  int first_x = -1, first_y = -1, overflowing = 0;
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x) {
      OpCounts ops;
      tracer.trace_pixel(x, y, scratch, ops);
      if (wide_pixel_cycles(ops, config.profile.costs) > Cycles::kMax && overflowing++ == 0) {
        first_x = x;
        first_y = y;
      }
    }
  ASSERT_GT(overflowing, 1);
  ASSERT_GT(first_y, 0);  // not simply the first pixel traced
  const std::string message = cycle_overflow_of(tracer, config, 1);
  EXPECT_EQ(message.rfind("cost profile slow.json: the simulated time exceeds the 64-bit cycle counter "
                          "(18446744073709551615 cycles, 2305843009214 s at clock_hz 8000000): ", 0),
            0u)
      << message;
  const std::string pixel = fmt::format("pixel ({}, {}) of cell[{},{}]: ", first_x, first_y,
                                        first_y % 4, first_x % 4);
  EXPECT_NE(message.find(pixel), std::string::npos) << message << "\nexpected " << pixel;
  EXPECT_EQ(cycle_overflow_of(tracer, config, 2), message);
  EXPECT_EQ(cycle_overflow_of(tracer, config, 0), message);
}

TEST(Machine, ACellsWorkBeyondTheCycleCounterNamesTheCellAndItsExactSum) {
  const PreparedScene scene = balls(24, 20);
  const Tracer tracer(scene, TraceOptions{.primary_only = true});
  MachineConfig config = config_of({4, 4}, PixelMode::Dot);
  config.profile.costs[CostTerm::RayOther] = Cycles(Cycles::kMax / 2 + 1);  // every pixel fits; two do not
  const WindowLayout layout(PixelMode::Dot, config.cells, 24, 20);
  Tracer::Scratch scratch(scene);
  unsigned __int128 cell0 = 0;
  for (int k = 0; k < layout.window(0).pixel_count(); ++k) {
    const ScreenPixel p = layout.window(0).screen_pixel(k);
    OpCounts ops;
    tracer.trace_pixel(p.x, p.y, scratch, ops);
    ASSERT_EQ(ops.rays, 1u);
    ASSERT_LE(wide_pixel_cycles(ops, config.profile.costs), Cycles::kMax);
    cell0 += wide_pixel_cycles(ops, config.profile.costs);
  }
  const std::string expected = fmt::format("cell[0,0]'s work for its 30 pixels adds up to {} cycles", cell0);
  for (int threads : {1, 2}) {
    const std::string message = cycle_overflow_of(tracer, config, threads);
    EXPECT_EQ(message.substr(message.size() - std::min(message.size(), expected.size())), expected)
        << message;
  }
}

TEST(Machine, AFrameBeyondTheCycleCounterNamesTheCellWhoseTracingEndsTooLate) {
  const PreparedScene scene = balls(1, 1);
  const Tracer tracer(scene, TraceOptions{.primary_only = true});
  MachineConfig config = config_of({1, 1}, PixelMode::Dot);
  for (const CostTermInfo& t : kCostTerms)
    if (t.payer == CostPayer::Cell) config.profile.costs[t.term] = Cycles(0);
  config.profile.costs[CostTerm::RayOther] = Cycles(Cycles::kMax - 1000);  // fits, but not after the broadcasts
  const CostProfile& p = config.profile;
  auto transfer = [&](std::uint64_t bytes) { return p.bus.arbitration + p.bus_data_cycles(bytes) + p.bus.latency; };
  const SceneFootprint f = scene_footprint(scene);
  Cycles start = voxel_generation_cost(scene.voxel_counts, p.costs).total();
  for (std::uint64_t bytes : {p.program_bytes, f.scene_bytes(), f.voxel_bytes(), kStartCommandBytes})
    start += transfer(bytes);
  const std::string message = cycle_overflow_of(tracer, config, 1);
  const std::string expected =
      fmt::format("cell[0,0]'s tracing: an event {} cycles after cycle {}", Cycles::kMax - 1000, start.count());
  EXPECT_NE(message.find(expected), std::string::npos) << message << "\nexpected " << expected;
}

TEST(Machine, SceneFootprintCountsTheDataStructures) {
  const PreparedScene scene = balls(16, 16);
  const SceneFootprint f = scene_footprint(scene);
  EXPECT_EQ(f.primitives, scene.prims.size() * 120);
  EXPECT_EQ(f.status_tree, (scene.tree_template.nodes().size() + scene.prims.size()) * 8);
  EXPECT_EQ(f.voxel_grid, 28 + 4 * (scene.grid.offsets.size() + scene.grid.items.size()));
  EXPECT_EQ(f.view, 48 + 24 * scene.lights.size() + 12);
}

// The paper's Table 4-4: dot mode spreads the load best, line mode next, block
// mode worst.
TEST(Machine, BallsOnEightByEightCellsSpreadsBestInDotModeThenLineThenBlock) {
  const PreparedScene scene = balls(512, 512);
  const Tracer tracer(scene, TraceOptions{});
  double d[3];
  int i = 0;
  for (PixelMode mode : {PixelMode::Dot, PixelMode::Line, PixelMode::Block})
    d[i++] = load_spread(simulate_frame(tracer, config_of({8, 8}, mode), 0, false)).deviation_percent;
  EXPECT_LT(d[0], d[1]);
  EXPECT_LT(d[1], d[2]);
  EXPECT_LT(d[0], 5.0);  // the paper measured 2.3 %
}

}  // namespace
}  // namespace capsim::sim
