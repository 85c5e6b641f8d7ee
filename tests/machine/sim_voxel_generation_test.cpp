// Voxel generation on the cells (machine/parts/voxel_shares.h): every cell
// places a share of the primitives and builds a share of the voxels, and the
// shares go to every cell over the command bus. What must hold: the shares
// add up to the host's generation, operation by operation and byte by byte;
// the screen is the host-generated run's; every broadcast share reaches every
// other cell; and the cycles of a small run are exactly these.

#include "machine/machine.h"
#include "machine/parts/voxel_shares.h"
#include "machine/scene_footprint.h"

#include "support/balance_scenes.h"
#include "support/sequence_builders.h"
#include "support/shipped_scene.h"

#include "capsim/trace/render.h"

#include <gtest/gtest.h>

#include <string>

namespace capsim::sim {
namespace {

using testing::random_scene;
using testing::same_floats;

MachineConfig cells_config(CellGrid grid, PixelMode mode = PixelMode::Dot) {
  MachineConfig c;
  c.cells = grid;
  c.mode = mode;
  c.profile = load_cost_profile("cap");
  c.voxel_generation = VoxelGeneration::Cells;
  return c;
}

VoxelGenCounts sum(const std::vector<VoxelShare>& shares) {
  VoxelGenCounts n;
  for (const VoxelShare& s : shares) {
    n += s.placing;
    n += s.building;
  }
  return n;
}

TEST(VoxelShares, AddUpToTheHostsGenerationOperationByOperation) {
  const CostTable& costs = load_cost_profile("cap").costs;
  for (unsigned seed = 1; seed <= 8; ++seed) {
    const PreparedScene scene = random_scene(seed, 16, 12);
    const SceneFootprint footprint = scene_footprint(scene);
    // One cell, fewer cells than primitives, more cells than primitives,
    // more cells than voxels.
    for (const int cells : {1, 3, 8, 64, 4096}) {
      const std::vector<VoxelShare> shares = voxel_shares(scene, cells, costs);
      ASSERT_EQ(shares.size(), static_cast<std::size_t>(cells));
      EXPECT_EQ(sum(shares), scene.voxel_counts) << "seed " << seed << ", " << cells << " cells";
      std::uint64_t entries_bytes = 0, rows_bytes = 0;
      for (const VoxelShare& s : shares) {
        entries_bytes += s.entries_bytes;
        rows_bytes += s.rows_bytes;
        EXPECT_EQ(s.placing_cycles, voxel_generation_cost(s.placing, costs, CostPayer::CellVoxels).total());
        EXPECT_EQ(s.building_cycles, voxel_generation_cost(s.building, costs, CostPayer::CellVoxels).total());
      }
      // Every entry goes out once with its two indices, and the rows are the
      // voxel data the host would broadcast but for the header the scene carries.
      EXPECT_EQ(entries_bytes, scene.grid.entries() * kVoxelEntryBytes);
      EXPECT_EQ(rows_bytes + kCellGridHeaderBytes, footprint.voxel_bytes());
    }
  }
}

TEST(VoxelShares, SplitThePrimitivesAndTheVoxelsEvenlyInOrder) {
  const PreparedScene scene = testing::shipped_scene("balls.csg", 16, 16);  // 125 spheres, 10^3 voxels
  ASSERT_EQ(scene.grid.n, 10);
  const std::vector<VoxelShare> shares = voxel_shares(scene, 8, load_cost_profile("cap").costs);
  for (std::size_t k = 0; k < shares.size(); ++k) {
    // 125 / 8: cells 0 to 2 and 4 to 6 take 15 or 16 primitives, floor((k + 1) 125 / 8) - floor(k 125 / 8).
    EXPECT_EQ(shares[k].placing.primitives, (k + 1) * 125 / 8 - k * 125 / 8) << k;
    EXPECT_EQ(shares[k].placing.matmat, shares[k].placing.primitives) << k;
    EXPECT_EQ(shares[k].placing.matvec, 8 * shares[k].placing.primitives) << k;
    EXPECT_EQ(shares[k].building.grid_voxels, 125u) << k;  // 1000 / 8
    const std::uint64_t first = k * 125, end = first + 125;
    EXPECT_EQ(shares[k].building.voxel_entries, scene.grid.offsets[end] - scene.grid.offsets[first]) << k;
  }
  EXPECT_THROW(voxel_shares(scene, 0, load_cost_profile("cap").costs), std::invalid_argument);
}

TEST(VoxelGenerationOnTheCells, ShowsTheHostGeneratedScreenInEveryModeAndScheme) {
  const PreparedScene scene = random_scene(7, 24, 18);
  const Tracer tracer(scene, TraceOptions{});
  for (const PixelMode mode : {PixelMode::Block, PixelMode::Line, PixelMode::Dot})
    for (const BalanceScheme scheme : {BalanceScheme::Static, BalanceScheme::Demand, BalanceScheme::Steal})
      for (const int aa : {0, 1}) {
        if (scheme == BalanceScheme::Demand && mode != PixelMode::Dot) continue;  // tiles take no mode
        MachineConfig host = cells_config({3, 2}, mode);
        host.voxel_generation = VoxelGeneration::Host;
        host.balance.scheme = scheme;
        host.balance.tile_pixels = 16;
        host.balance.chunk_pixels = 4;
        host.aa = {aa, 0.3};
        MachineConfig cells = host;
        cells.voxel_generation = VoxelGeneration::Cells;
        const std::string what = fmt::format("{} {} aa {}", to_string(mode), to_string(host.balance), aa);
        const SimulationResult h = simulate_frame(tracer, host, 2, false);
        for (const int threads : {1, 2}) {
          const SimulationResult c = simulate_frame(tracer, cells, threads, false);
          ASSERT_EQ(c.screens.size(), 1u);
          EXPECT_TRUE(same_floats(c.screens[0].screen.rgba, h.screens[0].screen.rgba)) << what;
          EXPECT_TRUE(same_floats(c.screens[0].screen.depth, h.screens[0].screen.depth)) << what;
          // The cells' tracing is the same work; only the start of the frame moves.
          for (std::size_t i = 0; i < c.cells.size(); ++i)
            EXPECT_EQ(c.cells[i].busy, h.cells[i].busy + c.cells[i].voxel_generation) << what << " cell " << i;
        }
      }
}

TEST(VoxelGenerationOnTheCells, EveryShareReachesEveryOtherCellOnce) {
  const PreparedScene scene = testing::shipped_scene("balls.csg", 24, 24);
  const Tracer tracer(scene, TraceOptions{});
  const MachineConfig config = cells_config({2, 3});
  const SimulationResult r = simulate_frame(tracer, config, 2, false);
  ASSERT_EQ(r.voxel_shares.size(), 1u);
  const std::vector<VoxelShare>& shares = r.voxel_shares[0];
  std::uint64_t all_sent = 0;
  for (const VoxelShare& s : shares) all_sent += s.entries_bytes + s.rows_bytes;
  for (std::size_t i = 0; i < r.cells.size(); ++i) {
    const CellReport& c = r.cells[i];
    EXPECT_EQ(c.voxel_bytes_sent, shares[i].entries_bytes + shares[i].rows_bytes) << i;
    EXPECT_EQ(c.voxel_bytes_received, all_sent - c.voxel_bytes_sent) << i;
    EXPECT_EQ(c.voxel_generation, shares[i].placing_cycles + shares[i].building_cycles) << i;
  }
  EXPECT_EQ(r.voxel_entries_bus.transfers, 6u);
  EXPECT_EQ(r.voxel_rows_bus.transfers, 6u);
  EXPECT_EQ(r.voxel_entries_bus.bytes + r.voxel_rows_bus.bytes, all_sent);
  // The host generates nothing and sends no voxel data; Table 4-3's voxel
  // generation row is the cells' shares.
  EXPECT_EQ(r.voxel_counts, VoxelGenCounts{});
  Cycles shares_cycles;
  for (const VoxelShare& s : shares) shares_cycles += s.placing_cycles + s.building_cycles;
  EXPECT_EQ(r.breakdown[CostCategory::VoxelGeneration], shares_cycles);
  const CostProfile& p = config.profile;
  EXPECT_EQ(r.bus.bytes, p.program_bytes + r.footprint.scene_bytes() + kCellGridHeaderBytes + kStartCommandBytes +
                             all_sent + 6 * kDoneMessageBytes);
  EXPECT_EQ(r.bus.transfers, 3u + 12u + 6u);
}

// One frame on 1 x 2 cells, with placing and building costs made simple:
// each cell places its primitives and broadcasts their entries, builds its
// voxels' lists once the other's entries are in and broadcasts them, and
// traces once the other's rows are in. The frame's time follows transfer by
// transfer.
TEST(VoxelGenerationOnTheCells, TheCyclesOfATwoCellRunAreExactlyThese) {
  const PreparedScene scene = random_scene(3, 8, 4);
  const Tracer tracer(scene, TraceOptions{});
  MachineConfig config = cells_config({1, 2});
  config.profile.costs[CostTerm::CellPrimitive] = Cycles(1000);
  config.profile.costs[CostTerm::CellGridVoxel] = Cycles(10);
  config.profile.costs[CostTerm::CellMatmat] = Cycles(0);
  config.profile.costs[CostTerm::CellMatvec] = Cycles(0);
  const SimulationResult r = simulate_frame(tracer, config, 2, false);
  const std::vector<VoxelShare>& s = r.voxel_shares.at(0);
  const CostProfile& p = config.profile;
  auto transfer = [&](std::uint64_t bytes) { return p.bus.arbitration + p.bus_data_cycles(bytes) + p.bus.latency; };
  auto bus_held = [&](std::uint64_t bytes) { return p.bus.arbitration + p.bus_data_cycles(bytes); };
  // The host's broadcasts: program, scene with the grid's header, start.
  const Cycles start = transfer(p.program_bytes) + transfer(r.footprint.scene_bytes() + kCellGridHeaderBytes) +
                       transfer(kStartCommandBytes);
  ASSERT_EQ(s[0].placing_cycles, Cycles(1000 * s[0].placing.primitives));
  // Two cells' broadcasts asked for at a0 and a1: when each is delivered. The
  // earlier asker (cell 0 on a tie) goes first; the other waits while it holds
  // the bus.
  auto delivered = [&](Cycles a0, Cycles a1, std::uint64_t bytes0, std::uint64_t bytes1) {
    if (a0 <= a1) return std::pair{a0 + transfer(bytes0), std::max(a1, a0 + bus_held(bytes0)) + transfer(bytes1)};
    return std::pair{std::max(a0, a1 + bus_held(bytes1)) + transfer(bytes0), a1 + transfer(bytes1)};
  };
  // Entries, once each has placed its primitives.
  const auto [e0, e1] = delivered(start + s[0].placing_cycles, start + s[1].placing_cycles, s[0].entries_bytes,
                                  s[1].entries_bytes);
  // Each builds once its own broadcast and the other's are in, then sends its rows.
  ASSERT_EQ(s[0].building_cycles, Cycles(10 * s[0].building.grid_voxels));
  const Cycles entries_in = std::max(e0, e1);
  const auto [r0, r1] = delivered(entries_in + s[0].building_cycles, entries_in + s[1].building_cycles,
                                  s[0].rows_bytes, s[1].rows_bytes);
  const Cycles ready = std::max(r0, r1);
  // Then each traces and reports "done", one after the other on the bus.
  const Cycles traced0 = ready + r.cells[0].busy - r.cells[0].voxel_generation;
  const Cycles traced1 = ready + r.cells[1].busy - r.cells[1].voxel_generation;
  const Cycles first = std::min(traced0, traced1), last = std::max(traced0, traced1);
  const Cycles done_first = first + transfer(kDoneMessageBytes);
  const Cycles done_last = std::max(last, first + bus_held(kDoneMessageBytes)) + transfer(kDoneMessageBytes);
  EXPECT_EQ(r.frame, std::max(done_first, done_last));
  // A cell gathers from its own broadcast's delivery to the other's.
  EXPECT_EQ(r.cells[0].voxel_gather, (entries_in - e0) + (ready - r0));
  EXPECT_EQ(r.cells[1].voxel_gather, (entries_in - e1) + (ready - r1));
}

TEST(VoxelGenerationOnTheCells, ALoneCellGeneratesTheWholeGridWithoutTheBus) {
  const PreparedScene scene = random_scene(5, 8, 6);
  const Tracer tracer(scene, TraceOptions{});
  const SimulationResult r = simulate_frame(tracer, cells_config({1, 1}), 1, false);
  EXPECT_EQ(r.voxel_entries_bus.transfers + r.voxel_rows_bus.transfers, 0u);
  EXPECT_EQ(r.cells[0].voxel_generation,
            voxel_generation_cost(scene.voxel_counts, r.config.profile.costs, CostPayer::CellVoxels).total());
  EXPECT_EQ(r.cells[0].voxel_gather, Cycles());
}

// A sequence: each frame's grid is generated anew; frame averaged, the cells
// run through a group's frames, and a faster cell's shares of the next frame
// may reach a slower one before it has all of this frame's.
TEST(VoxelGenerationOnTheCells, RunsSequencesAndFrameAveragedGroups) {
  const testing::FrameTracers frames = testing::moving_frames(4, 16, 12, 6, 4);
  for (const bool average : {false, true}) {
    MachineConfig host = cells_config({2, 2});
    host.voxel_generation = VoxelGeneration::Host;
    host.frame_average = average;
    MachineConfig cells = host;
    cells.voxel_generation = VoxelGeneration::Cells;
    const SimulationResult h = simulate_frames(frames.list, host, 2, false);
    const SimulationResult c = simulate_frames(frames.list, cells, 2, false);
    ASSERT_EQ(c.screens.size(), 4u);
    for (std::size_t f = 0; f < 4; ++f)
      EXPECT_TRUE(same_floats(c.screens[f].screen.rgba, h.screens[f].screen.rgba)) << f << " " << average;
    EXPECT_EQ(c.voxel_shares.size(), 4u);
    EXPECT_EQ(c.voxel_entries_bus.transfers, 4u * 4u) << average;
    EXPECT_EQ(c.voxel_rows_bus.transfers, 4u * 4u) << average;
    EXPECT_EQ(c.units.size(), average ? 1u : 4u);
  }
}

}  // namespace
}  // namespace capsim::sim
