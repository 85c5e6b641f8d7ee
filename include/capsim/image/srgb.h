#pragma once
// sRGB: the encoding of the 8-bit images (PNG output, heat maps, the
// antialiasing threshold's colour difference) and the decoding of the
// colours a scene file gives.

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>

namespace capsim {

// An sRGB-encoded value in [0, 1] -> linear.
double srgb_to_linear(double c);

// An 8-bit sRGB code -> linear, as a float.
inline float srgb8_to_linear(unsigned char v) { return static_cast<float>(srgb_to_linear(v / 255.0)); }

// Linear -> 8-bit sRGB code, exactly as the formula rounds it: values below 0
// and NaN give 0, values from 1 up give 255.
unsigned char linear_to_srgb8(float v);

// The same encoding by table, for loops over many values: floats in [0, 1]
// fall into 16257 buckets by their top 16 bits (sign, exponent and 7 mantissa
// bits). No bucket spans more than one step of the encoding, so a bucket's
// first code and the threshold of the next code give the exact result with
// one comparison. The encoding is monotonic, and the buckets are built from
// its thresholds, so the table reproduces the formula bit for bit (the
// construction checks the one-step property).
class Srgb8Encoder {
 public:
  Srgb8Encoder();
  unsigned char operator()(float v) const {
    // Into [0, 1] without branches; NaN becomes 0 (std::max returns its first
    // argument when the comparison fails).
    v = std::min(std::max(0.0f, v), 1.0f);
    std::uint32_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    const std::uint32_t b = bits >> 16;
    return static_cast<unsigned char>(code_[b] + (v >= next_[b] ? 1 : 0));
  }

 private:
  static constexpr std::uint32_t kBuckets = 0x3f81;  // up to the top 16 bits of 1.0f
  std::array<unsigned char, kBuckets> code_{};
  std::array<float, kBuckets> next_{};
};

// The one table, built on first use.
const Srgb8Encoder& srgb8_encoder();

}  // namespace capsim
