#pragma once
// What the balancing tests share: random small scenes, screens compared bit
// for bit, and the pixels a steal run moved.

#include "machine/parts/balance.h"
#include "machine/machine.h"

#include "capsim/scene/parser.h"
#include "capsim/trace/prepared_scene.h"

#include <fmt/core.h>

#include <cstring>
#include <random>
#include <span>
#include <string>
#include <vector>

namespace capsim::testing {

// A few spheres and boxes at random places in front of the camera.
inline PreparedScene random_scene(unsigned seed, int width, int height) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> place(-3, 3), size(0.3, 1.5);
  std::string text = fmt::format(
      "camera(eye = [0, -14, 4], center = [0, 0, 0], up = [0, 0, 1], fov = 40, size = [{}, {}]);\n"
      "light(position = [10, -10, 20], color = [1, 1, 1]);\n",
      width, height);
  const int count = 2 + static_cast<int>(rng() % 6);
  for (int i = 0; i < count; ++i) {
    const double x = place(rng), y = place(rng), z = place(rng), s = size(rng);
    text += i % 2 == 0 ? fmt::format("translate([{}, {}, {}]) sphere(r = {});\n", x, y, z, s)
                       : fmt::format("translate([{}, {}, {}]) cube([{}, {}, {}]);\n", x, y, z, s, s, s);
  }
  return prepare_scene(parse_scene(text, "random.csg"), {});
}

inline bool same_floats(std::span<const float> a, std::span<const float> b) {
  // An 8-bit screen has no floats: memcmp must not see its null data.
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0);
}

// Stealing: the pixels of the chunks cells traced for another cell, all
// frames (the windows are `mode`'s, as the run's config gives them).
inline std::uint64_t stolen_pixels(const sim::SimulationResult& r) {
  const sim::WindowLayout layout(r.config.mode, r.config.cells, r.width, r.height);
  std::uint64_t pixels = 0;
  for (const sim::CellReport& c : r.cells)
    for (const sim::ChunkRun& run : c.chunk_runs)
      if (run.owner != c.id)
        for (int k = run.first_chunk; k < run.first_chunk + run.chunks; ++k)
          pixels += static_cast<std::uint64_t>(
              sim::chunk_range(k, layout.window(run.owner).pixel_count(), r.config.balance.chunk_pixels).pixels);
  return pixels;
}

}  // namespace capsim::testing
