#pragma once
// SHA-256 (FIPS 180-4) of a byte string, as lowercase hex: the content digest
// the reports give for the files a run read, the same `sha256sum FILE` prints,
// so that anyone can check which scene and profile a report came from.

#include <string>
#include <string_view>

namespace capsim {

// 64 lowercase hex digits.
std::string sha256_hex(std::string_view bytes);

// The same of a file's bytes. Throws std::runtime_error "PATH: REASON" if it
// cannot be read.
std::string file_sha256_hex(const std::string& path);

}  // namespace capsim
