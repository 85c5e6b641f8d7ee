// Whitted's adaptive antialiasing on the host (capsim/trace/antialias.h): sample
// counts, independence of how the screen is cut, and coverage against the exact
// area on analytic scenes.

#include "capsim/image/srgb.h"
#include "capsim/scene/parser.h"
#include "capsim/trace/antialias.h"
#include "capsim/trace/render.h"
#include "support/scene_builders.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fmt/core.h>
#include <vector>

namespace capsim {
namespace {

using testing::box;
using testing::make_scene;
using testing::sphere;

PreparedScene small_scene(int width, int height) {
  std::vector<Primitive> prims;
  for (int x = 0; x < 3; ++x) prims.push_back(sphere({x * 2.0, 0, 0}, 0.9));
  prims.push_back(box({-1, -1, -1.5}, {6, 3, 0.5}));
  prims[1].material.reflect = 0.5;
  PrepareOptions o;
  o.width = width;
  o.height = height;
  return prepare_scene(make_scene(prims), o);
}

std::vector<PixelSample> render_samples(const Tracer& tracer, int threads, const AntialiasOptions& aa,
                                        RenderStats* stats = nullptr) {
  const Camera& cam = tracer.scene().camera;
  std::vector<PixelSample> out(static_cast<std::size_t>(cam.width) * cam.height);
  render_rows(
      tracer, threads,
      [&](int j, std::span<const PixelSample> row) {
        std::copy(row.begin(), row.end(), out.begin() + static_cast<std::ptrdiff_t>(j) * cam.width);
      },
      stats, nullptr, aa);
  return out;
}

void expect_same(const PixelSample& a, const PixelSample& b, const std::string& where) {
  EXPECT_EQ(a.color, b.color) << where;
  EXPECT_EQ(a.alpha, b.alpha) << where;
  EXPECT_EQ(a.depth, b.depth) << where;
  EXPECT_EQ(a.primitive, b.primitive) << where;
  EXPECT_EQ(a.samples, b.samples) << where;
}

TEST(Antialias, DepthZeroIsOneSampleAtEachPixelCentre) {
  const PreparedScene ps = small_scene(24, 16);
  const Tracer tracer(ps, {});
  RenderStats stats;
  const std::vector<PixelSample> img = render_samples(tracer, 2, {0, 0.3}, &stats);
  Tracer::Scratch s(ps);
  OpCounts ops;
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 24; ++i)
      expect_same(img[static_cast<std::size_t>(j) * 24 + i], tracer.trace_pixel(i, j, s, ops),
                  fmt::format("pixel {},{}", i, j));
  EXPECT_EQ(stats.ops, ops);
  EXPECT_EQ(stats.ops.primary_rays, 24u * 16u);
}

TEST(Antialias, EveryPixelDependsOnlyOnItsOwnCornersAndSubdivision) {
  // Each pixel resolved alone, with a fresh scratch and corners traced just for
  // it, equals the same pixel of whole renders on one and on two threads.
  const PreparedScene ps = small_scene(20, 14);
  const Tracer tracer(ps, {});
  const AntialiasOptions aa{2, 0.1};
  const std::vector<PixelSample> one = render_samples(tracer, 1, aa);
  const std::vector<PixelSample> two = render_samples(tracer, 2, aa);
  int split = 0;
  for (int j = 0; j < 14; ++j)
    for (int i = 0; i < 20; ++i) {
      Tracer::Scratch s(ps);
      OpCounts ops;
      const ScreenSample c[4] = {trace_screen_sample(tracer, i, j, s, ops),
                                 trace_screen_sample(tracer, i + 1, j, s, ops),
                                 trace_screen_sample(tracer, i, j + 1, s, ops),
                                 trace_screen_sample(tracer, i + 1, j + 1, s, ops)};
      AntialiasedPixel alone = resolve_pixel(tracer, i, j, c, aa, s, ops);
      alone.value.samples = owned_corner_count(i, j, 20, 14) + alone.subdivision_samples;
      const std::size_t k = static_cast<std::size_t>(j) * 20 + i;
      expect_same(alone.value, one[k], fmt::format("pixel {},{} (1 thread)", i, j));
      expect_same(alone.value, two[k], fmt::format("pixel {},{} (2 threads)", i, j));
      split += alone.subdivision_samples > 0;
    }
  EXPECT_GT(split, 10);  // the scene has edges, so the test covers subdivision
}

TEST(Antialias, SamplesPerPixelCountEveryPrimaryRayOnce) {
  const PreparedScene ps = small_scene(21, 13);
  const Tracer tracer(ps, {});
  for (int depth = 1; depth <= 3; ++depth) {
    RenderStats stats;
    const std::vector<PixelSample> img = render_samples(tracer, 2, {depth, 0.05}, &stats);
    std::uint64_t samples = 0;
    int max_samples = 0;
    for (const PixelSample& p : img) {
      samples += static_cast<std::uint64_t>(p.samples);
      max_samples = std::max(max_samples, p.samples);
    }
    EXPECT_EQ(samples, stats.ops.primary_rays) << "depth " << depth;
    // A pixel split at every level traces 5 samples per split square:
    // 5 (1 + 4 + ... + 4^(depth-1)); plus its own corner(s).
    int full = 0;
    for (int l = 0, squares = 1; l < depth; ++l, squares *= 4) full += 5 * squares;
    EXPECT_LE(max_samples, full + 4) << "depth " << depth;
    EXPECT_GE(max_samples, full + 1) << "depth " << depth;  // some pixel splits all the way
    EXPECT_EQ(stats.ops.rays, stats.ops.primary_rays + stats.ops.shadow_rays + stats.ops.secondary_rays);
    EXPECT_GT(stats.ops.aa_squares, 21u * 13u);
  }
}

// A sample's 8-bit codes, encoded once when it is made, are the encoding of
// its float channels (what corner_difference compared when it encoded each
// corner anew), whatever the colour: out of range, NaN, at the codes' steps.
TEST(Antialias, ASamplesCodesAreItsChannelsEncoded) {
  const double values[] = {-1.0, 0.0, 1e-9, 0.0031308, 0.2, 0.5, 0.99999, 1.0, 7.5, std::nan("")};
  for (const double r : values)
    for (const double g : values) {
      PixelSample p;
      p.color = {r, g, 1.0 - g};
      const ScreenSample s = ScreenSample::from(p);
      EXPECT_TRUE(s.r == static_cast<float>(r) || (std::isnan(r) && std::isnan(s.r))) << r;
      EXPECT_EQ(s.srgb8[0], linear_to_srgb8(s.r)) << r;
      EXPECT_EQ(s.srgb8[1], linear_to_srgb8(s.g)) << g;
      EXPECT_EQ(s.srgb8[2], linear_to_srgb8(s.b)) << 1.0 - g;
    }
  // A code step: 0.1f and the float next below it lie on either side of one.
  const float step = 0.1f, below = std::nextafter(step, 0.0f);
  const ScreenSample a = ScreenSample::of(step, 0, 0, true, 1, 0), b = ScreenSample::of(below, 0, 0, true, 1, 0);
  EXPECT_EQ(a.srgb8[0], linear_to_srgb8(step));
  EXPECT_EQ(b.srgb8[0], linear_to_srgb8(below));
  EXPECT_EQ(corner_difference(a, a, a, b), std::abs(int{a.srgb8[0]} - int{b.srgb8[0]}) / 255.0);
}

TEST(Antialias, CornersThatAgreeGiveTheirMeanWithoutExtraSamples) {
  const PreparedScene ps = small_scene(8, 8);
  const Tracer tracer(ps, {});
  Tracer::Scratch s(ps);
  OpCounts ops;
  ScreenSample c[4];
  // 8-bit sRGB codes 0, 89, 124, 149 ...
  for (int k = 0; k < 4; ++k) c[k] = ScreenSample::of(0.1f * k, 0, 0, k % 2 == 1, 0, -1);
  // ... differ by up to 149 / 255 = 0.58: below a threshold of 0.6, no split.
  const AntialiasedPixel p = resolve_pixel(tracer, 3, 3, c, {3, 0.6}, s, ops);
  EXPECT_EQ(p.subdivision_samples, 0);
  EXPECT_EQ(ops.primary_rays, 0u);
  EXPECT_EQ(ops.aa_squares, 1u);
  EXPECT_DOUBLE_EQ(p.value.color.x, (0.0 + double(0.1f) + double(0.2f) + double(0.3f)) / 4);
  EXPECT_EQ(p.value.alpha, 0.5f);
  // At a threshold of 0.5 they split.
  const AntialiasedPixel q = resolve_pixel(tracer, 3, 3, c, {1, 0.5}, s, ops);
  EXPECT_EQ(q.subdivision_samples, 5);
}

// The exact fraction of the unit square [i, i+1] x [j, j+1] where
// a u + b v + c <= 0 (the square clipped by the half-plane).
double covered_area(int i, int j, double a, double b, double c) {
  std::vector<std::pair<double, double>> poly = {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}};
  std::vector<std::pair<double, double>> out;
  for (std::size_t k = 0; k < poly.size(); ++k) {
    const auto [u0, v0] = poly[k];
    const auto [u1, v1] = poly[(k + 1) % poly.size()];
    const double f0 = a * u0 + b * v0 + c, f1 = a * u1 + b * v1 + c;
    if (f0 <= 0) out.push_back({u0, v0});
    if ((f0 < 0) != (f1 < 0) && f0 != f1) {
      const double t = f0 / (f0 - f1);
      out.push_back({u0 + t * (u1 - u0), v0 + t * (v1 - v0)});
    }
  }
  double area = 0;
  for (std::size_t k = 0; k < out.size(); ++k) {
    const auto [u0, v0] = out[k];
    const auto [u1, v1] = out[(k + 1) % out.size()];
    area += u0 * v1 - u1 * v0;
  }
  return std::abs(area) / 2;
}

TEST(Antialias, CoverageIsTheCoveredAreaWithinAToleranceThatHalvesPerLevel) {
  // A large box seen from straight above: its top face (z = 0, facing the
  // camera) ends at the line y' = 0.1234 of a frame turned by `angle` about z,
  // so on screen its edge is a straight line at a known place. For a straight
  // edge every pixel it crosses has corners on both sides, and so does every
  // square it crosses at each level; a leaf square of side h = 2^-depth that it
  // crosses is off by at most h^2 / 2, and it crosses fewer than 2 / h of them
  // in a pixel: the error of A is below 2^-depth.
  constexpr int kSize = 32;
  for (const double angle : {7.0, 30.0, 45.0, 62.5}) {
    const std::string text = fmt::format(
        "camera(eye = [0, 0, 10], center = [0, 0, 0], up = [0, 1, 0], fov = 40, size = [{0}, {0}]);\n"
        "light(position = [0, 0, 50], color = [1, 1, 1]);\n"
        "background(color = [0, 0, 0]);\n"
        "rotate([0, 0, {1}]) translate([-100, -99.8766, -1]) cube([200, 100, 1]);\n",
        kSize, angle);
    const PreparedScene ps = prepare_scene(parse_scene(text, "edge.csg"), {});
    const Tracer tracer(ps, {});
    // Screen (u, v) -> world (x, y) on z = 0, then the edge's side:
    // y' = -x sin + y cos <= 0.1234 is covered.
    const double half = 10 * std::tan(20.0 * std::acos(-1.0) / 180.0);
    const double sn = std::sin(angle * std::acos(-1.0) / 180.0), cs = std::cos(angle * std::acos(-1.0) / 180.0);
    // x = (2u / W - 1) half, y = (1 - 2v / H) half.
    const double a = -sn * 2 * half / kSize - 0, b = -cs * 2 * half / kSize;
    const double c = sn * half + cs * half - 0.1234;
    for (int depth = 1; depth <= 4; ++depth) {
      const std::vector<PixelSample> img = render_samples(tracer, 2, {depth, 0.1});
      double worst = 0;
      int crossed = 0;
      for (int j = 0; j < kSize; ++j)
        for (int i = 0; i < kSize; ++i) {
          const double exact = covered_area(i, j, a, b, c);
          const double got = img[static_cast<std::size_t>(j) * kSize + i].alpha;
          if (exact > 0 && exact < 1) ++crossed;
          worst = std::max(worst, std::abs(got - exact));
        }
      EXPECT_GT(crossed, kSize / 2) << "angle " << angle;
      EXPECT_LT(worst, std::ldexp(1.0, -depth)) << "angle " << angle << " depth " << depth;
    }
  }
}

}  // namespace
}  // namespace capsim
