#pragma once
// The per-cell heat map (--heatmap): each cell's busy time as a coloured block,
// laid out as the cell grid (row 0 at the top), with a colour bar below labelled
// with the smallest and largest busy time in simulated seconds. Colours follow
// the viridis scale (dark blue = least busy, yellow = most busy).

#include "machine/machine.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace capsim::sim {

struct RgbImage {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;  // 3 bytes per pixel, row 0 at the top
};

RgbImage render_heatmap(const SimulationResult& r);

// The viridis scale at t, clamped to [0, 1]: dark blue at 0, yellow at 1.
std::array<unsigned char, 3> viridis(double t);

// When each pixel appeared, one image pixel a screen pixel: completion
// (row-major, FrameScreen::completion_cycles) in viridis from `from` (dark
// blue) to `to` (yellow). Precondition: completion.size() == width * height.
RgbImage render_completion_map(const std::vector<std::uint64_t>& completion, int width, int height,
                               Cycles from, Cycles to);

// The image as a framebuffer whose sRGB encoding (write_image's PNG output) gives
// back exactly these 8-bit colours.
Framebuffer to_framebuffer(const RgbImage& image);

}  // namespace capsim::sim
