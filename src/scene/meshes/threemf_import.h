#pragma once
// import() of a 3MF file, read through lib3mf 1.x as OpenSCAD 2021.01's
// import_3mf.cc reads it: every mesh object of the model, as its vertices and
// triangles give it.

#include "scene/meshes/mesh_files.h"

#include <string>
#include <vector>

namespace capsim::scene_file {

// The mesh objects of a 3MF file's bytes (`data`, read from `path`, which
// messages name). Refused (MeshFileError, "PATH: message") when lib3mf cannot
// read the package, when a coordinate is not one capsim traces, or when no
// mesh object has a triangle.
std::vector<MeshObject> read_3mf(const std::string& path, std::string data);

}  // namespace capsim::scene_file
