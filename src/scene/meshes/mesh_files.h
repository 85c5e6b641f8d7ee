#pragma once
// Mesh files import() reads: STL (ASCII and binary), OFF, AMF and 3MF, as
// OpenSCAD 2021.01 writes and reads them.

#include "capsim/scene/triangle_mesh.h"

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace capsim::scene_file {

// A file that cannot be read as a mesh: what() is "PATH:LINE: message" for a
// text file, "PATH: message" otherwise.
class MeshFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// One solid of a mesh file: an STL or OFF file holds one, an AMF or 3MF file
// one per object, which OpenSCAD unites. `name` is how a message names it:
// "the mesh in PATH", "PATH:LINE: object 2" (AMF), "PATH: object 2" (3MF).
struct MeshObject {
  std::string name;
  PolygonMesh mesh;
};

// The solids of an .stl, .off, .amf or .3mf file (by its extension, in any
// case), read whole; a file larger than max_bytes is refused before it is
// read, an empty one as empty. Every coordinate must be a finite number within
// 1e30 of the origin.
std::vector<MeshObject> read_mesh_file(const std::string& path, std::size_t max_bytes);

// Why v cannot be an imported coordinate, or "" when it can: it must be a
// finite number within 1e30 of the origin, the farthest capsim traces.
std::string coordinate_fault(double v);

// A file's bytes, refused (MeshFileError, "PATH: message") when it cannot be
// read or holds more than max_bytes.
std::string read_whole(const std::string& path, std::size_t max_bytes);

// Whether read_mesh_file reads files with this name's extension.
bool is_mesh_file_name(const std::string& path);

}  // namespace capsim::scene_file
