// Image output: the sRGB encoding, PNG and EXR contents read back by an
// independent reader (OpenImageIO), and failures that leave nothing behind.

#include "capsim/image/image_io.h"
#include "capsim/image/srgb.h"
#include "capsim/system/shared_library.h"
#include "support/cli_run.h"
#include "image/exr_writer_module.h"
#include "image/zlib_bands.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

using namespace capsim;
using namespace capsim::testing;

namespace {

// The definition of the 8-bit sRGB encoding, written out independently.
unsigned char srgb8_by_formula(float v) {
  if (!(v > 0)) return 0;
  if (v >= 1) return 255;
  const float s = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
  return static_cast<unsigned char>(std::lround(s * 255.0f));
}

}  // namespace

// Every 8-bit code decodes to a linear value that encodes back to it (the
// heat maps' colours survive the PNG output's encoding).
TEST(Srgb, EveryCodeDecodesAndEncodesBack) {
  for (int v = 0; v < 256; ++v)
    EXPECT_EQ(linear_to_srgb8(srgb8_to_linear(static_cast<unsigned char>(v))), v);
}

TEST(ImageIo, Srgb8TableEqualsTheFormula) {
  // Every 61st float from 0 up to past 1, and both neighbours of every step.
  for (std::uint32_t bits = 0; bits < 0x3f900000u; bits += 61) {
    float v;
    std::memcpy(&v, &bits, sizeof v);
    ASSERT_EQ(linear_to_srgb8(v), srgb8_by_formula(v)) << v;
  }
  for (int b = 1; b < 256; ++b) {
    float lo = 0, hi = 1;
    while (std::nextafter(lo, 1.0f) < hi) {
      const float mid = lo + (hi - lo) / 2;
      (srgb8_by_formula(mid) >= b ? hi : lo) = mid;
    }
    EXPECT_EQ(linear_to_srgb8(hi), srgb8_by_formula(hi));
    EXPECT_EQ(linear_to_srgb8(lo), srgb8_by_formula(lo));
  }
  EXPECT_EQ(linear_to_srgb8(std::nanf("")), 0);
  EXPECT_EQ(linear_to_srgb8(-1.0f), 0);
  EXPECT_EQ(linear_to_srgb8(INFINITY), 255);
}

TEST(ImageIo, PngHoldsTheEncodedBytes) {
  TempDir dir;
  Framebuffer fb(3, 2);
  const float values[6] = {0.0f, 0.001f, 0.18f, 0.5f, 0.9f, 1.5f};
  for (int k = 0; k < 6; ++k)
    for (int c = 0; c < 3; ++c) fb.rgba[4 * k + c] = values[(k + c) % 6];
  write_image(dir / "x.png", fb);
  auto in = OIIO::ImageInput::open(dir / "x.png");
  ASSERT_TRUE(in);
  ASSERT_EQ(in->spec().nchannels, 3);
  std::vector<unsigned char> px(18);
  ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, px.data()));
  for (int k = 0; k < 6; ++k)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(px[3 * k + c], linear_to_srgb8(values[(k + c) % 6]));
}

TEST(ImageIo, ExrHoldsEveryChannelExactly) {
  TempDir dir;
  Framebuffer fb(2, 2);
  // Pixel (1, 0): colour (0.25, 2.5, 1e-3), covered, at depth 12.5, primitive 7.
  for (int c = 0; c < 3; ++c) fb.rgba[4 + c] = std::array<float, 3>{0.25f, 2.5f, 1e-3f}[c];
  fb.rgba[7] = 1;
  fb.depth[1] = 12.5f;
  fb.id[1] = 7;
  write_image(dir / "x.exr", fb, {{"cycles", {1, 2, 3, 16777216}}});
  auto in = OIIO::ImageInput::open(dir / "x.exr");
  ASSERT_TRUE(in);
  const OIIO::ImageSpec& spec = in->spec();
  ASSERT_EQ(spec.nchannels, 7);
  std::vector<float> px(4 * 7);
  ASSERT_TRUE(in->read_image(0, 0, 0, 7, OIIO::TypeDesc::FLOAT, px.data()));
  const auto at = [&](int k, const std::string& name) {
    const auto c = std::find(spec.channelnames.begin(), spec.channelnames.end(), name) - spec.channelnames.begin();
    return px[static_cast<std::size_t>(k) * 7 + c];
  };
  EXPECT_EQ(at(1, "R"), 0.25f);
  EXPECT_EQ(at(1, "G"), 2.5f);
  EXPECT_EQ(at(1, "A"), 1.0f);
  EXPECT_EQ(at(1, "Z"), 12.5f);
  EXPECT_EQ(at(1, "id"), 7.0f);
  EXPECT_EQ(at(0, "id"), -1.0f);
  EXPECT_TRUE(std::isinf(at(0, "Z")));
  EXPECT_EQ(at(3, "cycles"), 16777216.0f);
}

// The EXR module's C function, called as the image layer calls it: a file
// OpenImageIO reads back, and OpenEXR's refusal returned as a message cut to the
// room given, never thrown across the C boundary.
TEST(ImageIo, TheExrModuleWritesAndReturnsOpenExrsMessage) {
  TempDir dir;
  const capsim::SharedLibrary module(CAPSIM_EXR_MODULE_BUILT, "the test");
  const auto write = module.function<decltype(&capsim_write_exr)>("capsim_write_exr");
  const char* names[] = {"a", "b"};
  const float a[] = {1.5f, -2, 0.25f}, b[] = {7, 8, 9};
  const float* planes[] = {a, b};
  char error[1024] = "untouched";
  ASSERT_EQ(write((dir / "m.exr").c_str(), 3, 1, 2, names, planes, error, sizeof error), 0) << error;
  EXPECT_STREQ(error, "untouched");
  auto in = OIIO::ImageInput::open(dir / "m.exr");
  ASSERT_TRUE(in);
  ASSERT_EQ(in->spec().nchannels, 2);
  std::vector<float> px(6);
  ASSERT_TRUE(in->read_image(0, 0, 0, 2, OIIO::TypeDesc::FLOAT, px.data()));
  const std::vector<std::string>& read_names = in->spec().channelnames;
  const auto channel = [&](const std::string& name) {
    const auto c = static_cast<std::size_t>(std::find(read_names.begin(), read_names.end(), name) - read_names.begin());
    return std::vector<float>{px[c], px[2 + c], px[4 + c]};
  };
  EXPECT_EQ(channel("a"), (std::vector<float>{1.5f, -2, 0.25f}));
  EXPECT_EQ(channel("b"), (std::vector<float>{7, 8, 9}));

  const std::string missing = dir / "missing/m.exr";
  ASSERT_EQ(write(missing.c_str(), 3, 1, 2, names, planes, error, sizeof error), 1);
  EXPECT_NE(std::string(error).find("missing/m.exr"), std::string::npos) << error;
  char four[4] = "xyz";
  ASSERT_EQ(write(missing.c_str(), 3, 1, 2, names, planes, four, sizeof four), 1);
  EXPECT_EQ(std::strlen(four), 3u);
  char none[1] = {'x'};
  ASSERT_EQ(write(missing.c_str(), 3, 1, 2, names, planes, none, 0), 1);
  EXPECT_EQ(none[0], 'x');
}

TEST(ImageIo, FailureLeavesNoFile) {
  TempDir dir;
  Framebuffer fb(2, 2);
  EXPECT_THROW(write_image(dir / "missing/x.png", fb), std::runtime_error);
  EXPECT_THROW(write_image(dir / "missing/x.exr", fb), std::runtime_error);
  EXPECT_THROW(write_image(dir / "x.tiff", fb), std::runtime_error);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 0);
}

TEST(ImageIo, PngInMemoryRefusesAWrongSize) {
  EXPECT_THROW((void)encode_png_rgb8(4, 3, std::vector<unsigned char>(35)), std::logic_error);
}

TEST(ImageIo, EqualImagesGiveEqualBytes) {
  TempDir dir;
  Framebuffer fb(4, 4);
  write_image(dir / "a.exr", fb);
  write_image(dir / "b.exr", fb);
  write_image(dir / "a.png", fb);
  write_image(dir / "b.png", fb);
  EXPECT_TRUE(read_file(dir / "a.exr") == read_file(dir / "b.exr"));
  EXPECT_TRUE(read_file(dir / "a.png") == read_file(dir / "b.png"));
}

// A PNG's scanlines put row by row, in an order that leaves bands half full
// for a while, from two threads: the file's image data is the zlib stream of
// the Sub-filtered rows as a whole, filtered here independently. Rows of 2,101
// bytes cross the 48 KiB bands' edges at every offset a 700-pixel row gives.
TEST(ImageIo, PngScanlinesHoldTheSubFilteredRowsCompressed) {
  TempDir dir;
  const int w = 700, h = 90;
  const std::size_t row_bytes = 3 * w;
  std::vector<unsigned char> rgb(row_bytes * h);
  std::uint32_t state = 4242;
  for (std::size_t k = 0; k < rgb.size(); ++k) {
    state = state * 1664525u + 1013904223u;
    rgb[k] = static_cast<unsigned char>((k / 997) % 5 * 40 + ((state >> 28) == 0 ? state >> 24 : 0));
  }
  std::vector<unsigned char> filtered;
  for (int j = 0; j < h; ++j) {
    const unsigned char* p = rgb.data() + j * row_bytes;
    filtered.push_back(1);
    for (std::size_t k = 0; k < row_bytes; ++k) filtered.push_back(static_cast<unsigned char>(p[k] - (k >= 3 ? p[k - 3] : 0)));
  }
  const ZlibStream expected = zlib_compress_in_bands(filtered, 1);

  PngScanlines image(w, h);
  const auto put = [&](int first) {  // rows first, first + 3, ... from the bottom up
    for (int j = h - 1 - first; j >= 0; j -= 3) image.put_row(j, {rgb.data() + j * row_bytes, row_bytes});
  };
  std::thread other(put, 1);
  put(0);
  other.join();
  put(2);
  EXPECT_THROW(image.put_row(0, {rgb.data(), row_bytes}), std::logic_error);  // put twice
  EXPECT_THROW(image.put_row(h, {rgb.data(), row_bytes}), std::logic_error);
  {
    PendingFile out(dir / "x.png");
    write_png(out, image);
    out.commit();
  }
  // The image data: every IDAT chunk's data, in order.
  const std::string file = read_file(dir / "x.png");
  std::string idat;
  for (std::size_t at = 8; at + 12 <= file.size();) {
    const std::size_t length = (std::size_t{static_cast<unsigned char>(file[at])} << 24) |
                               (std::size_t{static_cast<unsigned char>(file[at + 1])} << 16) |
                               (std::size_t{static_cast<unsigned char>(file[at + 2])} << 8) |
                               static_cast<unsigned char>(file[at + 3]);
    if (file.compare(at + 4, 4, "IDAT") == 0) idat += file.substr(at + 8, length);
    at += 12 + length;
  }
  const std::vector<unsigned char> stream = expected.joined();
  EXPECT_TRUE(idat == std::string(stream.begin(), stream.end()));
}

// A row of the wrong size is refused before anything is put.
TEST(ImageIo, PngScanlinesRefuseARowOfTheWrongSize) {
  PngScanlines image(4, 3);
  EXPECT_THROW(image.put_row(1, std::vector<unsigned char>(11)), std::logic_error);
  image.put_row(1, std::vector<unsigned char>(12, 7));
}
