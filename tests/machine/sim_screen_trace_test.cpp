// A screen traced once (ScreenTrace) and laid out on any cells gives what
// tracing for those cells gives, to the bit: every cell's samples, cycles,
// operations and work, in every format, plain and antialiased, for every way
// of sharing the screen; and so the same runs.

#include "machine/machine.h"
#include "machine/traced_cells.h"

#include "support/balance_scenes.h"
#include "support/shipped_scene.h"

#include <gtest/gtest.h>

#include <string>

namespace capsim::sim {
namespace {

using testing::random_scene;
using testing::same_floats;

void expect_same_cells(const std::vector<TracedCell>& a, const std::vector<TracedCell>& b, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t c = 0; c < a.size(); ++c) {
    const std::string cell = what + ", cell " + std::to_string(c);
    EXPECT_TRUE(same_floats(a[c].samples.rgba, b[c].samples.rgba)) << cell;
    EXPECT_TRUE(same_floats(a[c].samples.depth, b[c].samples.depth)) << cell;
    EXPECT_TRUE(same_floats(a[c].samples.id, b[c].samples.id)) << cell;
    EXPECT_EQ(a[c].srgb8, b[c].srgb8) << cell;
    EXPECT_EQ(a[c].pixel_cycles, b[c].pixel_cycles) << cell;
    EXPECT_EQ(a[c].work.cycles, b[c].work.cycles) << cell;
    EXPECT_EQ(a[c].rays, b[c].rays) << cell;
    EXPECT_EQ(a[c].ops, b[c].ops) << cell;
    EXPECT_EQ(a[c].corner_work.cycles, b[c].corner_work.cycles) << cell;
    EXPECT_EQ(a[c].corner_ops, b[c].corner_ops) << cell;
    EXPECT_EQ(a[c].subdivision_work.cycles, b[c].subdivision_work.cycles) << cell;
    EXPECT_EQ(a[c].pixel_samples, b[c].pixel_samples) << cell;
    EXPECT_EQ(a[c].write_cycles, b[c].write_cycles) << cell;
    ASSERT_EQ(a[c].chunk_work.size(), b[c].chunk_work.size()) << cell;
    for (std::size_t k = 0; k < a[c].chunk_work.size(); ++k)
      EXPECT_EQ(a[c].chunk_work[k].cycles, b[c].chunk_work[k].cycles) << cell << ", chunk " << k;
    EXPECT_EQ(a[c].chunk_ops, b[c].chunk_ops) << cell;
  }
}

TEST(ScreenTrace, LaidOutOnAnyCellsIsTracingForThem) {
  const CostTable& costs = load_cost_profile("cap").costs;
  for (unsigned seed : {2u, 9u}) {
    const PreparedScene scene = random_scene(seed, 21, 13);
    const Tracer tracer(scene, TraceOptions{});
    for (const int depth : {0, 2}) {
      const AntialiasOptions aa{depth, 0.3};
      for (const int threads : {1, 2}) {
        const ScreenTrace screen = trace_screen(tracer, aa, threads);
        for (const PixelMode mode : {PixelMode::Block, PixelMode::Line, PixelMode::Dot})
          for (const CellGrid grid : {CellGrid{1, 1}, CellGrid{2, 3}, CellGrid{4, 4}})
            for (const ScreenFormat format : {ScreenFormat::Float, ScreenFormat::Srgb8})
              for (const CornerTracing corners : {CornerTracing::ByOwner, CornerTracing::ByEveryWindowThatNeedsIt})
                for (const bool keep : {false, true})
                  for (const int chunk : {0, 4}) {
                    const WindowLayout layout(mode, grid, 21, 13);
                    const std::string what = "seed " + std::to_string(seed) + ", aa " + std::to_string(depth) +
                                             ", " + to_string(mode) + " " + to_string(grid) + ", threads " +
                                             std::to_string(threads) + ", keep " + std::to_string(keep) +
                                             ", chunk " + std::to_string(chunk);
                    expect_same_cells(
                        trace_cells(screen, layout, costs, threads, format, keep, corners, chunk),
                        trace_cells(tracer, layout, costs, threads, nullptr, aa, format, keep, corners, chunk), what);
                  }
      }
    }
  }
}

// Stealing's chunks hold a cell's pixel operations between them: cut into
// chunks or not, a cell has the same operations, rays and work, and its
// chunks' operations add up to its pixels' (antialiased: its subdivision's),
// whether the pixels' own cycles are kept or only the sums.
TEST(ScreenTrace, ChunksAddUpToTheirCells) {
  const CostTable& costs = load_cost_profile("cap").costs;
  const PreparedScene scene = random_scene(5, 19, 11);
  const Tracer tracer(scene, TraceOptions{});
  for (const int depth : {0, 2}) {
    const ScreenTrace screen = trace_screen(tracer, AntialiasOptions{depth, 0.3}, 1);
    for (const PixelMode mode : {PixelMode::Block, PixelMode::Line, PixelMode::Dot})
      for (const ScreenFormat format : {ScreenFormat::Float, ScreenFormat::Srgb8})
        for (const bool keep : {false, true}) {
          const WindowLayout layout(mode, CellGrid{2, 3}, 19, 11);
          const std::string what = "aa " + std::to_string(depth) + ", " + to_string(mode) + ", keep " +
                                   std::to_string(keep);
          const std::vector<TracedCell> whole = trace_cells(screen, layout, costs, 2, format, keep);
          const std::vector<TracedCell> chunked =
              trace_cells(screen, layout, costs, 2, format, keep, CornerTracing::ByOwner, 3);
          for (std::size_t c = 0; c < whole.size(); ++c) {
            EXPECT_EQ(whole[c].ops, chunked[c].ops) << what << ", cell " << c;
            EXPECT_EQ(whole[c].rays, chunked[c].rays) << what << ", cell " << c;
            EXPECT_EQ(whole[c].work.cycles, chunked[c].work.cycles) << what << ", cell " << c;
            EXPECT_TRUE(whole[c].chunk_ops.empty()) << what << ", cell " << c;
            OpCounts chunks;
            for (const OpCounts& k : chunked[c].chunk_ops) chunks += k;
            EXPECT_NE(chunks, OpCounts()) << what << ", cell " << c;
            // Antialiased, the corners are traced before the chunks are
            // handed out: the chunks hold the subdivision.
            EXPECT_EQ(chunks + chunked[c].corner_ops, chunked[c].ops) << what << ", cell " << c;
            if (depth > 0) {
              EXPECT_NE(chunked[c].corner_ops, OpCounts()) << what << ", cell " << c;
            }
          }
        }
  }
}

TEST(ScreenTrace, RunsAsTheTracerRunsAndRefusesOtherAntialiasing) {
  const PreparedScene scene = testing::shipped_scene("balls.csg", 32, 24);
  const Tracer tracer(scene, TraceOptions{});
  for (const int depth : {0, 1}) {
    const ScreenTrace screen = trace_screen(tracer, {depth, 0.3}, 2);
    for (const BalanceScheme scheme : {BalanceScheme::Static, BalanceScheme::Demand, BalanceScheme::Steal}) {
      MachineConfig config;
      config.cells = {2, 3};
      config.profile = load_cost_profile("cap");
      config.aa = {depth, 0.3};
      config.balance.scheme = scheme;
      config.balance.tile_pixels = 16;
      config.completion_cycles = true;
      const SimulationResult traced = simulate_traced_frame(screen, config, 2);
      const SimulationResult now = simulate_frame(tracer, config, 2, false);
      EXPECT_EQ(traced.frame, now.frame) << depth << " " << to_string(config.balance);
      EXPECT_EQ(traced.breakdown.cycles, now.breakdown.cycles);
      ASSERT_EQ(traced.cells.size(), now.cells.size());
      for (std::size_t c = 0; c < now.cells.size(); ++c) EXPECT_EQ(traced.cells[c].finish, now.cells[c].finish) << c;
      EXPECT_TRUE(same_floats(traced.screens[0].screen.rgba, now.screens[0].screen.rgba));
      EXPECT_EQ(traced.screens[0].completion_cycles, now.screens[0].completion_cycles);
    }
    MachineConfig other;
    other.aa = {depth + 1, 0.3};
    EXPECT_THROW(simulate_traced_frame(screen, other, 1), std::invalid_argument);
  }
}

}  // namespace
}  // namespace capsim::sim
