#pragma once
// A float image: linear colour and coverage, depth and primitive id per pixel
// (what an EXR output holds).

#include "capsim/system/huge_pages.h"

#include <cstdint>

namespace capsim {

struct Framebuffer {
  int width = 0, height = 0;
  // On huge pages where large (huge_pages.h): 24 MiB at 1024 x 1024, which
  // in small pages took some 6,000 page faults to fill (docs/performance.md).
  LargeVector<float> rgba;   // linear, 4 floats per pixel, row 0 at the top
  LargeVector<float> depth;  // distance from the eye to the visible surface; +inf on a miss
  LargeVector<float> id;     // 0-based visible primitive index in file order; -1 on a miss

  Framebuffer() = default;
  Framebuffer(int w, int h);

  // The bytes the buffers of a w x h framebuffer hold.
  static std::uint64_t bytes(int w, int h);
};

}  // namespace capsim
