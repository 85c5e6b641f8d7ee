// The bytes a framebuffer's estimate counts are those it holds.

#include "capsim/image/framebuffer.h"

#include <gtest/gtest.h>

namespace capsim {
namespace {

TEST(MemoryEstimate, FramebufferBytesAreWhatAFramebufferHolds) {
  const Framebuffer fb(37, 11);
  const std::uint64_t held = (fb.rgba.size() + fb.depth.size() + fb.id.size()) * sizeof(float);
  EXPECT_EQ(Framebuffer::bytes(37, 11), held);
}

}  // namespace
}  // namespace capsim
