// What a run reports beyond times: the operations every cell paid for, the
// host's voxel-generation counts, and the command bus's traffic.

#include "machine/parts/frame_protocol.h"
#include "machine/machine.h"
#include "support/sim_test_profile.h"

#include "capsim/scene/parser.h"
#include "capsim/trace/render.h"

#include <gtest/gtest.h>

namespace capsim::sim {
namespace {

PreparedScene balls() {
  PrepareOptions prep;
  prep.width = 40;
  prep.height = 30;
  return prepare_scene(parse_scene_file(std::string(CAPSIM_SOURCE_DIR) + "/scenes/balls.csg"), prep);
}

TEST(RunTotals, CellsOperationsAddUpToTheWholeScreensOnAnyThreadCount) {
  const PreparedScene scene = balls();
  const Tracer tracer(scene, TraceOptions{});
  RenderStats stats;
  render(tracer, 1, &stats);
  for (PixelMode mode : {PixelMode::Dot, PixelMode::Line, PixelMode::Block})
    for (int threads : {1, 2}) {
      MachineConfig config;
      config.cells = {2, 3};
      config.mode = mode;
      config.profile = testing::round_number_profile();
      const SimulationResult r = simulate_frame(tracer, config, threads, false);
      OpCounts sum;
      for (const CellReport& c : r.cells) {
        sum += c.ops;
        EXPECT_EQ(c.rays, c.ops.rays);
        // Each cell's busy time is the cost of its operations.
        EXPECT_EQ(c.busy, work_cost(c.ops, c.pixels, config.profile.costs).total());
      }
      EXPECT_EQ(sum, stats.ops) << to_string(mode) << ", " << threads << " threads";
      EXPECT_EQ(r.voxel_counts, scene.voxel_counts);
    }
}

TEST(RunTotals, BusCarriesFourBroadcastsAndADonePerCell) {
  const PreparedScene scene = balls();
  const Tracer tracer(scene, TraceOptions{});
  MachineConfig config;
  config.cells = {2, 3};
  config.profile = testing::round_number_profile();
  const SimulationResult r = simulate_frame(tracer, config, 1, false);
  const CostProfile& p = config.profile;
  const SceneFootprint& f = r.footprint;
  const std::uint64_t broadcast = p.program_bytes + f.scene_bytes() + f.voxel_bytes() + kStartCommandBytes;
  EXPECT_EQ(r.bus.transfers, 4u + 6u);
  EXPECT_EQ(r.bus.bytes, broadcast + 6 * kDoneMessageBytes);
  // 10 cycles a byte, 3 of arbitration per transfer (round_number_profile).
  EXPECT_EQ(r.bus.busy, Cycles(10 * (broadcast + 6 * kDoneMessageBytes) + 3 * 10));
}

}  // namespace
}  // namespace capsim::sim
