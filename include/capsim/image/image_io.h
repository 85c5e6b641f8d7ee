#pragma once
// Image output, chosen by the file extension: .png is 8-bit sRGB RGB (libpng for
// the file, libdeflate for the image data);
// .exr is linear float R, G, B, A, Z (distance from the eye, +inf on a miss) and
// id (float primitive index, -1 on a miss), plus any extra channels (OpenEXR).
// The file is written under a temporary name and renamed only on success
// (PendingFile).
//
// These libraries rather than OpenImageIO: linking OpenImageIO loads some
// 250 shared libraries at every start of the program (about half a second),
// which would cost more than tracing a megapixel.

#include "capsim/image/framebuffer.h"
#include "capsim/system/pending_file.h"

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace capsim {

struct ExtraChannel {
  std::string name;
  std::vector<float> values;  // width * height, row 0 at the top
};

// Throws std::runtime_error with the path and the reason on failure (unknown
// extension, unwritable directory, library error); leaves no file behind.
void write_image(const std::string& path, const Framebuffer& fb,
                 const std::vector<ExtraChannel>& extra = {});

// The same into a pending file (its target's extension chooses the format),
// which the caller commits; messages name the target.
void write_image(PendingFile& out, const Framebuffer& fb, const std::vector<ExtraChannel>& extra = {});

// The working memory write_image takes for a width x height image with
// extra_channels extra channels, beyond the framebuffer and channels it is
// given: for a PNG the 8-bit copy, the filtered rows and the compressed data
// (write_png_rgb8_memory), for an EXR a planar copy of every channel.
std::uint64_t write_image_memory(const std::string& path, int width, int height, std::size_t extra_channels);

// The working memory write_png_rgb8 takes beyond its RGB bytes.
std::uint64_t write_png_rgb8_memory(int width, int height);

// True for the extensions write_image accepts (.png, .exr; any case).
bool is_supported_image_path(const std::string& path);

// True for a .png path (any case): an 8-bit image, which needs only colour.
bool is_png_path(const std::string& path);

// An 8-bit sRGB RGB image (3 bytes per pixel, row 0 at the top) as PNG, written
// under a temporary name and renamed on success; throws std::runtime_error.
void write_png_rgb8(const std::string& path, int width, int height,
                    const std::vector<unsigned char>& rgb);
void write_png_rgb8(PendingFile& out, int width, int height, const std::vector<unsigned char>& rgb);

// An 8-bit sRGB RGB image on its way into a PNG's compressed image data.
// Whoever makes a row puts it (put_row), on any thread, for different rows;
// the row is put under the Sub filter (each byte less the same channel of the
// pixel to its left, after the filter-type byte) into the 48 KiB bands the
// image data is compressed in, and the thread that makes a band whole
// compresses it at once, while it is still in cache. A band's memory is then
// used again for a later band: the rows of an image traced top to bottom
// never take more than a few bands, where the whole image's scanlines would
// touch a page of new memory every 4 KiB (docs/performance.md).
class ZlibStream;  // src/image/zlib_bands.h

class PngScanlines {
 public:
  PngScanlines(int width, int height);
  ~PngScanlines();
  PngScanlines(PngScanlines&&) noexcept;
  PngScanlines& operator=(PngScanlines&&) noexcept;

  int width() const { return width_; }
  int height() const { return height_; }

  // Row j's pixels: 3 * width bytes, R, G, B per pixel. Once per row; throws
  // std::logic_error for a row out of range, of another size or put before.
  void put_row(int j, std::span<const unsigned char> rgb);

  // The most bytes of scanlines a width x height image holds at once: every
  // row's filter byte and pixels, should the rows come in an order that makes
  // no band whole before the last.
  static std::uint64_t bytes(int width, int height);

 private:
  friend void write_png(PendingFile& out, PngScanlines& image);
  friend std::vector<unsigned char> encode_png_rgb8(int width, int height, const std::vector<unsigned char>& rgb);
  struct Bands;

  // The image data, compressed; throws std::logic_error if some row was not
  // put. Once: the bands' memory goes with it.
  ZlibStream image_data();

  int width_;
  int height_;
  std::unique_ptr<Bands> bands_;
  std::vector<unsigned char> row_put_;  // per row: 1 once put
};

// That image as a PNG file, the file write_png_rgb8 writes of the same pixels,
// into a pending file the caller commits; throws std::runtime_error, and
// std::logic_error if some row was not put. Once per image.
void write_png(PendingFile& out, PngScanlines& image);

// The working memory write_png takes beyond the scanlines: the compressed data.
std::uint64_t write_png_memory(int width, int height);

// The bytes of that PNG file, in memory (for data URIs). Throws
// std::logic_error if rgb does not hold width * height * 3 bytes.
std::vector<unsigned char> encode_png_rgb8(int width, int height, const std::vector<unsigned char>& rgb);

// The 8-bit sRGB colours (3 bytes per pixel, row 0 at the top) that
// write_image's PNG output of fb holds.
std::vector<unsigned char> srgb8_pixels(const Framebuffer& fb);

}  // namespace capsim
