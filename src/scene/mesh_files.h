#pragma once
// Mesh files import() reads: STL (ASCII and binary) and OFF, as OpenSCAD
// writes and reads them.

#include "capsim/triangle_mesh.h"

#include <cstddef>
#include <stdexcept>
#include <string>

namespace capsim::scene_file {

// A file that cannot be read as a mesh: what() is "PATH:LINE: message" for a
// text file, "PATH: message" otherwise.
class MeshFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The polygon faces of an .stl or .off file (by its extension, in any case),
// read whole; a file larger than max_bytes is refused before it is read.
// Every coordinate must be a finite number within 1e30 of the origin.
PolygonMesh read_mesh_file(const std::string& path, std::size_t max_bytes);

// A file's bytes, refused (MeshFileError, "PATH: message") when it cannot be
// read or holds more than max_bytes.
std::string read_whole(const std::string& path, std::size_t max_bytes);

// Whether read_mesh_file reads files with this name's extension.
bool is_mesh_file_name(const std::string& path);

}  // namespace capsim::scene_file
