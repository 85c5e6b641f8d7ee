// The reports of a run (text, JSON) are the same bytes whatever the host's
// threads and the screen's format, for one frame, antialiased and sequences;
// and they hold what each kind of run adds.

#include "machine/machine.h"
#include "report/sim_report.h"
#include "support/sequence_builders.h"

#include "capsim/scene/parser.h"

#include <gtest/gtest.h>

#include <string>

namespace capsim::sim {
namespace {

PreparedScene balls(int width, int height) {
  PrepareOptions prep;
  prep.width = width;
  prep.height = height;
  return prepare_scene(parse_scene_file(std::string(CAPSIM_SOURCE_DIR) + "/scenes/balls.csg"), prep);
}

MachineConfig config_of(CellGrid grid, PixelMode mode, int depth) {
  MachineConfig c;
  c.cells = grid;
  c.mode = mode;
  c.profile = load_cost_profile("cap");
  c.aa = {depth, 0.3};
  return c;
}

TEST(Reports, OneFrameDoesNotDependOnHostThreads) {
  const PreparedScene scene = balls(96, 64);
  const Tracer tracer(scene, TraceOptions{});
  for (int depth : {0, 2}) {
    const MachineConfig config = config_of({8, 8}, PixelMode::Dot, depth);
    const SimulationResult one = simulate_frame(tracer, config, 1, false);
    const SimulationResult two = simulate_frame(tracer, config, 2, false);
    EXPECT_EQ(report_json(one).dump(), report_json(two).dump()) << depth;
    EXPECT_EQ(format_report(one), format_report(two)) << depth;
    EXPECT_EQ(chrome_trace_text(one), chrome_trace_text(two)) << depth;
  }
}

TEST(Reports, EightBitAndFloatScreensGiveTheSameReport) {
  const PreparedScene scene = balls(45, 38);
  const Tracer tracer(scene, TraceOptions{});
  for (int depth : {0, 2})
    for (PixelMode mode : {PixelMode::Dot, PixelMode::Line, PixelMode::Block}) {
      MachineConfig config = config_of({3, 5}, mode, depth);
      const SimulationResult floats = simulate_frame(tracer, config, 2, false);
      config.screen = ScreenFormat::Srgb8;
      const SimulationResult bytes = simulate_frame(tracer, config, 2, false);
      EXPECT_EQ(report_json(bytes).dump(), report_json(floats).dump()) << to_string(mode) << " depth " << depth;
    }
}

TEST(Reports, SequencesDoNotDependOnHostThreads) {
  const testing::FrameTracers frames = testing::moving_frames(4, 32, 24, 6, 4);
  for (bool average : {false, true}) {
    MachineConfig config = config_of({2, 2}, PixelMode::Dot, 1);
    config.frame_average = average;
    const SimulationResult one = simulate_frames(frames.list, config, 1, false);
    const SimulationResult two = simulate_frames(frames.list, config, 2, false);
    EXPECT_EQ(report_json(one).dump(), report_json(two).dump());
    EXPECT_EQ(format_report(one), format_report(two));
    const nlohmann::json report = report_json(one);
    EXPECT_EQ(report["frames"].size(), 4u);
    EXPECT_EQ(report["sequence"]["frame_average"], average);
    EXPECT_NE(format_report(one).find("Table 4-5 form, 4 frames"), std::string::npos);
  }
}

TEST(Reports, AntialiasedRunsAddLinksAndPhases) {
  const PreparedScene scene = balls(128, 128);
  const Tracer tracer(scene, TraceOptions{});
  const SimulationResult plain = simulate_frame(tracer, config_of({8, 8}, PixelMode::Dot, 0), 2, false);
  const SimulationResult aa = simulate_frame(tracer, config_of({8, 8}, PixelMode::Dot, 2), 2, false);
  const nlohmann::json report = report_json(aa);
  EXPECT_EQ(report["link_totals"]["messages"], 128);
  EXPECT_TRUE(report["cells"][0].contains("subdivide_cycles"));
  EXPECT_FALSE(report_json(plain).contains("links"));
}

}  // namespace
}  // namespace capsim::sim
