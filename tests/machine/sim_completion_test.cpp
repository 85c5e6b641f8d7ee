// When each pixel reached the screen (FrameScreen::completion_cycles): a cell's
// pixels in video-memory order, each when its own operations' cycles have
// passed, the last exactly when the cell's tracing (antialiased, its
// subdivision) ends; in every mode, on several grids, in both screen formats,
// with antialiasing and over a sequence of frames.

#include "machine/machine.h"
#include "support/sequence_builders.h"

#include "capsim/scene/parser.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace capsim::sim {
namespace {

PreparedScene balls(int width, int height) {
  PrepareOptions prep;
  prep.width = width;
  prep.height = height;
  return prepare_scene(parse_scene_file(std::string(CAPSIM_SOURCE_DIR) + "/scenes/balls.csg"), prep);
}

MachineConfig config_of(CellGrid grid, PixelMode mode, int aa, ScreenFormat screen) {
  MachineConfig c;
  c.cells = grid;
  c.mode = mode;
  c.profile = load_cost_profile("cap");
  c.aa = {aa, 0.3};
  c.screen = screen;
  c.completion_cycles = true;
  return c;
}

// The span of a cell's track that writes frame `frame`'s pixels into video
// memory: "trace N pixels" (antialiased "subdivide N pixels"), with ", frame F"
// when the run has several frames.
const TimelineSpan& write_span(const SimulationResult& r, CellId cell, int frame) {
  const int track = 2 + cell;  // after the host and the bus
  const std::string verb = r.config.aa.depth > 0 ? "subdivide " : "trace ";
  const std::string suffix = r.screens.size() > 1 ? ", frame " + std::to_string(frame) : "";
  const std::string tail = " pixels" + suffix;
  for (const TimelineSpan& s : r.timeline.spans())
    if (s.track == track && s.name.starts_with(verb) && s.name.ends_with(tail)) return s;
  throw std::logic_error("no write span for cell " + std::to_string(cell));
}

// Checks, for every cell of a frame, that its pixels complete in video-memory
// order, strictly later each (every pixel costs at least a pixel write), the
// first after its span begins, the last exactly when its span ends.
void expect_cells_complete_in_video_order(const SimulationResult& r, const WindowLayout& layout, int frame,
                                          const std::string& what) {
  const std::vector<std::uint64_t>& done = r.screens.at(frame).completion_cycles;
  ASSERT_EQ(done.size(), static_cast<std::size_t>(r.width) * r.height) << what;
  for (CellId c = 0; c < layout.grid().cell_count(); ++c) {
    const CellWindow& w = layout.window(c);
    if (w.pixel_count() == 0) continue;
    const TimelineSpan& span = write_span(r, c, frame);
    std::uint64_t previous = span.begin.count();
    for (int k = 0; k < w.pixel_count(); ++k) {
      const ScreenPixel p = w.screen_pixel(k);
      const std::uint64_t t = done[static_cast<std::size_t>(p.y) * r.width + p.x];
      ASSERT_GT(t, previous) << what << " cell " << c << " pixel " << k;
      previous = t;
    }
    EXPECT_EQ(previous, span.end.count()) << what << " cell " << c;
  }
}

TEST(CompletionCycles, EachCellsPixelsCompleteInOrderAndTheLastWhenItsWritingEnds) {
  const PreparedScene scene = balls(45, 38);  // not a multiple of the grids
  const Tracer tracer(scene, TraceOptions{});
  for (PixelMode mode : {PixelMode::Dot, PixelMode::Line, PixelMode::Block})
    for (CellGrid grid : {CellGrid{1, 1}, CellGrid{3, 5}, CellGrid{8, 8}})
      for (int aa : {0, 1}) {
        const std::string what = std::string(to_string(mode)) + " " + to_string(grid) + " aa " + std::to_string(aa);
        const SimulationResult floats =
            simulate_frame(tracer, config_of(grid, mode, aa, ScreenFormat::Float), 2, false);
        const SimulationResult bytes =
            simulate_frame(tracer, config_of(grid, mode, aa, ScreenFormat::Srgb8), 2, false);
        const WindowLayout layout(mode, grid, 45, 38);
        expect_cells_complete_in_video_order(floats, layout, 0, what);
        // The screen format changes what video memory holds, not when.
        EXPECT_EQ(bytes.screens[0].completion_cycles, floats.screens[0].completion_cycles) << what;
        std::uint64_t last = 0;
        for (std::uint64_t t : floats.screens[0].completion_cycles) last = std::max(last, t);
        Cycles last_write;
        for (CellId c = 0; c < grid.cell_count(); ++c)
          if (layout.window(c).pixel_count() > 0) last_write = std::max(last_write, write_span(floats, c, 0).end);
        EXPECT_EQ(last, last_write.count()) << what;
      }
}

TEST(CompletionCycles, ConsecutivePixelsOfACellAreTheirOperationsCyclesApart) {
  // Without antialiasing a pixel's write step is its whole tracing: its
  // operation counts times the profile's costs, computed here independently.
  const PreparedScene scene = balls(30, 22);
  const Tracer tracer(scene, TraceOptions{});
  const MachineConfig config = config_of({3, 4}, PixelMode::Line, 0, ScreenFormat::Srgb8);
  const SimulationResult r = simulate_frame(tracer, config, 2, false);
  const WindowLayout layout(PixelMode::Line, config.cells, 30, 22);
  Tracer::Scratch scratch(scene);
  for (CellId c = 0; c < config.cells.cell_count(); ++c) {
    std::uint64_t t = write_span(r, c, 0).begin.count();
    const CellWindow& w = layout.window(c);
    for (int k = 0; k < w.pixel_count(); ++k) {
      const ScreenPixel p = w.screen_pixel(k);
      OpCounts ops;
      tracer.trace_pixel(p.x, p.y, scratch, ops);
      t += pixel_cost(ops, config.profile.costs).total().count();
      ASSERT_EQ(r.screens[0].completion_cycles[static_cast<std::size_t>(p.y) * 30 + p.x], t)
          << "cell " << c << " pixel " << k;
    }
  }
}

TEST(CompletionCycles, KeptOnlyWhenAsked) {
  const PreparedScene scene = balls(16, 16);
  const Tracer tracer(scene, TraceOptions{});
  MachineConfig config = config_of({2, 2}, PixelMode::Dot, 0, ScreenFormat::Srgb8);
  config.completion_cycles = false;
  const SimulationResult r = simulate_frame(tracer, config, 1, false);
  EXPECT_TRUE(r.screens[0].completion_cycles.empty());
  EXPECT_TRUE(r.screens[0].pixel_cycles.empty());
}


TEST(CompletionCycles, EveryFrameOfASequenceCompletesWhenItsWritingEnds) {
  const testing::FrameTracers frames = testing::moving_frames(5, 24, 20);
  const std::vector<const Tracer*>& list = frames.list;
  for (bool average : {false, true})
    for (int aa : {0, 1}) {
      MachineConfig config = config_of({2, 2}, PixelMode::Dot, aa, ScreenFormat::Srgb8);
      config.frame_average = average;
      const SimulationResult r = simulate_frames(list, config, 2, false);
      ASSERT_EQ(r.screens.size(), 5u);
      for (int f = 0; f < 5; ++f)
        expect_cells_complete_in_video_order(r, frame_layout(r.config, 24, 20, f), f,
                                             "frame " + std::to_string(f) + (average ? " averaged" : "") +
                                                 " aa " + std::to_string(aa));
    }
}

}  // namespace
}  // namespace capsim::sim
