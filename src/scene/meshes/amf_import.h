#pragma once
// import() of an AMF file, read as OpenSCAD 2021.01's import_amf.cc reads it:
// each <object>'s vertices (mesh/vertices/vertex/coordinates/x, y, z) and the
// triangles of all its volumes (mesh/volume/triangle/v1, v2, v3), indices
// counting the object's vertices from 0.

#include "scene/meshes/mesh_files.h"

#include <string>
#include <vector>

namespace capsim::scene_file {

// The objects of an AMF file's bytes (`data`, read from `path`, which messages
// name), each one solid. Refused (MeshFileError, "PATH:LINE: message") for
// malformed XML, a vertex without one of its coordinates, a coordinate that is
// not a number capsim traces, a triangle without one of its corners or naming
// a vertex its object does not have, and a file with no triangle; a zipped
// (compressed) AMF file is refused as such ("PATH: message").
std::vector<MeshObject> read_amf(const std::string& path, const std::string& data);

}  // namespace capsim::scene_file
