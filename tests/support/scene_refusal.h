#pragma once
// The message a scene text is refused with, for tests of located errors.

#include "capsim/scene/parser.h"

#include <string>
#include <string_view>

namespace capsim::testing {

// parse_scene's error for `text` read as `file` (whose folder relative
// imports resolve against), or "parsed without error".
inline std::string refusal(std::string_view text, const std::string& file = "t.csg") {
  try {
    parse_scene(text, file);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "parsed without error";
}

}  // namespace capsim::testing
