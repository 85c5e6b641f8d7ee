#pragma once
// Whitted's adaptive antialiasing from pixel-corner samples (paper §3.3; Whitted
// 1980). The screen has (W+1) x (H+1) corner samples at integer coordinates;
// corner (x, y) is the top-left corner of pixel (x, y). A square whose four
// corners differ by the threshold or more is split into four: its four edge
// midpoints and its centre are sampled (5 new samples; the corners are reused),
// and each quarter is treated the same way, down to `depth` levels. A square
// that is not split is the mean of its corners; a split square is the mean of
// its quarters. A pixel's value depends only on its own four corners and its
// own subdivision, so it never depends on who computes it or how the screen is
// cut; samples are not shared between pixels (an edge midpoint of two split
// neighbours is traced by each).
//
// Colour difference: |dR| + |dG| + |dB| of the 8-bit sRGB codes the PNG output
// shows, divided by 255, so 0 to 3; the threshold compares with the largest
// difference over the six pairs of corners (POV-Ray's metric and default 0.3).

#include "capsim/trace/tracer.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace capsim {

struct AntialiasOptions {
  int depth = 0;           // 0 = one sample at each pixel centre (no antialiasing)
  double threshold = 0.3;  // split a square whose corners differ by this or more
};

inline constexpr int kMaxAntialiasDepth = 8;

// One screen sample as the averaging uses it, and as it crosses the neighbour
// links: colour as three 32-bit floats and coverage (the primary ray hit
// something) as one byte: kScreenSampleBytes. depth and primitive are the
// primary ray's, kept for the pixel's Z and id (its top-left corner's).
struct ScreenSample {
  float r = 0, g = 0, b = 0;
  std::uint8_t covered = 0;
  // r, g and b as the 8-bit sRGB codes the threshold compares, encoded once
  // when the sample is made (a corner is compared by each of the four pixels
  // around it); on the host only, never sent over the links. of() and from()
  // set them: make a sample with a colour through them.
  std::array<std::uint8_t, 3> srgb8{};
  float depth = 0;
  std::int32_t primitive = -1;

  static ScreenSample of(float r, float g, float b, bool covered, float depth, std::int32_t primitive);
  static ScreenSample from(const PixelSample& s);
  bool operator==(const ScreenSample&) const = default;
};
inline constexpr std::uint64_t kScreenSampleBytes = 3 * 4 + 1;

// The largest colour difference between two of the four corners (see above).
double corner_difference(const ScreenSample& a, const ScreenSample& b, const ScreenSample& c,
                         const ScreenSample& d);

// The samples a screen point (u, v) in pixel units gives: the tracer's sample
// through it, rounded to a ScreenSample.
ScreenSample trace_screen_sample(const Tracer& tracer, double u, double v, Tracer::Scratch& scratch,
                                 OpCounts& ops);

// A resolved pixel: its colour and coverage as PixelSample (depth and primitive
// from its top-left corner) and the samples traced for its subdivision.
struct AntialiasedPixel {
  PixelSample value;
  int subdivision_samples = 0;  // 5 per split square
};

// Pixel (i, j) from its corners in the order top-left, top-right, bottom-left,
// bottom-right, splitting as the options ask; the extra samples' operations are
// added to ops. Precondition: options.depth >= 1.
AntialiasedPixel resolve_pixel(const Tracer& tracer, int i, int j, const ScreenSample corners[4],
                               const AntialiasOptions& options, Tracer::Scratch& scratch,
                               OpCounts& ops);

// The corner samples of the whole screen, row by row ((W+1) x (H+1)).
struct CornerSamples {
  int width = 0, height = 0;  // the screen's, in pixels
  std::vector<ScreenSample> samples;

  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * (width + 1) + x; }
  const ScreenSample& at(int x, int y) const { return samples[index(x, y)]; }
};

// The pixel whose owner traces corner (x, y) of a width x height screen: the
// pixel it is the top-left corner of, or, for the extra right column and
// bottom row of corners, the last pixel of that row or column.
struct CornerPixel {
  int x, y;
};
inline CornerPixel corner_pixel(int x, int y, int width, int height) {
  return {std::min(x, width - 1), std::min(y, height - 1)};
}

// The number of corner samples a pixel's owner traces: its own (top-left)
// corner, plus the screen's extra right column and bottom row of corners for
// the pixels of the last column and row.
inline int owned_corner_count(int i, int j, int width, int height) {
  return (1 + (i == width - 1)) * (1 + (j == height - 1));
}

}  // namespace capsim
