#pragma once
// A shipped model (scenes/NAME) parsed and prepared at a screen size.

#include "capsim/scene/parser.h"
#include "capsim/trace/prepared_scene.h"

#include <string>

namespace capsim::testing {

inline PreparedScene shipped_scene(const std::string& name, int width, int height) {
  PrepareOptions prep;
  prep.width = width;
  prep.height = height;
  return prepare_scene(parse_scene_file(std::string(CAPSIM_SOURCE_DIR) + "/scenes/" + name), prep);
}

}  // namespace capsim::testing
