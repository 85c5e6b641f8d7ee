#include "video_bus.h"

#include <fmt/core.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <stdexcept>

namespace capsim::sim {

Framebuffer compose_screen(const WindowLayout& layout, const std::vector<const Framebuffer*>& video) {
  const int cells = layout.grid().cell_count();
  if (static_cast<int>(video.size()) != cells)
    throw std::logic_error("one video memory per cell is needed");
  Framebuffer screen(layout.width(), layout.height());
  // Cells write disjoint pixels when the windows are right, so they are
  // composed in parallel; the atomic count still catches a pixel with two owners.
  std::vector<std::atomic<unsigned char>> owners(static_cast<std::size_t>(layout.width()) * layout.height());
  tbb::parallel_for(0, cells, [&](CellId c) {
    const CellWindow& window = layout.window(c);
    const Framebuffer& vm = *video[c];
    if (vm.width != window.pixel_count())
      throw std::logic_error(fmt::format("cell {} video memory holds {} pixels, its window {}", c,
                                         vm.width, window.pixel_count()));
    for (int k = 0; k < window.pixel_count(); ++k) {
      const ScreenPixel p = window.screen_pixel(k);
      const std::size_t s = static_cast<std::size_t>(p.y) * screen.width + p.x;
      if (owners[s].fetch_add(1, std::memory_order_relaxed) != 0)
        throw std::logic_error(fmt::format("screen pixel ({}, {}) has two owners", p.x, p.y));
      std::copy_n(vm.rgba.begin() + 4 * k, 4, screen.rgba.begin() + 4 * s);
      screen.depth[s] = vm.depth[k];
      screen.id[s] = vm.id[k];
    }
  });
  const auto hole = std::find_if(owners.begin(), owners.end(), [](const auto& o) { return o.load() == 0; });
  if (hole != owners.end()) {
    const auto s = static_cast<int>(hole - owners.begin());
    throw std::logic_error(fmt::format("screen pixel ({}, {}) has no owner", s % screen.width,
                                       s / screen.width));
  }
  return screen;
}

}  // namespace capsim::sim
