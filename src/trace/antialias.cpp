// Whitted's adaptive antialiasing from corner samples (see capsim/trace/antialias.h).

#include "capsim/trace/antialias.h"

#include "capsim/image/srgb.h"

#include <algorithm>
#include <cstdlib>

namespace capsim {

ScreenSample ScreenSample::of(float r, float g, float b, bool covered, float depth, std::int32_t primitive) {
  const Srgb8Encoder& encode = srgb8_encoder();
  ScreenSample out;
  out.r = r;
  out.g = g;
  out.b = b;
  out.covered = covered ? 1 : 0;
  out.srgb8 = {encode(r), encode(g), encode(b)};
  out.depth = depth;
  out.primitive = primitive;
  return out;
}

ScreenSample ScreenSample::from(const PixelSample& s) {
  return of(static_cast<float>(s.color.x), static_cast<float>(s.color.y), static_cast<float>(s.color.z),
            s.alpha > 0, static_cast<float>(s.depth), s.primitive);
}

namespace {

int colour_distance(const ScreenSample& a, const ScreenSample& b) {
  int sum = 0;
  for (int k = 0; k < 3; ++k) sum += std::abs(int{a.srgb8[k]} - int{b.srgb8[k]});
  return sum;
}

// A square's mean colour and coverage, in double so that the order of the sums
// is the only rounding that matters, and it is fixed.
struct Mean {
  double r = 0, g = 0, b = 0, covered = 0;
};

Mean mean_of(const Mean& a, const Mean& b, const Mean& c, const Mean& d) {
  return {(a.r + b.r + c.r + d.r) / 4, (a.g + b.g + c.g + d.g) / 4, (a.b + b.b + c.b + d.b) / 4,
          (a.covered + b.covered + c.covered + d.covered) / 4};
}

Mean as_mean(const ScreenSample& s) { return {s.r, s.g, s.b, static_cast<double>(s.covered)}; }

class Subdivision {
 public:
  Subdivision(const Tracer& tracer, const AntialiasOptions& options, Tracer::Scratch& scratch,
              OpCounts& ops)
      : tracer_(tracer), options_(options), scratch_(scratch), ops_(ops) {}

  // The square with top-left corner (u, v) and side h, `levels` splits allowed.
  Mean square(double u, double v, double h, int levels, const ScreenSample& tl,
              const ScreenSample& tr, const ScreenSample& bl, const ScreenSample& br) {
    ++ops_.aa_squares;
    if (levels == 0 || corner_difference(tl, tr, bl, br) < options_.threshold)
      return mean_of(as_mean(tl), as_mean(tr), as_mean(bl), as_mean(br));
    const double m = h / 2;  // exact: h is a power of two
    const ScreenSample top = sample(u + m, v);
    const ScreenSample left = sample(u, v + m);
    const ScreenSample centre = sample(u + m, v + m);
    const ScreenSample right = sample(u + h, v + m);
    const ScreenSample bottom = sample(u + m, v + h);
    samples_ += 5;
    return mean_of(square(u, v, m, levels - 1, tl, top, left, centre),
                   square(u + m, v, m, levels - 1, top, tr, centre, right),
                   square(u, v + m, m, levels - 1, left, centre, bl, bottom),
                   square(u + m, v + m, m, levels - 1, centre, right, bottom, br));
  }

  int samples() const { return samples_; }

 private:
  ScreenSample sample(double u, double v) {
    return trace_screen_sample(tracer_, u, v, scratch_, ops_);
  }

  const Tracer& tracer_;
  const AntialiasOptions& options_;
  Tracer::Scratch& scratch_;
  OpCounts& ops_;
  int samples_ = 0;
};

}  // namespace

double corner_difference(const ScreenSample& a, const ScreenSample& b, const ScreenSample& c,
                         const ScreenSample& d) {
  const int largest = std::max({colour_distance(a, b), colour_distance(a, c), colour_distance(a, d),
                                colour_distance(b, c), colour_distance(b, d), colour_distance(c, d)});
  return largest / 255.0;
}

ScreenSample trace_screen_sample(const Tracer& tracer, double u, double v, Tracer::Scratch& scratch,
                                 OpCounts& ops) {
  return ScreenSample::from(tracer.trace_screen_point(u, v, scratch, ops));
}

AntialiasedPixel resolve_pixel(const Tracer& tracer, int i, int j, const ScreenSample corners[4],
                               const AntialiasOptions& options, Tracer::Scratch& scratch,
                               OpCounts& ops) {
  Subdivision split(tracer, options, scratch, ops);
  const Mean m = split.square(i, j, 1.0, options.depth, corners[0], corners[1], corners[2], corners[3]);
  AntialiasedPixel p;
  p.value.color = {m.r, m.g, m.b};
  p.value.alpha = static_cast<float>(m.covered);
  p.value.depth = corners[0].depth;
  p.value.primitive = corners[0].primitive;
  p.subdivision_samples = split.samples();
  return p;
}

}  // namespace capsim
