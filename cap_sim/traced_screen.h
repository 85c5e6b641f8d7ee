#pragma once
// The tracing the cells will do, computed ahead of the event loop by host threads
// (tracing is pure, so the result does not depend on the thread count): every
// screen pixel's sample and its cost on a cell. The event loop then decides, in
// simulated time, when each cell does that work and writes each pixel.

#include "cost_profile.h"

#include "capsim/render.h"
#include "capsim/tracer.h"

#include <cstdint>
#include <vector>

namespace capsim::sim {

class Progress;

struct PixelWork {
  CostBreakdown cost;       // pixel_cost() of the pixel's operation counts
  std::uint64_t rays = 0;   // rays traced for the pixel, all kinds
};

struct TracedScreen {
  Framebuffer image;            // the samples, as Framebuffer::set stores them
  std::vector<PixelWork> work;  // row-major, row 0 at the top

  const PixelWork& work_at(int x, int y) const {
    return work[static_cast<std::size_t>(y) * image.width + x];
  }
};

// threads: 0 = all hardware threads. progress may be null.
TracedScreen trace_screen(const Tracer& tracer, const CellCosts& costs, int threads,
                          Progress* progress);

}  // namespace capsim::sim
