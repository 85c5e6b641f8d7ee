// The memory limits a run is checked against.

#include "capsim/system/memory_limit.h"

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

}  // namespace
