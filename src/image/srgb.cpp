#include "capsim/image/srgb.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace capsim {

double srgb_to_linear(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

namespace {

float float_of(std::uint32_t bits) {
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

// The sRGB encoding of one channel, rounded to 8 bits: the definition that
// linear_to_srgb8 must reproduce exactly.
unsigned char encode_srgb8(float v) {
  if (!(v > 0)) return 0;  // also NaN
  if (v >= 1) return 255;
  const float s = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
  return static_cast<unsigned char>(std::lround(s * 255.0f));
}

// thresholds[b] is the least float whose encoding is at least b (b = 1..255).
std::array<float, 256> srgb8_thresholds() {
  std::array<float, 256> t{};
  t[0] = -std::numeric_limits<float>::infinity();
  for (int b = 1; b < 256; ++b) {
    float lo = 0.0f, hi = 1.0f;  // encode(lo) < b <= encode(hi)
    while (std::nextafter(lo, 1.0f) < hi) {
      const float mid = lo + (hi - lo) / 2;
      if (mid <= lo || mid >= hi) break;
      (encode_srgb8(mid) >= b ? hi : lo) = mid;
    }
    t[b] = hi;
  }
  return t;
}

}  // namespace

Srgb8Encoder::Srgb8Encoder() {
  const std::array<float, 256> t = srgb8_thresholds();
  // The buckets' first values rise with b, and so does their code: the
  // greatest code whose threshold is at most the first value, found by
  // moving on from the last bucket's rather than by a search per bucket.
  int code = 0;
  for (std::uint32_t b = 0; b < kBuckets; ++b) {
    const float first = float_of(b << 16), last = float_of((b << 16) | 0xffffu);
    while (code < 255 && t[code + 1] <= first) ++code;
    code_[b] = static_cast<unsigned char>(code);
    next_[b] = code < 255 ? t[code + 1] : std::numeric_limits<float>::infinity();
    if (code < 254 && last >= t[code + 2])
      throw std::logic_error("sRGB table: a bucket spans two steps of the encoding");
  }
}

const Srgb8Encoder& srgb8_encoder() {
  static const Srgb8Encoder table;
  return table;
}

unsigned char linear_to_srgb8(float v) { return srgb8_encoder()(v); }

}  // namespace capsim
