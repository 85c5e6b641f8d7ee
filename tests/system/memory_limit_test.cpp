// The memory limits a run is checked against, and the buffer sizes it is
// estimated from.

#include "capsim/memory_limit.h"
#include "capsim/render.h"
#include "machine/machine.h"

#include <gtest/gtest.h>

using namespace capsim;

namespace {

TEST(MemoryLimit, MemAvailableIsReadInBytes) {
  const std::string meminfo =
      "MemTotal:       24683656 kB\nMemFree:        22911512 kB\nMemAvailable:   24223732 kB\nBuffers: 1 kB\n";
  EXPECT_EQ(meminfo_available(meminfo), std::optional<std::uint64_t>(24223732ull * 1024));
  EXPECT_EQ(meminfo_available("MemTotal: 5 kB\n"), std::nullopt);
  EXPECT_EQ(meminfo_available("MemAvailable: many kB\n"), std::nullopt);
}

TEST(MemoryLimit, CgroupPathsAreFoundForBothVersions) {
  const std::string v1 = "9:name=systemd:/\n4:memory:/jobs/42\n2:cpu,cpuacct:/\n";
  EXPECT_EQ(cgroup_v1_memory_path(v1), std::optional<std::string>("/jobs/42"));
  EXPECT_EQ(cgroup_v2_path(v1), std::nullopt);
  EXPECT_EQ(cgroup_v1_memory_path("3:cpuset,memory:/a\n"), std::optional<std::string>("/a"));
  EXPECT_EQ(cgroup_v1_memory_path("3:memory_x:/a\n"), std::nullopt);
  const std::string v2 = "0::/user.slice/session-1.scope\n";
  EXPECT_EQ(cgroup_v2_path(v2), std::optional<std::string>("/user.slice/session-1.scope"));
  EXPECT_EQ(cgroup_v1_memory_path(v2), std::nullopt);
}

TEST(MemoryLimit, TheTightestLimitWins) {
  EXPECT_EQ(tightest({}), std::nullopt);
  const std::optional<MemoryLimit> t = tightest({{300, "a"}, {100, "b"}, {200, "c"}});
  ASSERT_TRUE(t);
  EXPECT_EQ(t->bytes, 100u);
  EXPECT_EQ(t->source, "b");
}

TEST(MemoryLimit, ThisProcessHasTheAvailableMemoryAmongItsLimits) {
  bool found = false;
  for (const MemoryLimit& l : process_memory_limits())
    if (l.source == "of memory available (MemAvailable in /proc/meminfo)") found = l.bytes > 0;
  EXPECT_TRUE(found);
}

TEST(MemoryLimit, BytesAreFormattedInBinaryUnits) {
  EXPECT_EQ(format_bytes(1), "1 byte");
  EXPECT_EQ(format_bytes(1023), "1023 bytes");
  EXPECT_EQ(format_bytes(1024), "1.0 KiB");
  EXPECT_EQ(format_bytes(1536ull << 20), "1.5 GiB");
  EXPECT_EQ(format_bytes(16384ull * 16384 * 61), "15.2 GiB");
}

TEST(MemoryEstimate, FramebufferBytesAreWhatAFramebufferHolds) {
  const Framebuffer fb(37, 11);
  const std::uint64_t held = (fb.rgba.size() + fb.depth.size() + fb.id.size()) * sizeof(float);
  EXPECT_EQ(Framebuffer::bytes(37, 11), held);
}

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

}  // namespace
