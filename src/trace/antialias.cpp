// Whitted's adaptive antialiasing from corner samples (see capsim/antialias.h).

#include "capsim/antialias.h"

#include "capsim/srgb.h"

#include <algorithm>
#include <cstdlib>

namespace capsim {

ScreenSample ScreenSample::from(const PixelSample& s) {
  ScreenSample out;
  out.r = static_cast<float>(s.color.x);
  out.g = static_cast<float>(s.color.y);
  out.b = static_cast<float>(s.color.z);
  out.covered = s.alpha > 0 ? 1 : 0;
  out.depth = static_cast<float>(s.depth);
  out.primitive = s.primitive;
  return out;
}

namespace {

// A sample's colour as the 8-bit sRGB codes the threshold compares, by the
// table (linear_to_srgb8 is the same encoding, a call away): a corner
// difference encodes each of its four corners once, not once per pair.
struct Codes {
  int r, g, b;
};

Codes srgb8_codes(const ScreenSample& s) {
  static const Srgb8Encoder& encode = srgb8_encoder();
  return {encode(s.r), encode(s.g), encode(s.b)};
}

int colour_distance(const Codes& a, const Codes& b) {
  return std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b);
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
  const Codes ca = srgb8_codes(a), cb = srgb8_codes(b), cc = srgb8_codes(c), cd = srgb8_codes(d);
  const int largest = std::max({colour_distance(ca, cb), colour_distance(ca, cc), colour_distance(ca, cd),
                                colour_distance(cb, cc), colour_distance(cb, cd), colour_distance(cc, cd)});
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
