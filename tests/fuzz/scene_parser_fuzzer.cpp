// Fuzz target: the scene parser on arbitrary bytes.
//
// The contract (include/capsim/scene/parser.h): parse_scene returns a scene or throws
// SceneError. Any other exception escapes and is reported as a crash, as are
// memory errors, undefined behaviour and stack overflow.

#include "capsim/scene/parser.h"

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    (void)capsim::parse_scene(text, "fuzz.csg");
  } catch (const capsim::SceneError&) {
    // A refusal with FILE:LINE:COL is the expected answer to most inputs.
  }
  return 0;
}
