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

// The least float whose 8-bit sRGB code is at least b, for b = 1 .. 255, as
// the floats' bits. The code of v in [0, 1] is the formula's,
//   round(255 * (v <= 0.0031308 ? 12.92 v : 1.055 v^(1/2.4) - 0.055)),
// in float arithmetic with glibc's powf; each threshold was found by bisection
// on it. They are kept here rather than worked out by each run: that took some
// 6,000 calls of powf, a tenth of a tiny render's time, and a libm whose powf
// rounds differently would have moved them. ImageIo.Srgb8TableEqualsTheFormula
// checks each against the formula, on both sides.
constexpr std::array<std::uint32_t, 255> kThresholdBits = {
    0x391f22b4, 0x39eeb40e, 0x3a46eb61, 0x3a8b3e5d, 0x3ab3070b, 0x3adacfb7, 0x3b014c32, 0x3b153089,
    0x3b2914df, 0x3b3cf936, 0x3b50f2d1, 0x3b65fb9a, 0x3b7c3404, 0x3b89d060, 0x3b962333, 0x3ba314be,
    0x3bb0a731, 0x3bbedcb6, 0x3bcdb76c, 0x3bdd3966, 0x3bed64ae, 0x3bfe3b44, 0x3c07df90, 0x3c10f919,
    0x3c1a6b32, 0x3c2436c7, 0x3c2e5cc7, 0x3c38de19, 0x3c43bba3, 0x3c4ef646, 0x3c5a8ee2, 0x3c668654,
    0x3c72dd73, 0x3c7f9512, 0x3c865703, 0x3c8d1490, 0x3c940396, 0x3c9b247c, 0x3ca277a8, 0x3ca9fd79,
    0x3cb1b654, 0x3cb9a299, 0x3cc1c2a9, 0x3cca16e3, 0x3cd29fa4, 0x3cdb5d4d, 0x3ce45034, 0x3ced78b6,
    0x3cf6d72f, 0x3d0035fc, 0x3d051bb6, 0x3d0a1cee, 0x3d0f39d1, 0x3d14728a, 0x3d19c745, 0x3d1f382b,
    0x3d24c56a, 0x3d2a6f24, 0x3d303586, 0x3d3618b9, 0x3d3c18e6, 0x3d423634, 0x3d4870cb, 0x3d4ec8d3,
    0x3d553e74, 0x3d5bd1d3, 0x3d628319, 0x3d69526a, 0x3d703fee, 0x3d774bce, 0x3d7e7627, 0x3d82df92,
    0x3d869374, 0x3d8a56cc, 0x3d8e29ad, 0x3d920c28, 0x3d95fe50, 0x3d9a0036, 0x3d9e11ec, 0x3da23384,
    0x3da66510, 0x3daaa6a0, 0x3daef847, 0x3db35a17, 0x3db7cc1d, 0x3dbc4e6c, 0x3dc0e116, 0x3dc5842a,
    0x3dca37ba, 0x3dcefbd7, 0x3dd3d090, 0x3dd8b5f6, 0x3dddac19, 0x3de2b30a, 0x3de7cad9, 0x3decf395,
    0x3df22d4f, 0x3df7781a, 0x3dfcd3fe, 0x3e012088, 0x3e03dfaf, 0x3e06a77c, 0x3e0977f7, 0x3e0c5127,
    0x3e0f3314, 0x3e121dc6, 0x3e151144, 0x3e180d95, 0x3e1b12c2, 0x3e1e20d1, 0x3e2137cb, 0x3e2457b7,
    0x3e27809a, 0x3e2ab27c, 0x3e2ded67, 0x3e313160, 0x3e347e6f, 0x3e37d49d, 0x3e3b33ed, 0x3e3e9c68,
    0x3e420e14, 0x3e4588fa, 0x3e490d21, 0x3e4c9a8f, 0x3e50314b, 0x3e53d15c, 0x3e577ac9, 0x3e5b2d99,
    0x3e5ee9d2, 0x3e62af7c, 0x3e667e9d, 0x3e6a5740, 0x3e6e3963, 0x3e722512, 0x3e761a53, 0x3e7a192d,
    0x3e7e21a6, 0x3e8119e2, 0x3e8327c8, 0x3e853a87, 0x3e875222, 0x3e896e9e, 0x3e8b8ffc, 0x3e8db641,
    0x3e8fe170, 0x3e92118b, 0x3e944696, 0x3e968094, 0x3e98bf89, 0x3e9b0377, 0x3e9d4c61, 0x3e9f9a4b,
    0x3ea1ed38, 0x3ea4452a, 0x3ea6a225, 0x3ea9042d, 0x3eab6b43, 0x3eadd76b, 0x3eb048a9, 0x3eb2bf01,
    0x3eb53a72, 0x3eb7bb01, 0x3eba40b2, 0x3ebccb86, 0x3ebf5b82, 0x3ec1f0a7, 0x3ec48afa, 0x3ec72a7d,
    0x3ec9cf32, 0x3ecc791e, 0x3ecf2842, 0x3ed1dca2, 0x3ed49641, 0x3ed75521, 0x3eda1945, 0x3edce2b1,
    0x3edfb167, 0x3ee2856a, 0x3ee55ebc, 0x3ee83d62, 0x3eeb215c, 0x3eee0aaf, 0x3ef0f95d, 0x3ef3ed69,
    0x3ef6e6d6, 0x3ef9e5a6, 0x3efce9e0, 0x3efff37f, 0x3f018145, 0x3f030b82, 0x3f049878, 0x3f062827,
    0x3f07ba92, 0x3f094fba, 0x3f0ae79f, 0x3f0c8244, 0x3f0e1faa, 0x3f0fbfd2, 0x3f1162be, 0x3f13086e,
    0x3f14b0e4, 0x3f165c22, 0x3f180a29, 0x3f19baf9, 0x3f1b6e95, 0x3f1d24fe, 0x3f1ede35, 0x3f209a3b,
    0x3f225912, 0x3f241abb, 0x3f25df37, 0x3f27a688, 0x3f2970ae, 0x3f2b3dac, 0x3f2d0d84, 0x3f2ee033,
    0x3f30b5be, 0x3f328e25, 0x3f346969, 0x3f36478c, 0x3f38288f, 0x3f3a0c73, 0x3f3bf33a, 0x3f3ddce5,
    0x3f3fc975, 0x3f41b8eb, 0x3f43ab48, 0x3f45a08f, 0x3f4798bf, 0x3f4993da, 0x3f4b91e2, 0x3f4d92d8,
    0x3f4f96bd, 0x3f519d91, 0x3f53a758, 0x3f55b410, 0x3f57c3bd, 0x3f59d65e, 0x3f5bebf6, 0x3f5e0485,
    0x3f60200d, 0x3f623e91, 0x3f64600b, 0x3f668486, 0x3f68abfa, 0x3f6ad671, 0x3f6d03e3, 0x3f6f345b,
    0x3f7167d0, 0x3f739e4d, 0x3f75d7ca, 0x3f781452, 0x3f7a53db, 0x3f7c9671, 0x3f7edc0e
};

}  // namespace

Srgb8Encoder::Srgb8Encoder() {
  std::array<float, 256> t{};
  t[0] = -std::numeric_limits<float>::infinity();
  for (int b = 1; b < 256; ++b) t[b] = float_of(kThresholdBits[b - 1]);
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
