// The two screen formats of the machine: an 8-bit run (what a PNG needs) gives
// the same simulation and the sRGB encoding of the float run's screen.

#include "machine/machine.h"

#include "capsim/image/image_io.h"
#include "capsim/scene/parser.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

namespace capsim::sim {
namespace {

TEST(ScreenFormat, EightBitScreenIsTheEncodedFloatScreenAndTheSameRun) {
  PrepareOptions prep;
  prep.width = 45;
  prep.height = 38;
  const PreparedScene scene =
      prepare_scene(parse_scene_file(std::string(CAPSIM_SOURCE_DIR) + "/scenes/balls.csg"), prep);
  const Tracer tracer(scene, TraceOptions{});
  for (int depth : {0, 2})
    for (PixelMode mode : {PixelMode::Dot, PixelMode::Line, PixelMode::Block}) {
      MachineConfig config;
      config.cells = {3, 5};
      config.mode = mode;
      config.profile = load_cost_profile("cap");
      config.aa = {depth, 0.3};
      const SimulationResult floats = simulate_frame(tracer, config, 2, false);
      config.screen = ScreenFormat::Srgb8;
      const SimulationResult bytes = simulate_frame(tracer, config, 2, false);
      const std::string where = std::string(to_string(mode)) + " depth " + std::to_string(depth);
      EXPECT_EQ(bytes.timeline, floats.timeline) << where;
      EXPECT_EQ(bytes.frame, floats.frame) << where;
      ASSERT_EQ(bytes.cells.size(), floats.cells.size()) << where;
      for (std::size_t c = 0; c < bytes.cells.size(); ++c) {
        EXPECT_EQ(bytes.cells[c].busy, floats.cells[c].busy) << where << " cell " << c;
        EXPECT_EQ(bytes.cells[c].ops, floats.cells[c].ops) << where << " cell " << c;
      }
      ASSERT_EQ(bytes.screens[0].screen_srgb8.size(), 45u * 38u * 3u) << where;
      std::vector<PixelSample> row(1);
      for (std::size_t k = 0; k < 45u * 38u; ++k) {
        row[0].color = {floats.screens[0].screen.rgba[4 * k], floats.screens[0].screen.rgba[4 * k + 1], floats.screens[0].screen.rgba[4 * k + 2]};
        unsigned char rgb[3];
        encode_srgb8_row(row, rgb);
        ASSERT_EQ(0, std::memcmp(rgb, bytes.screens[0].screen_srgb8.data() + 3 * k, 3)) << where << " pixel " << k;
      }
      EXPECT_TRUE(bytes.screens[0].screen.rgba.empty());
      EXPECT_TRUE(bytes.screens[0].pixel_cycles.empty());
      EXPECT_EQ(floats.screens[0].pixel_cycles.size(), 45u * 38u);
    }
}

}  // namespace
}  // namespace capsim::sim
