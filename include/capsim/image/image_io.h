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

// An 8-bit sRGB RGB image held as a PNG's scanlines: per row, the filter-type
// byte, then 3 bytes per pixel, left to right. Whoever makes a row writes its
// pixels in place (row) and filters it (filter_row) while it is still in cache,
// on any thread, for different rows; writing the file then only compresses.
// This spares write_png_rgb8's copy of the image and its second buffer of
// image size, and, on several threads, the one-thread filtering pass. The
// buffer is not zero-filled: each page is first touched by the thread that
// fills its rows.
class PngScanlines {
 public:
  PngScanlines(int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }

  // Row j's 3 * width bytes, R, G, B per pixel; written before filter_row(j).
  unsigned char* row(int j) { return data_.get() + static_cast<std::size_t>(j) * stride() + 1; }

  // Puts row j, once it is whole, under the Sub filter (each byte less the same
  // channel of the pixel to its left), in place. Once per row.
  void filter_row(int j);

  // Every row's filter byte and bytes, as the PNG's image data compresses
  // them. Throws std::logic_error if some row was not filtered.
  std::span<const unsigned char> filtered() const;

  // The bytes a width x height image takes.
  static std::uint64_t bytes(int width, int height);

 private:
  std::size_t stride() const { return 3 * static_cast<std::size_t>(width_) + 1; }

  int width_;
  int height_;
  std::unique_ptr<unsigned char[]> data_;
  std::vector<unsigned char> row_filtered_;  // per row: 1 once filter_row ran
};

// That image as a PNG file, the file write_png_rgb8 writes of the same pixels,
// into a pending file the caller commits; throws std::runtime_error. The image
// data is compressed on `threads` host threads (0 = all); the file's bytes do
// not depend on them.
void write_png(PendingFile& out, const PngScanlines& image, int threads = 1);

// The working memory write_png takes beyond the scanlines: the compressed data.
std::uint64_t write_png_memory(int width, int height);

// The bytes of that PNG file, in memory (for data URIs). Throws
// std::logic_error if rgb does not hold width * height * 3 bytes.
std::vector<unsigned char> encode_png_rgb8(int width, int height, const std::vector<unsigned char>& rgb);

// The 8-bit sRGB colours (3 bytes per pixel, row 0 at the top) that
// write_image's PNG output of fb holds.
std::vector<unsigned char> srgb8_pixels(const Framebuffer& fb);

}  // namespace capsim
