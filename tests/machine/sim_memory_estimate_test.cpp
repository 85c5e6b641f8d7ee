// The memory a simulation's image buffers take, per pixel, as the estimate
// checked before a run counts it.

#include "capsim/image/image_io.h"
#include "machine/machine.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace capsim {
namespace {

TEST(MemoryEstimate, SimulateHoldsWhatEachScreenFormatNeedsPerPixel) {
  sim::MachineConfig config;
  // An 8-bit screen: video memory (3) and screen (3) per frame, owner counts (1).
  config.screen = sim::ScreenFormat::Srgb8;
  EXPECT_EQ(sim::simulation_memory(config, 640, 480, 1), 640u * 480 * 7);
  EXPECT_EQ(sim::simulation_memory(config, 640, 480, 4), 640u * 480 * (4 * 6 + 1));
  // Floats: traced samples (24) and cycles (8), the screen (24) and its float
  // cycles (4), owner counts (1).
  config.screen = sim::ScreenFormat::Float;
  EXPECT_EQ(sim::simulation_memory(config, 640, 480, 1), 640u * 480 * 61);
  // Antialiased: also samples per pixel (4 + 4), one frame's corners (24 and
  // 8 for their cycles) and the running unit's exchange plan (3 x 12 a pixel
  // of its frames).
  config.aa.depth = 2;
  EXPECT_EQ(sim::simulation_memory(config, 640, 480, 1), 640u * 480 * (69 + 3 * 12) + 641u * 481 * 32);
  // Sixty-four frames with a barrier per frame: one frame's plan at a time.
  config.screen = sim::ScreenFormat::Srgb8;
  const std::uint64_t per_frame = 640u * 480 * (64 * 6 + 1) + 641u * 481 * 24;
  EXPECT_EQ(sim::simulation_memory(config, 640, 480, 64), per_frame + 640u * 480 * 3 * 12);
  // Frame averaged on 8x8 cells: a unit is 64 frames, planned at once.
  config.frame_average = true;
  EXPECT_EQ(sim::simulation_memory(config, 640, 480, 64), per_frame + 64 * 640u * 480 * 3 * 12);
  // Keeping every corner taken in, for tests: 3 x 4 a pixel of every frame.
  config.keep_received_corners = true;
  EXPECT_EQ(sim::simulation_memory(config, 640, 480, 64),
            per_frame + 64 * 640u * 480 * 3 * 12 + 64 * 640u * 480 * 3 * 4);
}

TEST(MemoryEstimate, UntilWrittenAddsWritingTheScreensToTheirFiles) {
  sim::MachineConfig config;
  const std::uint64_t pixels = 640u * 480;
  // PNG: the result's 8-bit screen (3) and the compressor's buffers, more
  // than the simulation's own peak (7 a pixel).
  config.screen = sim::ScreenFormat::Srgb8;
  const std::uint64_t png = 3 * pixels + write_png_rgb8_memory(640, 480);
  EXPECT_EQ(sim::simulation_memory_until_written(config, 640, 480, 1),
            std::max<std::uint64_t>(sim::simulation_memory(config, 640, 480, 1), png));
  EXPECT_GT(png, sim::simulation_memory(config, 640, 480, 1));
  // EXR: the result (28 a pixel), the cycles copied into a channel (4) and the
  // planes of all channels; the peak (61) is still larger.
  config.screen = sim::ScreenFormat::Float;
  const std::uint64_t exr = 28 * pixels + 4 * pixels + write_image_memory(".exr", 640, 480, 1);
  EXPECT_EQ(exr, 60 * pixels);
  EXPECT_EQ(sim::simulation_memory_until_written(config, 640, 480, 1), 61 * pixels);
  EXPECT_EQ(sim::simulation_memory_until_written(config, 640, 480, 3), sim::simulation_memory(config, 640, 480, 3));
  // Antialiased EXR: also the samples, in the result (4) and as a channel (4),
  // one more plane (4).
  config.aa.depth = 1;
  const std::uint64_t exr_aa = 32 * pixels + 8 * pixels + write_image_memory(".exr", 640, 480, 2);
  EXPECT_EQ(exr_aa, 72 * pixels);
  EXPECT_EQ(sim::simulation_memory_until_written(config, 640, 480, 1),
            std::max<std::uint64_t>(sim::simulation_memory(config, 640, 480, 1), exr_aa));
}

}  // namespace
}  // namespace capsim
