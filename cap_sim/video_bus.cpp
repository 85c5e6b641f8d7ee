#include "video_bus.h"

#include <fmt/core.h>

#include <algorithm>
#include <atomic>
#include <stdexcept>

namespace capsim::sim {

Framebuffer compose_screen(const WindowLayout& layout, const std::vector<const Framebuffer*>& video) {
  const int cells = layout.grid().cell_count();
  if (static_cast<int>(video.size()) != cells)
    throw std::logic_error("one video memory per cell is needed");
  for (CellId c = 0; c < cells; ++c)
    if (video[c]->width != layout.window(c).pixel_count())
      throw std::logic_error(fmt::format("cell {} video memory holds {} pixels, its window {}", c,
                                         video[c]->width, layout.window(c).pixel_count()));
  Framebuffer screen(layout.width(), layout.height());
  // Cells write disjoint pixels when the windows are right, so they are
  // composed in parallel; the atomic count still catches a pixel with two owners.
  std::vector<std::atomic<unsigned char>> owners(static_cast<std::size_t>(layout.width()) * layout.height());
  for_each_window_pixel(layout, [&](CellId c, int k, std::size_t s) {
    if (owners[s].fetch_add(1, std::memory_order_relaxed) != 0)
      throw std::logic_error(
          fmt::format("screen pixel ({}, {}) has two owners", s % screen.width, s / screen.width));
    const Framebuffer& vm = *video[c];
    std::copy_n(vm.rgba.begin() + 4 * k, 4, screen.rgba.begin() + 4 * s);
    screen.depth[s] = vm.depth[k];
    screen.id[s] = vm.id[k];
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
