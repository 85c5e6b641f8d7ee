#include "image/exr_writer_module.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>

#include <algorithm>
#include <cstring>
#include <exception>

namespace {

// text into error[0..size), cut to fit and NUL-terminated.
void copy_message(const char* text, char* error, std::size_t size) {
  if (size == 0) return;
  const std::size_t n = std::min(std::strlen(text), size - 1);
  std::memcpy(error, text, n);
  error[n] = '\0';
}

}  // namespace

extern "C" int capsim_write_exr(const char* path, int width, int height, int channels,
                                const char* const* names, const float* const* planes, char* error,
                                std::size_t error_size) {
  try {
    Imf::Header header(width, height);
    Imf::FrameBuffer frame;
    for (int k = 0; k < channels; ++k) {
      header.channels().insert(names[k], Imf::Channel(Imf::FLOAT));
      // OpenEXR reads a slice through a char*; it never writes to it.
      frame.insert(names[k], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(const_cast<float*>(planes[k])),
                                        sizeof(float), sizeof(float) * static_cast<std::size_t>(width)));
    }
    Imf::OutputFile file(path, header);
    file.setFrameBuffer(frame);
    file.writePixels(height);
    return 0;
  } catch (const std::exception& e) {
    copy_message(e.what(), error, error_size);
    return 1;
  } catch (...) {
    copy_message("OpenEXR failed for a reason it did not name", error, error_size);
    return 1;
  }
}
