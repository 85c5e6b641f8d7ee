#pragma once
// The EXR writer as a module of its own, libcapsim_exr.so (built from
// src/exr_module/exr_writer_module.cpp), which capsim opens the first time
// it writes an .exr (src/image/image_io.cpp). OpenEXR has a C++ interface
// only, which dlsym cannot reach by name; linked into capsim, its four
// libraries were loaded and relocated on every run, some 0.9 ms
// (docs/performance.md, "Start-up"). The module's one entry point is a C
// function, found by name as shared_library.h finds any other.

#include <cstddef>

extern "C" {

// Writes a scanline EXR file at `path`, width x height pixels, OpenEXR's
// default header (ZIP compression), with `channels` FLOAT channels: channel k
// named names[k], its values planes[k] (width * height floats, row by row from
// the top). Returns 0; or 1 when OpenEXR refuses, with its message in `error`,
// cut to error_size - 1 bytes and NUL-terminated. Never throws.
int capsim_write_exr(const char* path, int width, int height, int channels, const char* const* names,
                     const float* const* planes, char* error, std::size_t error_size);

}  // extern "C"
