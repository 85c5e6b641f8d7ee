#include "machine/parts/video_bus.h"

#include <fmt/core.h>

#include <algorithm>
#include <atomic>
#include <stdexcept>

namespace capsim::sim {

namespace {

// Calls copy(c, k, s) for every window pixel, checking that video memories have
// their windows' sizes and that every screen pixel has exactly one owner.
template <class Copy>
void compose_checked(const WindowLayout& layout, const std::vector<int>& video_pixels, Copy copy) {
  const int cells = layout.grid().cell_count();
  if (static_cast<int>(video_pixels.size()) != cells)
    throw std::logic_error("one video memory per cell is needed");
  for (CellId c = 0; c < cells; ++c)
    if (video_pixels[c] != layout.window(c).pixel_count())
      throw std::logic_error(fmt::format("cell {} video memory holds {} pixels, its window {}", c,
                                         video_pixels[c], layout.window(c).pixel_count()));
  const int width = layout.width();
  // Cells write disjoint pixels when the windows are right, so they are
  // composed in parallel; the atomic count still catches a pixel with two owners.
  std::vector<std::atomic<unsigned char>> owners(static_cast<std::size_t>(width) * layout.height());
  for_each_window_pixel(layout, [&](CellId c, int k, std::size_t s) {
    if (owners[s].fetch_add(1, std::memory_order_relaxed) != 0)
      throw std::logic_error(fmt::format("screen pixel ({}, {}) has two owners", s % width, s / width));
    copy(c, k, s);
  });
  const auto hole = std::find_if(owners.begin(), owners.end(), [](const auto& o) { return o.load() == 0; });
  if (hole != owners.end()) {
    const auto s = static_cast<int>(hole - owners.begin());
    throw std::logic_error(fmt::format("screen pixel ({}, {}) has no owner", s % width, s / width));
  }
}

}  // namespace

Framebuffer compose_screen(const WindowLayout& layout, const std::vector<const Framebuffer*>& video) {
  std::vector<int> sizes;
  for (const Framebuffer* v : video) sizes.push_back(v->width);
  Framebuffer screen(layout.width(), layout.height());
  compose_checked(layout, sizes, [&](CellId c, int k, std::size_t s) {
    const Framebuffer& vm = *video[c];
    std::copy_n(vm.rgba.begin() + 4 * k, 4, screen.rgba.begin() + 4 * s);
    screen.depth[s] = vm.depth[k];
    screen.id[s] = vm.id[k];
  });
  return screen;
}

std::vector<unsigned char> compose_screen_srgb8(const WindowLayout& layout,
                                                const std::vector<const std::vector<unsigned char>*>& video) {
  std::vector<int> sizes;
  for (const auto* v : video) sizes.push_back(static_cast<int>(v->size() / 3));
  std::vector<unsigned char> screen(static_cast<std::size_t>(layout.width()) * layout.height() * 3);
  compose_checked(layout, sizes, [&](CellId c, int k, std::size_t s) {
    std::copy_n(video[c]->begin() + 3 * static_cast<std::ptrdiff_t>(k), 3, screen.begin() + 3 * static_cast<std::ptrdiff_t>(s));
  });
  return screen;
}

}  // namespace capsim::sim
