#include "capsim/image/image_io.h"

#include "capsim/image/srgb.h"
#include "capsim/system/huge_pages.h"
#include "capsim/system/shared_library.h"
#include "image/exr_writer_module.h"
#include "image/zlib_bands.h"

#include <fmt/core.h>
#include <png.h>

#include <algorithm>
#include <atomic>
#include <array>
#include <cerrno>
#include <cmath>
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>

namespace capsim {

namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// Every row under the Sub filter: one filter rather than libpng's adaptive
// choice, which tries all five on every row: within a few percent of the
// adaptive size on the shipped scenes, at a small part of the cost.
PngScanlines png_scanlines(int width, int height, const unsigned char* rgb) {
  PngScanlines image(width, height);
  const std::size_t row_bytes = static_cast<std::size_t>(width) * 3;
  for (int j = 0; j < height; ++j) image.put_row(j, {rgb + j * row_bytes, row_bytes});
  return image;
}

// Bytes [from, to) of a row's scanline under the Sub filter, rgb being the
// row's pixels: byte 0 is the filter type, byte k > 0 is rgb[k - 1] less the
// same channel of the pixel to its left (none for the first pixel).
void put_sub_filtered(std::span<const unsigned char> rgb, std::size_t from, std::size_t to, unsigned char* out) {
  std::size_t k = from;
  if (k == 0 && k < to) out[k++ - from] = 1;  // filter type Sub
  for (; k < to && k <= 3; ++k) out[k - from] = rgb[k - 1];
  for (; k < to; ++k) out[k - from] = static_cast<unsigned char>(rgb[k - 1] - rgb[k - 4]);
}

// Where libpng's output goes, and what went wrong: the first write error's
// errno (libpng's own message for it is only "Write Error"), or libpng's message.
struct PngSink {
  std::FILE* file;
  int write_errno = 0;
  std::string message;
};

void png_write_to_sink(png_structp png, png_bytep data, png_size_t size) {
  auto* sink = static_cast<PngSink*>(png_get_io_ptr(png));
  if (std::fwrite(data, 1, size, sink->file) != size) {
    sink->write_errno = errno;
    png_error(png, "write error");
  }
}

void png_flush_sink(png_structp png) {
  auto* sink = static_cast<PngSink*>(png_get_io_ptr(png));
  if (std::fflush(sink->file) != 0) {
    sink->write_errno = errno;
    png_error(png, "write error");
  }
}

// Keeps libpng's message for the exception instead of printing it.
[[noreturn]] void png_keep_error(png_structp png, png_const_charp message) {
  static_cast<PngSink*>(png_get_error_ptr(png))->message = message;
  png_longjmp(png, 1);
}

// libpng writes the signature, the header and colour chunks, and the CRCs; the
// image data comes ready, compressed band by band (ZlibBandWriter). libpng
// reports errors by longjmp; this frame holds nothing that needs destroying,
// so jumping out of it is safe, and what the callbacks record lives in the
// caller's frame (an object of this one changed after setjmp would be
// indeterminate after the jump).
// Returns the error text or "".
std::string png_write_chunks(PngSink& sink, int width, int height, const ZlibStream& idat) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &sink, png_keep_error, nullptr);
  if (!png) return "cannot start the PNG encoder";
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    if (sink.write_errno != 0) return std::strerror(sink.write_errno);
    return sink.message.empty() ? "PNG encoding failed" : "PNG encoding failed: " + sink.message;
  }
  png_set_write_fn(png, &sink, png_write_to_sink, png_flush_sink);
  png_set_IHDR(png, info, width, height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  png_write_info(png, info);
  // One IDAT chunk, its data written piece by piece: the bytes png_write_chunk
  // writes of the joined stream, and its limit on a chunk's length.
  const std::size_t idat_size = idat.size();
  if (idat_size > PNG_UINT_31_MAX) png_error(png, "length exceeds PNG maximum");
  png_write_chunk_start(png, reinterpret_cast<png_const_bytep>("IDAT"), static_cast<png_uint_32>(idat_size));
  for (std::size_t k = 0; k < idat.pieces(); ++k) png_write_chunk_data(png, idat.piece(k).data(), idat.piece(k).size());
  png_write_chunk_end(png);
  png_write_chunk(png, reinterpret_cast<png_const_bytep>("IEND"), nullptr, 0);
  png_write_flush(png);
  png_destroy_write_struct(&png, &info);
  return "";
}

// Writes to out's temporary file; messages name its target.
void write_png_file(const PendingFile& out, int width, int height, const ZlibStream& idat) {
  const std::string& path = out.target();
  std::FILE* f = std::fopen(out.temp_path().c_str(), "wb");
  if (!f) throw std::runtime_error(fmt::format("{}: {}", path, std::strerror(errno)));
  PngSink sink{f, 0, ""};
  const std::string error = png_write_chunks(sink, width, height, idat);
  const bool closed = std::fclose(f) == 0;
  const int close_error = errno;
  if (!error.empty()) throw std::runtime_error(fmt::format("{}: {}", path, error));
  if (!closed) throw std::runtime_error(fmt::format("{}: {}", path, std::strerror(close_error)));
}

// The EXR writer's module (src/image/exr_writer_module.h): where an
// installed capsim keeps it, seen from the program's directory
// (CAPSIM_EXR_MODULE_FROM_BIN, from CMakeLists.txt), else where this build
// made it (CAPSIM_EXR_MODULE_BUILT), for the programs of the build tree.
#if !defined(CAPSIM_EXR_MODULE_FROM_BIN) || !defined(CAPSIM_EXR_MODULE_BUILT)
#error "CMakeLists.txt defines CAPSIM_EXR_MODULE_FROM_BIN and CAPSIM_EXR_MODULE_BUILT for this file"
#endif
std::string exr_module_path() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const std::filesystem::path installed = (exe.parent_path() / CAPSIM_EXR_MODULE_FROM_BIN).lexically_normal();
    if (std::filesystem::is_regular_file(installed, ec)) return installed.string();
  }
  return CAPSIM_EXR_MODULE_BUILT;
}

const SharedLibrary& exr_module() {
  static const SharedLibrary module(exr_module_path(), "EXR output");
  return module;
}

void write_exr_file(const PendingFile& out, const Framebuffer& fb, const std::vector<ExtraChannel>& extra) {
  const std::size_t pixels = static_cast<std::size_t>(fb.width) * fb.height;
  // The channels in the order the header lists them: R, G, B and A as planar
  // copies of the interleaved colour, the others as they are.
  static constexpr const char* kColourNames[] = {"R", "G", "B", "A"};
  std::vector<LargeVector<float>> colour(4, LargeVector<float>(pixels));
  std::vector<const char*> names;
  std::vector<const float*> values;
  for (std::size_t c = 0; c < 4; ++c) {
    for (std::size_t k = 0; k < pixels; ++k) colour[c][k] = fb.rgba[4 * k + c];
    names.push_back(kColourNames[c]);
    values.push_back(colour[c].data());
  }
  names.push_back("Z");
  values.push_back(fb.depth.data());
  names.push_back("id");
  values.push_back(fb.id.data());
  for (const ExtraChannel& e : extra) {
    names.push_back(e.name.c_str());
    values.push_back(e.values.data());
  }
  char error[1024] = "";
  const auto write = exr_module().function<decltype(&capsim_write_exr)>("capsim_write_exr");
  if (write(out.temp_path().c_str(), fb.width, fb.height, static_cast<int>(names.size()), names.data(),
            values.data(), error, sizeof error) != 0) {
    // OpenEXR names the file it was given: name the target instead.
    std::string message = error;
    for (auto at = message.find(out.temp_path()); at != std::string::npos; at = message.find(out.temp_path()))
      message.replace(at, out.temp_path().size(), out.target());
    throw std::runtime_error(fmt::format("{}: {}", out.target(), message));
  }
}

}  // namespace

bool is_supported_image_path(const std::string& path) {
  const std::string ext = lower_extension(path);
  return ext == ".png" || ext == ".exr";
}

bool is_png_path(const std::string& path) { return lower_extension(path) == ".png"; }

// The bands of a PngScanlines' image data: each band's room while its rows
// come in, and the compressed stream they go to.
struct PngScanlines::Bands {
  explicit Bands(std::uint64_t size)
      : writer(size), filled(std::make_unique<std::atomic<std::size_t>[]>(writer.bands())), rooms(writer.bands()) {}

  // Band b's room, taken when its first bytes come.
  unsigned char* room(std::size_t b) {
    const std::lock_guard<std::mutex> lock(mutex);
    if (!rooms[b]) {
      if (spare.empty()) {
        rooms[b] = std::make_unique_for_overwrite<unsigned char[]>(writer.band_bytes());
      } else {
        rooms[b] = std::move(spare.back());
        spare.pop_back();
      }
    }
    return rooms[b].get();
  }

  // Adds n bytes put into band b's room; the thread that makes it whole
  // compresses it and leaves the room for a later band. Each thread adds
  // after writing, so the last to add sees every thread's bytes.
  void filled_by(std::size_t b, std::size_t n) {
    const std::size_t size = writer.band_size(b);
    if (filled[b].fetch_add(n, std::memory_order_acq_rel) + n != size) return;
    unsigned char* data;
    {
      const std::lock_guard<std::mutex> lock(mutex);
      data = rooms[b].get();
    }
    writer.compress(b, {data, size});
    const std::lock_guard<std::mutex> lock(mutex);
    spare.push_back(std::move(rooms[b]));
  }

  ZlibBandWriter writer;
  std::unique_ptr<std::atomic<std::size_t>[]> filled;  // bytes put into each band
  std::mutex mutex;                                     // guards rooms and spare
  std::vector<std::unique_ptr<unsigned char[]>> rooms;  // of the bands filling
  std::vector<std::unique_ptr<unsigned char[]>> spare;  // of bands compressed
};

PngScanlines::PngScanlines(int width, int height)
    : width_(width),
      height_(height),
      bands_(std::make_unique<Bands>(bytes(width, height))),
      row_put_(static_cast<std::size_t>(height), 0) {}

PngScanlines::~PngScanlines() = default;
PngScanlines::PngScanlines(PngScanlines&&) noexcept = default;
PngScanlines& PngScanlines::operator=(PngScanlines&&) noexcept = default;

std::uint64_t PngScanlines::bytes(int width, int height) {
  return (static_cast<std::uint64_t>(width) * 3 + 1) * static_cast<std::uint64_t>(height);
}

void PngScanlines::put_row(int j, std::span<const unsigned char> rgb) {
  const std::size_t stride = 3 * static_cast<std::size_t>(width_) + 1;
  if (j < 0 || j >= height_ || rgb.size() + 1 != stride)
    throw std::logic_error(fmt::format("PNG scanlines: row {} of {} bytes for a {}x{} image", j, rgb.size(),
                                       width_, height_));
  if (row_put_[static_cast<std::size_t>(j)]) throw std::logic_error(fmt::format("PNG scanlines: row {} put twice", j));
  row_put_[static_cast<std::size_t>(j)] = 1;
  const std::size_t band = bands_->writer.band_bytes();
  const std::uint64_t begin = static_cast<std::uint64_t>(j) * stride;
  // The row's bytes in each band they fall in, the band's offset to the row's.
  for (std::size_t k = 0; k < stride;) {
    const std::uint64_t at = begin + k;
    const auto b = static_cast<std::size_t>(at / band);
    const auto offset = static_cast<std::size_t>(at - static_cast<std::uint64_t>(b) * band);
    const std::size_t n = std::min(band - offset, stride - k);
    put_sub_filtered(rgb, k, k + n, bands_->room(b) + offset);
    bands_->filled_by(b, n);
    k += n;
  }
}

ZlibStream PngScanlines::image_data() {
  if (std::find(row_put_.begin(), row_put_.end(), 0) != row_put_.end())
    throw std::logic_error("PNG scanlines: a row was not put");
  ZlibStream idat = bands_->writer.finish();
  bands_.reset();
  return idat;
}

void write_png(PendingFile& out, PngScanlines& image) {
  write_png_file(out, image.width(), image.height(), image.image_data());
}

std::uint64_t write_png_memory(int width, int height) {
  return zlib_compress_in_bands_memory(PngScanlines::bytes(width, height));
}

std::uint64_t write_png_rgb8_memory(int width, int height) {
  return PngScanlines::bytes(width, height) + write_png_memory(width, height);
}

std::uint64_t write_image_memory(const std::string& path, int width, int height, std::size_t extra_channels) {
  const std::uint64_t pixels = static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
  if (is_png_path(path)) return pixels * 3 + write_png_rgb8_memory(width, height);
  return pixels * (6 + extra_channels) * sizeof(float);
}

void write_png_rgb8(PendingFile& out, int width, int height, const std::vector<unsigned char>& rgb) {
  if (rgb.size() != static_cast<std::size_t>(width) * height * 3)
    throw std::logic_error(
        fmt::format("{}: {} bytes for a {}x{} RGB image", out.target(), rgb.size(), width, height));
  PngScanlines image = png_scanlines(width, height, rgb.data());
  write_png(out, image);
}

void write_png_rgb8(const std::string& path, int width, int height, const std::vector<unsigned char>& rgb) {
  PendingFile out(path);
  write_png_rgb8(out, width, height, rgb);
  out.commit();
}

void write_image(const std::string& path, const Framebuffer& fb, const std::vector<ExtraChannel>& extra) {
  if (!is_supported_image_path(path))
    throw std::runtime_error(fmt::format("{}: unsupported image type (use .png or .exr)", path));
  PendingFile out(path);
  write_image(out, fb, extra);
  out.commit();
}

void write_image(PendingFile& out, const Framebuffer& fb, const std::vector<ExtraChannel>& extra) {
  const std::string& path = out.target();
  if (!is_supported_image_path(path))
    throw std::runtime_error(fmt::format("{}: unsupported image type (use .png or .exr)", path));
  const std::size_t pixels = static_cast<std::size_t>(fb.width) * fb.height;
  for (const ExtraChannel& c : extra)
    if (c.values.size() != pixels)
      throw std::logic_error(fmt::format("channel {} has {} values for {} pixels", c.name, c.values.size(), pixels));

  if (is_png_path(path)) {
    // 8-bit sRGB; the background is opaque, coverage lives in the EXR.
    const Srgb8Encoder& encode = srgb8_encoder();
    std::vector<unsigned char> rgb(pixels * 3);
    for (std::size_t k = 0; k < pixels; ++k)
      for (int c = 0; c < 3; ++c) rgb[3 * k + c] = encode(fb.rgba[4 * k + c]);
    write_png_rgb8(out, fb.width, fb.height, rgb);
  } else {
    write_exr_file(out, fb, extra);
  }
}

std::vector<unsigned char> encode_png_rgb8(int width, int height, const std::vector<unsigned char>& rgb) {
  if (rgb.size() != static_cast<std::size_t>(width) * height * 3)
    throw std::logic_error(fmt::format("{} bytes for a {}x{} RGB image", rgb.size(), width, height));
  // The file writer's own path, into a memory stream.
  char* data = nullptr;
  std::size_t size = 0;
  std::FILE* f = open_memstream(&data, &size);
  if (!f) throw std::bad_alloc();
  PngSink sink{f, 0, ""};
  PngScanlines image = png_scanlines(width, height, rgb.data());
  const ZlibStream idat = image.image_data();
  const std::string error = png_write_chunks(sink, width, height, idat);
  std::fclose(f);
  std::vector<unsigned char> png(data, data + size);
  std::free(data);
  if (!error.empty()) throw std::runtime_error(error);
  return png;
}

std::vector<unsigned char> srgb8_pixels(const Framebuffer& fb) {
  const Srgb8Encoder& encode = srgb8_encoder();
  const std::size_t pixels = static_cast<std::size_t>(fb.width) * fb.height;
  std::vector<unsigned char> rgb(pixels * 3);
  for (std::size_t k = 0; k < pixels; ++k)
    for (int c = 0; c < 3; ++c) rgb[3 * k + c] = encode(fb.rgba[4 * k + c]);
  return rgb;
}

}  // namespace capsim
