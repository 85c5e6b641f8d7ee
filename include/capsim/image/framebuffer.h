#pragma once
// A float image: linear colour and coverage, depth and primitive id per pixel
// (what an EXR output holds).

#include <cstdint>
#include <vector>

namespace capsim {

struct Framebuffer {
  int width = 0, height = 0;
  std::vector<float> rgba;   // linear, 4 floats per pixel, row 0 at the top
  std::vector<float> depth;  // distance from the eye to the visible surface; +inf on a miss
  std::vector<float> id;     // 0-based visible primitive index in file order; -1 on a miss

  Framebuffer() = default;
  Framebuffer(int w, int h);

  // The bytes the buffers of a w x h framebuffer hold.
  static std::uint64_t bytes(int w, int h);
};

}  // namespace capsim
