#pragma once
// The video bus: the screen is the composition of every cell's video memory,
// each placed by its window controller. Every screen pixel must come from exactly
// one cell; composition checks it.

#include "window_controller.h"

#include "capsim/render.h"

#include <vector>

namespace capsim::sim {

// video[c] holds cell c's pixels: pixel k at (k, 0). Throws std::logic_error if a
// screen pixel is written twice or never, or a video memory has the wrong size.
Framebuffer compose_screen(const WindowLayout& layout, const std::vector<const Framebuffer*>& video);

}  // namespace capsim::sim
