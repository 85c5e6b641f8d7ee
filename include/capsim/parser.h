#pragma once
// Reads a scene file: OpenSCAD's CSG tree (what `openscad -o model.csg` writes)
// plus camera(), light(), material() and background() statements in the same
// grammar. docs/scene-format.md gives the grammar and the list of refusals.

#include "capsim/scene.h"

#include <string>
#include <string_view>

namespace capsim {

// Throws SceneError ("FILE:LINE:COL: message") on any input outside the supported
// subset and on every bad value; never returns a partial scene.
Scene parse_scene(std::string_view text, const std::string& file_name);
Scene parse_scene_file(const std::string& path);

}  // namespace capsim
