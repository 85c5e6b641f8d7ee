// The trace's 8-bit rows against the image library's PNG: the path `capsim
// render` takes to a PNG gives the file a Framebuffer gives.

#include "capsim/image_io.h"
#include "capsim/render.h"
#include "capsim/srgb.h"
#include "support/cli_run.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cstdint>
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

}  // namespace
