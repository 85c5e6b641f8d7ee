#pragma once
// The message a scene text is refused with, for tests of located errors.

#include "capsim/parser.h"

#include <string>
#include <string_view>

namespace capsim::testing {

// parse_scene's error for `text` read as t.csg, or "parsed without error".
inline std::string refusal(std::string_view text) {
  try {
    parse_scene(text, "t.csg");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "parsed without error";
}

}  // namespace capsim::testing
