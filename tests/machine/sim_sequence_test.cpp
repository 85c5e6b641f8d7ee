// Runs of several frames: the frame-averaged dot patterns, the barrier between
// frames, the groups of frame averaging, and determinism.

#include "machine/machine.h"
#include "machine/unit_memory.h"
#include "machine/run_figures.h"
#include "support/sequence_builders.h"

#include "capsim/scene/parser.h"
#include "capsim/trace/render.h"

#include <fmt/core.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <memory>
#include <set>
#include <string>

namespace capsim::sim {
namespace {

TEST(FrameAveraging, EveryCellOwnsEveryPositionOnceInAnyRxCConsecutiveFrames) {
  for (const CellGrid grid : {CellGrid{1, 1}, CellGrid{2, 3}, CellGrid{3, 5}, CellGrid{8, 8}, CellGrid{4, 1}}) {
    const int n = grid.cell_count();
    for (int first : {0, 1, n - 1, n + 2}) {
      for (CellId c = 0; c < n; ++c) {
        std::set<std::pair<int, int>> positions;
        for (int f = first; f < first + n; ++f) {
          MachineConfig config;
          config.cells = grid;
          config.frame_average = true;
          const WindowLayout layout = frame_layout(config, 2 * grid.cols, 2 * grid.rows, f);
          const ScreenPixel p = layout.window(c).screen_pixel(0);  // its position in the first square
          positions.insert({p.y % grid.rows, p.x % grid.cols});
        }
        EXPECT_EQ(static_cast<int>(positions.size()), n)
            << to_string(grid) << " cell " << c << " frames " << first << " on";
      }
    }
  }
}

TEST(FrameAveraging, FrameKOfAUnitShiftsThePatternDiagonally) {
  // Rows by k mod R, columns by (k mod R + k div R) mod C.
  const CellGrid g23{2, 3};
  const std::vector<DotShift> expected = {{0, 0}, {1, 1}, {0, 1}, {1, 2}, {0, 2}, {1, 0}};
  for (int k = 0; k < 6; ++k) EXPECT_EQ(dot_shift_for_frame(g23, k), expected[k]) << k;
  EXPECT_EQ(dot_shift_for_frame(g23, 6), (DotShift{0, 0}));
  const CellGrid g88{8, 8};
  EXPECT_EQ(dot_shift_for_frame(g88, 7), (DotShift{7, 7}));
  EXPECT_EQ(dot_shift_for_frame(g88, 8), (DotShift{0, 1}));
  EXPECT_EQ(dot_shift_for_frame(g88, 63), (DotShift{7, 6}));
  // Any R frames from k = jR move every cell over R different rows and R
  // different columns of the square; a unit of a few multiples of R, fewer
  // than R x C, spreads each pixel over as many cells as it has frames.
  for (const CellGrid grid : {CellGrid{2, 3}, CellGrid{3, 5}, CellGrid{8, 8}, CellGrid{4, 2}})
    for (int j = 0; j < grid.cols; ++j) {
      std::set<int> rows, cols;
      for (int k = j * grid.rows; k < (j + 1) * grid.rows; ++k) {
        rows.insert(dot_shift_for_frame(grid, k).rows);
        cols.insert(dot_shift_for_frame(grid, k).cols);
      }
      EXPECT_EQ(static_cast<int>(rows.size()), grid.rows) << to_string(grid) << " " << j;
      EXPECT_EQ(static_cast<int>(cols.size()), std::min(grid.rows, grid.cols)) << to_string(grid) << " " << j;
    }
}

TEST(FrameAveraging, ShiftedLayoutsGiveEveryPixelOneOwnerAndInvertTheirWindows) {
  for (const CellGrid grid : {CellGrid{2, 3}, CellGrid{3, 5}, CellGrid{4, 4}})
    for (int f = 0; f < grid.cell_count(); ++f)
      for (const auto& [w, h] : {std::pair{13, 11}, std::pair{2, 1}, std::pair{16, 16}}) {
        const WindowLayout layout(PixelMode::Dot, grid, w, h, dot_shift_for_frame(grid, f));
        std::vector<int> seen(static_cast<std::size_t>(w) * h, 0);
        for (CellId c = 0; c < grid.cell_count(); ++c)
          for (int k = 0; k < layout.window(c).pixel_count(); ++k) {
            const ScreenPixel p = layout.window(c).screen_pixel(k);
            ASSERT_TRUE(p.x < w && p.y < h);
            ++seen[static_cast<std::size_t>(p.y) * w + p.x];
            ASSERT_EQ(layout.owner(p), (PixelOwner{c, k})) << to_string(grid) << " frame " << f;
          }
        for (int s : seen) ASSERT_EQ(s, 1) << to_string(grid) << " frame " << f;
      }
}


MachineConfig config_of(CellGrid grid, int aa, bool average) {
  MachineConfig c;
  c.cells = grid;
  c.mode = PixelMode::Dot;
  c.profile = load_cost_profile("cap");
  c.aa = {aa, 0.3};
  c.frame_average = average;
  return c;
}

TEST(Sequence, WithABarrierEachFrameTakesItsOwnRunLessTheProgramBroadcast) {
  const testing::FrameTracers frames = testing::moving_frames(3, 40, 30, 6, 4);
  const MachineConfig config = config_of({4, 4}, 0, false);
  const SimulationResult run = simulate_frames(frames.list, config, 2, false);
  ASSERT_EQ(run.units.size(), 3u);
  const CostProfile& p = config.profile;
  const Cycles program = p.bus.arbitration + p.bus_data_cycles(p.program_bytes) + p.bus.latency;
  Cycles start;
  for (int k = 0; k < 3; ++k) {
    const SimulationResult alone = simulate_frame(*frames.list[k], config, 2, false);
    EXPECT_EQ(run.units[k].start, start) << k;
    EXPECT_EQ(run.units[k].end - run.units[k].start, k == 0 ? alone.frame : alone.frame - program) << k;
    if (k == 0) {
      EXPECT_EQ(frame_spreads(run)[0].deviation_percent, load_spread(alone).deviation_percent);
    }
    start = run.units[k].end;
  }
  EXPECT_EQ(run.frame, run.units.back().end);
}

TEST(Sequence, FrameAveragedScreensAreTheRenderedFrames) {
  const testing::FrameTracers frames = testing::moving_frames(5, 23, 17, 6, 4);
  for (int aa : {0, 1}) {
    const SimulationResult run = simulate_frames(frames.list, config_of({2, 3}, aa, true), 2, false);
    ASSERT_EQ(run.screens.size(), 5u);
    ASSERT_EQ(run.units.size(), 1u);  // a group of 6 frames holds all 5
    for (int k = 0; k < 5; ++k) {
      const Framebuffer rendered = render(*frames.list[k], 2, nullptr, nullptr, {aa, 0.3});
      EXPECT_EQ(0, std::memcmp(rendered.rgba.data(), run.screens[k].screen.rgba.data(),
                               rendered.rgba.size() * sizeof(float)))
          << "frame " << k << " aa " << aa;
    }
  }
}

TEST(Sequence, FrameAveragingGroupsRxCFramesAndEvensTheLoad) {
  // Antialiasing puts the work on the moving edges. With a barrier per frame
  // every frame's slowest cell counts; averaged over a group with the pattern
  // turned, each cell's total is nearly the mean.
  const testing::FrameTracers frames = testing::moving_frames(8, 48, 32, 6, 4);
  const SimulationResult plain = simulate_frames(frames.list, config_of({2, 2}, 1, false), 2, false);
  const SimulationResult averaged = simulate_frames(frames.list, config_of({2, 2}, 1, true), 2, false);
  ASSERT_EQ(averaged.units.size(), 2u);
  EXPECT_EQ(averaged.units[0].frames, 4);
  EXPECT_EQ(averaged.units[1].first_frame, 4);
  EXPECT_LT(averaged.frame, plain.frame);
  EXPECT_LT(max_deviation_percent(averaged), max_deviation_percent(plain));
  // The same pixels and rays in all, however they were distributed.
  std::uint64_t rays_plain = 0, rays_averaged = 0;
  for (const CellReport& c : plain.cells) rays_plain += c.rays;
  for (const CellReport& c : averaged.cells) rays_averaged += c.rays;
  EXPECT_EQ(rays_plain, rays_averaged);
  EXPECT_GT(averaged.units[0].video_memory_bytes, 4u * (48 * 32 / 4) * kVideoPixelBytes);
}

TEST(Sequence, TimelinesDoNotDependOnHostThreads) {
  const testing::FrameTracers frames = testing::moving_frames(4, 32, 24, 6, 4);
  for (bool average : {false, true}) {
    const MachineConfig config = config_of({2, 2}, 1, average);
    const SimulationResult one = simulate_frames(frames.list, config, 1, false);
    const SimulationResult two = simulate_frames(frames.list, config, 2, false);
    EXPECT_EQ(one.timeline, two.timeline);
    EXPECT_EQ(one.events, two.events);
  }
}

TEST(Sequence, FrameAveragingNeedsDotMode) {
  const testing::FrameTracers frames = testing::moving_frames(2, 8, 8, 6, 4);
  MachineConfig config = config_of({2, 2}, 0, true);
  config.mode = PixelMode::Line;
  EXPECT_THROW(simulate_frames(frames.list, config, 1, false), std::invalid_argument);
}

}  // namespace
}  // namespace capsim::sim

namespace capsim::sim {
namespace {

// scenes/disb: the 64 frames OpenSCAD exported from scenes/disb.scad.
struct Disb {
  std::vector<PreparedScene> scenes;
  std::vector<std::unique_ptr<Tracer>> tracers;
  std::vector<const Tracer*> list;
  explicit Disb(int size) {
    PrepareOptions o;
    o.width = o.height = size;
    for (int k = 0; k < 64; ++k)
      scenes.push_back(prepare_scene(
          parse_scene_file(fmt::format("{}/scenes/disb/f{:05d}.csg", CAPSIM_SOURCE_DIR, k)), o));
    for (const PreparedScene& s : scenes) tracers.push_back(std::make_unique<Tracer>(s, TraceOptions{}));
    for (const auto& t : tracers) list.push_back(t.get());
  }
};

TEST(Sequence, DisbHasTheShapeOfTable45) {
  // The paper, 64 frames of DISB on 8x8 cells in dot mode: 1336 s / 6.5 %
  // without antialiasing, 4626 s / 60.4 % with it, 2595 s / 8.8 % frame
  // averaged. Here at 384 x 384 pixels, the screen DISB is laid out for, with
  // --aa 2: the runs of docs/animation.md (3.49 times as long antialiased,
  // d 66.9 %, frame averaging 4.6 % and 48.8 % saved).
  const Disb disb(384);
  const SimulationResult plain = simulate_frames(disb.list, config_of({8, 8}, 0, false), 2, false);
  const SimulationResult aa = simulate_frames(disb.list, config_of({8, 8}, 2, false), 2, false);
  const SimulationResult averaged = simulate_frames(disb.list, config_of({8, 8}, 2, true), 2, false);
  const double time_ratio = aa.frame.seconds(1) / plain.frame.seconds(1);
  EXPECT_GE(time_ratio, 2.0);
  EXPECT_LE(time_ratio, 5.0);
  EXPECT_GE(max_deviation_percent(aa), 40.0);
  EXPECT_GE(max_deviation_percent(aa), 5 * max_deviation_percent(plain));
  // A CAP cell's 1 MiB of video memory holds 8 antialiased frames' pixels and
  // corner samples at 384 x 384: units of 8 (one turn of the 8 rows).
  EXPECT_EQ(averaged.config.frame_average_group, 8);
  EXPECT_LT(max_deviation_percent(averaged), 10.0);
  EXPECT_LT(averaged.frame.seconds(1), 0.7 * aa.frame.seconds(1));  // saves at least 30 %
  // The figures, exactly (simulated cycles are deterministic).
  EXPECT_EQ(plain.frame, Cycles(14'183'069'150));
  EXPECT_EQ(aa.frame, Cycles(49'486'611'200));
  EXPECT_EQ(averaged.frame, Cycles(25'324'685'372));
}

}  // namespace
}  // namespace capsim::sim
