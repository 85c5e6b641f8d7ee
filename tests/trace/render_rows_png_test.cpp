// The trace's 8-bit rows against the image library's PNG: the path `capsim
// render` takes to a PNG gives the file a Framebuffer gives.

#include "capsim/image/image_io.h"
#include "capsim/image/srgb.h"
#include "capsim/trace/render.h"
#include "support/cli_run.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <thread>
#include <vector>

using namespace capsim;
using namespace capsim::testing;

namespace {

// The PNG written from rows of samples (the path `capsim render` takes) is the
// one written from a Framebuffer, byte for byte, and holds every pixel's
// encoding: checked on values that vary from pixel to pixel, so the Sub filter
// wraps around in both directions.
TEST(ImageIo, PngFromRowsEqualsPngFromAFramebuffer) {
  TempDir dir;
  const int w = 37, h = 23;
  Framebuffer fb(w, h);
  std::vector<unsigned char> rgb(static_cast<std::size_t>(w) * h * 3);
  std::uint32_t state = 12345;
  for (int j = 0; j < h; ++j) {
    std::vector<PixelSample> row(w);
    for (int i = 0; i < w; ++i) {
      for (int c = 0; c < 3; ++c) {
        state = state * 1664525u + 1013904223u;
        row[i].color[c] = (state >> 8) / 16777216.0 * 1.2 - 0.1;
      }
      set_pixel(fb, i, j, row[i]);
    }
    encode_srgb8_row(row, rgb.data() + static_cast<std::size_t>(j) * w * 3);
  }
  write_image(dir / "fb.png", fb);
  write_png_rgb8(dir / "rows.png", w, h, rgb);
  EXPECT_TRUE(read_file(dir / "fb.png") == read_file(dir / "rows.png"));
  // In memory (the HTML report's data URIs): the same file, and the same
  // colours as the framebuffer's PNG.
  const std::vector<unsigned char> png = encode_png_rgb8(w, h, rgb);
  EXPECT_TRUE(std::string(png.begin(), png.end()) == read_file(dir / "rows.png"));
  EXPECT_TRUE(srgb8_pixels(fb) == rgb);

  auto in = OIIO::ImageInput::open(dir / "rows.png");
  ASSERT_TRUE(in);
  std::vector<unsigned char> px(rgb.size());
  ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, px.data()));
  for (std::size_t k = 0; k < px.size(); ++k)
    ASSERT_EQ(px[k], linear_to_srgb8(fb.rgba[4 * (k / 3) + k % 3])) << "byte " << k;
}

// Rows written in place into the PNG's scanlines and filtered one by one, by
// two threads in no set order, then compressed on three (the path `capsim
// render` takes), give the file write_png_rgb8 writes of the same bytes on one
// thread, and an independent reader finds those bytes in it: at widths where
// the Sub filter has no left neighbour to subtract (one pixel) and where it
// wraps both ways, and at a size whose image data is several bands.
TEST(ImageIo, PngFromScanlinesEqualsPngFromRgb) {
  TempDir dir;
  for (const std::pair<int, int>& shape :
       {std::pair{37, 23}, std::pair{1, 5}, std::pair{64, 1}, std::pair{700, 90}}) {
    const int w = shape.first, h = shape.second;  // plain names: lambdas below capture them
    std::vector<unsigned char> rgb(static_cast<std::size_t>(w) * h * 3);
    std::uint32_t state = 777u + static_cast<std::uint32_t>(w);
    for (unsigned char& b : rgb) {
      state = state * 1664525u + 1013904223u;
      b = static_cast<unsigned char>(state >> 24);
    }
    PngScanlines image(w, h);
    const std::size_t row_bytes = static_cast<std::size_t>(w) * 3;
    const auto fill = [&](int parity) {
      for (int j = h - 1 - parity; j >= 0; j -= 2) {
        image.put_row(j, {rgb.data() + static_cast<std::size_t>(j) * row_bytes, row_bytes});
      }
    };
    std::thread other(fill, 1);
    fill(0);
    other.join();
    PendingFile out(dir / "lines.png");
    write_png(out, image);
    out.commit();
    write_png_rgb8(dir / "rgb.png", w, h, rgb);
    EXPECT_TRUE(read_file(dir / "lines.png") == read_file(dir / "rgb.png")) << w << "x" << h;
    auto in = OIIO::ImageInput::open(dir / "lines.png");
    ASSERT_TRUE(in);
    std::vector<unsigned char> px(rgb.size());
    ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, px.data()));
    EXPECT_TRUE(px == rgb) << w << "x" << h;
  }
}

// A row never put (its pixels perhaps never traced) is refused, and
// nothing is left behind.
TEST(ImageIo, PngScanlinesRefuseARowNotPut) {
  TempDir dir;
  PngScanlines image(4, 3);
  const std::vector<unsigned char> row(12, 9);
  for (const int j : {0, 2}) image.put_row(j, row);
  {
    PendingFile out(dir / "x.png");
    EXPECT_THROW(write_png(out, image), std::logic_error);
  }
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 0);
}

}  // namespace
