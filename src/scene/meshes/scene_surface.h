#pragma once
// surface(file, center, invert, convexity): a height map (scene/meshes/height_maps.h)
// as a closed Mesh primitive, OpenSCAD's own mesh of it.

#include "capsim/scene/scene.h"
#include "scene/reading/scene_syntax.h"

#include <cstddef>
#include <string>

namespace capsim::scene_file {

// The file is found as import() finds it; a file that cannot be read as a
// height map is refused at the file argument, with the place in the file.
Primitive read_surface(const Call& call, const std::string& import_dir, std::size_t max_bytes);

}  // namespace capsim::scene_file
