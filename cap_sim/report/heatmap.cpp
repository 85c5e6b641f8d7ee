#include "report/heatmap.h"

#include "capsim/image/srgb.h"

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>

namespace capsim::sim {

namespace {

using Rgb = std::array<unsigned char, 3>;

}  // namespace

// Viridis at five evenly spaced stops; linear in between.
Rgb viridis(double t) {
  static constexpr double kStops[5][3] = {
      {68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}};
  t = (t >= 0.0 ? std::min(t, 1.0) : 0.0) * 4.0;  // NaN to 0: a cast of NaN to int is undefined
  const int i = std::min(static_cast<int>(t), 3);
  const double f = t - i;
  Rgb c;
  for (int k = 0; k < 3; ++k)
    c[k] = static_cast<unsigned char>(std::lround(kStops[i][k] + f * (kStops[i + 1][k] - kStops[i][k])));
  return c;
}

namespace {

// A 3x5 pixel font for the legend labels: digits, '.', 's', ' '.
const char* glyph(char ch) {
  switch (ch) {
    case '0': return "111101101101111";
    case '1': return "010110010010111";
    case '2': return "111001111100111";
    case '3': return "111001111001111";
    case '4': return "101101111001001";
    case '5': return "111100111001111";
    case '6': return "111100111101111";
    case '7': return "111001001001001";
    case '8': return "111101111101111";
    case '9': return "111101111001111";
    case '.': return "000000000000010";
    case 's': return "011100010001110";
    default: return "000000000000000";
  }
}

constexpr int kFontScale = 2;
constexpr int kGlyphAdvance = 4 * kFontScale;  // 3 columns and 1 of space

int text_width(std::string_view s) { return static_cast<int>(s.size()) * kGlyphAdvance; }

class Canvas {
 public:
  Canvas(int w, int h, Rgb background) : image_{w, h, std::vector<unsigned char>(3 * w * h)} {
    fill(0, 0, w, h, background);
  }
  void fill(int x0, int y0, int w, int h, Rgb c) {
    for (int y = std::max(0, y0); y < std::min(image_.height, y0 + h); ++y)
      for (int x = std::max(0, x0); x < std::min(image_.width, x0 + w); ++x)
        std::copy(c.begin(), c.end(), image_.rgb.begin() + 3 * (y * image_.width + x));
  }
  void text(int x, int y, std::string_view s, Rgb c) {
    for (char ch : s) {
      const char* g = glyph(ch);
      for (int row = 0; row < 5; ++row)
        for (int col = 0; col < 3; ++col)
          if (g[row * 3 + col] == '1')
            fill(x + col * kFontScale, y + row * kFontScale, kFontScale, kFontScale, c);
      x += kGlyphAdvance;
    }
  }
  RgbImage take() { return std::move(image_); }

 private:
  RgbImage image_;
};

}  // namespace

RgbImage render_heatmap(const SimulationResult& r) {
  const CellGrid grid = r.config.cells;
  const std::uint64_t hz = r.config.profile.clock_hz;
  Cycles lo{~0ull}, hi{0};
  for (const CellReport& c : r.cells) {
    lo = std::min(lo, c.busy);
    hi = std::max(hi, c.busy);
  }
  const std::string lo_label = fmt::format("{:.3f} s", lo.seconds(hz));
  const std::string hi_label = fmt::format("{:.3f} s", hi.seconds(hz));

  const int block = std::clamp(512 / std::max(grid.rows, grid.cols), 8, 64);
  const int margin = 8;
  const int grid_w = grid.cols * block;
  const int content_w = std::max({grid_w, text_width(lo_label) + text_width(hi_label) + 16, 160});
  const int bar_h = 16;
  const int label_h = 5 * kFontScale;
  const int width = content_w + 2 * margin;
  const int height = margin + grid.rows * block + margin + bar_h + 4 + label_h + margin;
  const Rgb background{255, 255, 255};
  const Rgb ink{0, 0, 0};
  Canvas canvas(width, height, background);

  auto scale = [&](Cycles c) {
    return hi > lo ? static_cast<double>((c - lo).count()) / static_cast<double>((hi - lo).count())
                   : 0.5;
  };
  const int grid_x = margin + (content_w - grid_w) / 2;
  for (const CellReport& c : r.cells) {
    const int x = grid_x + c.position.col * block;
    const int y = margin + c.position.row * block;
    canvas.fill(x, y, block, block, Rgb{40, 40, 40});  // a thin border between cells
    canvas.fill(x + 1, y + 1, block - 1, block - 1, viridis(scale(c.busy)));
  }

  const int bar_y = margin + grid.rows * block + margin;
  for (int x = 0; x < content_w; ++x)
    canvas.fill(margin + x, bar_y, 1, bar_h, viridis(static_cast<double>(x) / std::max(1, content_w - 1)));
  const int label_y = bar_y + bar_h + 4;
  canvas.text(margin, label_y, lo_label, ink);
  canvas.text(margin + content_w - text_width(hi_label) + kFontScale, label_y, hi_label, ink);
  return canvas.take();
}

RgbImage render_completion_map(const std::vector<std::uint64_t>& completion, int width, int height,
                               Cycles from, Cycles to) {
  RgbImage image{width, height, std::vector<unsigned char>(completion.size() * 3)};
  const double span = to > from ? static_cast<double>((to - from).count()) : 1.0;
  for (std::size_t k = 0; k < completion.size(); ++k) {
    const double t = completion[k] > from.count() ? static_cast<double>(completion[k] - from.count()) / span : 0.0;
    const Rgb c = viridis(t);
    std::copy(c.begin(), c.end(), image.rgb.begin() + 3 * static_cast<std::ptrdiff_t>(k));
  }
  return image;
}

Framebuffer to_framebuffer(const RgbImage& image) {
  Framebuffer fb(image.width, image.height);
  const std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
  for (std::size_t k = 0; k < pixels; ++k) {
    for (int c = 0; c < 3; ++c) fb.rgba[4 * k + c] = srgb8_to_linear(image.rgb[3 * k + c]);
    fb.rgba[4 * k + 3] = 1.0f;
  }
  return fb;
}

}  // namespace capsim::sim
