#pragma once
// The video bus: the screen is the composition of every cell's video memory,
// each placed by its window controller. Every screen pixel must come from exactly
// one cell; composition checks it.

#include "machine/parts/window_controller.h"

#include "capsim/trace/render.h"

#include <tbb/parallel_for.h>

#include <cstddef>
#include <vector>

namespace capsim::sim {

// Calls put(c, k, s) for every pixel k of every cell c's window, where s is that
// pixel's row-major index on the screen. Cells run in parallel, one thread per
// cell taking its pixels in order k = 0, 1, ..., so put may write only what
// belongs to screen pixel s or to cell c (windows never overlap in a valid
// layout; compose_screen checks that).
template <class Put>
void for_each_window_pixel(const WindowLayout& layout, Put put) {
  tbb::parallel_for(0, layout.grid().cell_count(), [&](CellId c) {
    // Row by row through the window: the same pixels in the same order as
    // screen_pixel(k) for k = 0, 1, ..., without a division per pixel.
    const CellWindow& w = layout.window(c);
    int k = 0;
    for (int r = 0; r < w.rows(); ++r) {
      std::size_t s = static_cast<std::size_t>(w.origin_y() + r * w.stride_y()) * layout.width() + w.origin_x();
      for (int col = 0; col < w.columns(); ++col, ++k, s += static_cast<std::size_t>(w.stride_x())) put(c, k, s);
    }
  });
}

// video[c] holds cell c's pixels: pixel k at (k, 0). Throws std::logic_error if a
// screen pixel is written twice or never, or a video memory has the wrong size.
Framebuffer compose_screen(const WindowLayout& layout, const std::vector<const Framebuffer*>& video);

// The same for 8-bit sRGB video memories (pixel k at bytes 3k .. 3k+2): the
// screen as RGB bytes, row 0 at the top.
std::vector<unsigned char> compose_screen_srgb8(const WindowLayout& layout,
                                                const std::vector<const std::vector<unsigned char>*>& video);

}  // namespace capsim::sim
