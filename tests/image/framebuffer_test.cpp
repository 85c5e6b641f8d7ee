// The bytes a framebuffer's estimate counts are those it holds, and where a
// large one keeps them.

#include "capsim/image/framebuffer.h"
#include "capsim/system/huge_pages.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

namespace capsim {
namespace {

TEST(MemoryEstimate, FramebufferBytesAreWhatAFramebufferHolds) {
  const Framebuffer fb(37, 11);
  const std::uint64_t held = (fb.rgba.size() + fb.depth.size() + fb.id.size()) * sizeof(float);
  EXPECT_EQ(Framebuffer::bytes(37, 11), held);
}

// Each array of a 1024 x 1024 framebuffer (4, 4 and 16 MiB) is a mapping of
// its own on a huge page boundary (huge_page_resource), never heap pages,
// and holds the starting values.
TEST(Framebuffer, ALargeOnesArraysLieOnHugePages) {
  const Framebuffer fb(1024, 1024);
  const std::uintptr_t huge = huge_page_bytes();
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(fb.rgba.data()) % huge, 0u);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(fb.depth.data()) % huge, 0u);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(fb.id.data()) % huge, 0u);
  EXPECT_EQ(fb.rgba.back(), 0.0f);
  EXPECT_TRUE(std::isinf(fb.depth.back()));
  EXPECT_EQ(fb.id.back(), -1.0f);
}

}  // namespace
}  // namespace capsim
