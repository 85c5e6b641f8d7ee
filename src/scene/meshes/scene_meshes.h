#pragma once
// polyhedron() and import(): the calls that make a Mesh primitive. Like
// scene_modules.h, these read one call only; parser.cpp places the result.

#include "capsim/scene/scene.h"
#include "scene/reading/scene_syntax.h"

#include <cstddef>
#include <string>
#include <vector>

namespace capsim::scene_file {

// polyhedron(points, faces, convexity), or triangles= for faces (OpenSCAD's
// older name). A mesh that is not closed is refused at the face concerned.
Primitive read_polyhedron(const Call& call);

// import(file, ...) of an .stl, .off, .amf or .3mf file: one closed mesh per
// object of the file (STL and OFF hold one), whose union is the solid. A
// relative path is looked up beside the scene file that names it, in
// `import_dir`, then in the current directory (where an OpenSCAD export
// written elsewhere finds it when run from the model's directory). Files
// larger than max_bytes are refused.
std::vector<Primitive> read_import(const Call& call, const std::string& import_dir, std::size_t max_bytes);

// The file an import names, as OpenSCAD finds it (beside the file that names
// it, in `import_dir`), else in the current directory; refused at the
// argument `file` of `args` when neither holds it.
class Args;
std::string resolve_import(const Args& args, const std::string& file, const std::string& import_dir);

}  // namespace capsim::scene_file
