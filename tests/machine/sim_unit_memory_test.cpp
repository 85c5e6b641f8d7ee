// What a cell holds for a distribution unit: its memory (program, every
// frame's scene and voxel data) and its video memory, checked against the
// profile; how many frames a frame-averaged unit holds.

#include "machine/parts/corner_exchange.h"
#include "machine/machine.h"
#include "machine/unit_memory.h"
#include "support/sequence_builders.h"

#include "capsim/trace/antialias.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace capsim::sim {
namespace {

// A frame whose scene and voxel data take `bytes` (all of it counted as
// voxel data).
SceneFootprint frame_of(std::uint64_t bytes) {
  SceneFootprint f;
  f.voxel_grid = bytes;
  return f;
}

MachineConfig averaged(CellGrid grid, int aa = 0) {
  MachineConfig c;
  c.cells = grid;
  c.profile = load_cost_profile("cap");
  c.aa = {aa, 0.3};
  c.frame_average = true;
  return c;
}

std::string refusal(const UnitMemory& u, const CostProfile& profile) {
  try {
    check_unit_memory(u, profile);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(UnitMemory, AUnitOverTheCellMemoryIsRefusedWithItsNumbers) {
  // Four frames of 300,000 bytes each fit one by one, not together: the host
  // broadcasts all four before "start".
  MachineConfig config = averaged({2, 2});
  config.frame_average_group = 4;
  const std::vector<SceneFootprint> frames(6, frame_of(300'000));
  const std::vector<UnitMemory> units = unit_memories(frames, config, 8, 8);
  ASSERT_EQ(units.size(), 2u);
  EXPECT_EQ(units[1].first_frame, 4);
  EXPECT_EQ(units[1].frames, 2);
  const std::string what = refusal(units[0], config.profile);
  EXPECT_EQ(what,
            "distribution unit 0 (frames 0 to 3) does not fit a cell's memory: it needs 1265536 bytes (program "
            "65536 + scene 0 + voxel data 1200000, its 4 frames) but a cell of profile 'cap' has 1048576 bytes; "
            "try a coarser --grid");
  EXPECT_EQ(refusal(units[1], config.profile), "");  // 65,536 + 600,000 bytes fit
}

// When the program and the scene alone are over the cell memory, no grid
// helps: the advice says so, with what the scene alone needs.
TEST(UnitMemory, AScenePastTheCellMemoryWithoutAnyGridIsNotToldToCoarsenTheGrid) {
  MachineConfig config;
  config.profile = load_cost_profile("cap");  // 1048576 bytes, program 65536
  SceneFootprint big;
  big.primitives = 1'000'000;
  big.voxel_grid = 100;
  const std::vector<UnitMemory> one = unit_memories({big}, config, 8, 8);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(refusal(one[0], config.profile),
            "distribution unit 0 (frame 0) does not fit a cell's memory: it needs 1065636 bytes (program 65536 + "
            "scene 1000000 + voxel data 100) but a cell of profile 'cap' has 1048576 bytes; the program and the "
            "scene alone need 1065536 bytes, without any voxel grid, so a coarser --grid cannot help; use a "
            "profile with more cell memory (--profile) or a scene of fewer primitives");
  // 900,000 bytes of scene leave room for a coarser grid's voxel data.
  big.primitives = 900'000;
  big.voxel_grid = 100'000;
  const std::string what = refusal(unit_memories({big}, config, 8, 8)[0], config.profile);
  EXPECT_NE(what.find("; try a coarser --grid"), std::string::npos) << what;
  // Frames averaged together: their scenes are summed, and fewer of them help.
  SceneFootprint half;
  half.primitives = 600'000;
  config = averaged({2, 2});
  config.frame_average_group = 2;
  const std::string two = refusal(unit_memories({half, half}, config, 8, 8)[0], config.profile);
  EXPECT_NE(two.find("the program and the scenes of its frames alone need 1265536 bytes, without any voxel grid, "
                     "so a coarser --grid cannot help; put fewer frames in a unit, use a profile with more cell "
                     "memory (--profile)"),
            std::string::npos)
      << two;
}

TEST(UnitMemory, AUnitOverTheVideoMemoryIsRefusedWithItsNumbers) {
  MachineConfig config = averaged({2, 2});
  config.frame_average_group = 4;
  config.profile.video_memory_bytes = 100;
  // 8 x 8 pixels on 2 x 2 cells: 16 pixels of 3 bytes a cell and frame.
  const std::vector<UnitMemory> units = unit_memories(std::vector<SceneFootprint>(4, frame_of(10)), config, 8, 8);
  ASSERT_EQ(units.size(), 1u);
  EXPECT_EQ(units[0].video_memory, 4u * 16 * kVideoPixelBytes);
  EXPECT_EQ(refusal(units[0], config.profile),
            "distribution unit 0 (frames 0 to 3) does not fit a cell's video memory: a cell needs 192 bytes for "
            "its pixels of its 4 frames but a cell of profile 'cap' has 100 bytes of video memory; try more "
            "--cells or a smaller --size");
  config.profile.video_memory_bytes = 192;
  EXPECT_EQ(refusal(units[0], config.profile), "");
}

TEST(UnitMemory, FramesPerUnitIsWhatFitsRoundedDownToWholeRows) {
  // 2 x 3 cells: a unit holds 6, 4, 2 or 1 frames. Each frame 100,000 bytes.
  const CellGrid grid{2, 3};
  const std::vector<SceneFootprint> frames(12, frame_of(100'000));
  MachineConfig config = averaged(grid);
  const std::uint64_t program = config.profile.program_bytes;
  for (const auto& [fit, group] : {std::pair{9, 6}, std::pair{6, 6}, std::pair{5, 4}, std::pair{4, 4},
                                   std::pair{3, 2}, std::pair{2, 2}, std::pair{1, 1}}) {
    config.profile.cell_memory_bytes = program + static_cast<std::uint64_t>(fit) * 100'000;
    EXPECT_EQ(frames_per_unit(frames, config, 6, 4), group) << fit << " frames fit";
  }
  config.profile.cell_memory_bytes = program + 99'999;
  EXPECT_THROW(frames_per_unit(frames, config, 6, 4), std::runtime_error);
  // Fewer frames than a group: one unit of all of them.
  config.profile.cell_memory_bytes = program + 5 * 100'000;
  EXPECT_EQ(frames_per_unit(std::vector<SceneFootprint>(5, frame_of(100'000)), config, 6, 4), 6);
  // Without frame averaging every unit is one frame.
  config.frame_average = false;
  EXPECT_EQ(frames_per_unit(frames, config, 6, 4), 1);
}

TEST(UnitMemory, FramesPerUnitFollowsTheLargestUnitAndTheVideoMemory) {
  MachineConfig config = averaged({2, 2});  // units of 4, 2 or 1
  const std::uint64_t program = config.profile.program_bytes;
  config.profile.cell_memory_bytes = program + 400;
  // Frames 4 to 7 together need 500 bytes: units of 4 do not fit, of 2 do.
  std::vector<SceneFootprint> frames(8, frame_of(100));
  frames[5] = frame_of(200);
  EXPECT_EQ(frames_per_unit(frames, config, 8, 8), 2);
  // 16 pixels of 3 bytes a cell and frame: 3 frames' worth holds a unit of 2.
  frames[5] = frame_of(100);
  config.profile.video_memory_bytes = 3 * 16 * kVideoPixelBytes;
  EXPECT_EQ(frames_per_unit(frames, config, 8, 8), 2);
  config.profile.video_memory_bytes = 16 * kVideoPixelBytes - 1;
  EXPECT_THROW(frames_per_unit(frames, config, 8, 8), std::runtime_error);
}

TEST(UnitMemory, AntialiasedVideoMemoryHoldsOwnedAndNeededCorners) {
  for (const CellGrid grid : {CellGrid{2, 3}, CellGrid{3, 3}, CellGrid{1, 1}}) {
    const WindowLayout layout(PixelMode::Dot, grid, 13, 10, dot_shift_for_frame(grid, 1));
    const std::vector<std::uint64_t> bytes = frame_video_memory(layout, true);
    const CornerExchange exchange(layout);
    for (CellId c = 0; c < grid.cell_count(); ++c) {
      const CellWindow& w = layout.window(c);
      std::uint64_t owned = 0;
      for (int k = 0; k < w.pixel_count(); ++k)
        owned += owned_corner_count(w.screen_pixel(k).x, w.screen_pixel(k).y, 13, 10);
      EXPECT_EQ(bytes[c], w.pixel_count() * kVideoPixelBytes + (owned + exchange.needs(c).size()) * kScreenSampleBytes)
          << to_string(grid) << " cell " << c;
    }
  }
}

TEST(UnitMemory, TheRunReportsWhatItChecked) {
  const testing::FrameTracers frames = testing::moving_frames(6, 24, 16, 6, 4);
  MachineConfig config = averaged({2, 2}, 1);
  const SimulationResult run = simulate_frames(frames.list, config, 2, false);
  EXPECT_EQ(run.config.frame_average_group, 4);
  std::vector<SceneFootprint> footprints;
  for (const Tracer* t : frames.list) footprints.push_back(scene_footprint(t->scene()));
  const std::vector<UnitMemory> units = unit_memories(footprints, run.config, 24, 16);
  ASSERT_EQ(run.units.size(), units.size());
  for (std::size_t u = 0; u < units.size(); ++u) {
    EXPECT_EQ(run.units[u].cell_memory_bytes, static_cast<std::uint64_t>(units[u].cell_memory));
    EXPECT_EQ(run.units[u].video_memory_bytes, units[u].video_memory);
  }
  // The same frames in units of 2 when the video memory holds only 2 or 3.
  config.profile.video_memory_bytes = run.units[0].video_memory_bytes - 1;
  const SimulationResult smaller = simulate_frames(frames.list, config, 2, false);
  EXPECT_EQ(smaller.config.frame_average_group, 2);
  EXPECT_EQ(smaller.units.size(), 3u);
}

}  // namespace
}  // namespace capsim::sim
