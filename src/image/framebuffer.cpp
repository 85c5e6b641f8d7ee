#include "capsim/image/framebuffer.h"

#include <limits>

namespace capsim {

Framebuffer::Framebuffer(int w, int h)
    : width(w),
      height(h),
      rgba(static_cast<std::size_t>(w) * h * 4, 0.0f),
      depth(static_cast<std::size_t>(w) * h, std::numeric_limits<float>::infinity()),
      id(static_cast<std::size_t>(w) * h, -1.0f) {}

std::uint64_t Framebuffer::bytes(int w, int h) {
  return static_cast<std::uint64_t>(w) * static_cast<std::uint64_t>(h) * (4 + 1 + 1) * sizeof(float);
}

}  // namespace capsim
