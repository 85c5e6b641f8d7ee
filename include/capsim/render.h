#pragma once
// Renders every pixel of a prepared scene with the tracer (host threads via TBB;
// the result does not depend on the thread count).

#include "capsim/progress.h"
#include "capsim/tracer.h"

#include <vector>

namespace capsim {

struct Framebuffer {
  int width = 0, height = 0;
  std::vector<float> rgba;   // linear, 4 floats per pixel, row 0 at the top
  std::vector<float> depth;  // distance from the eye to the visible surface; +inf on a miss
  std::vector<float> id;     // 0-based visible primitive index in file order; -1 on a miss

  Framebuffer() = default;
  Framebuffer(int w, int h);
  void set(int i, int j, const PixelSample& s);
};

struct RenderStats {
  OpCounts ops;  // summed over every pixel
};

// threads: 0 = all hardware threads. progress, if given, advances by each
// finished row's pixels.
Framebuffer render(const Tracer& tracer, int threads, RenderStats* stats = nullptr,
                   Progress* progress = nullptr);

}  // namespace capsim
