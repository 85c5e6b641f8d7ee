#pragma once
// projection(cut): the 2-D shape of its solid children (scene/regions/projection_2d.h
// gives the geometry). The children are read here, not placed as leaves of
// the scene's tree: each solid as OpenSCAD meshes it (a sphere is
// OpenSCAD's polyhedron of it, as in the STL OpenSCAD would project), under
// its transforms and CSG operators.

#include "scene/meshes/scene_hulls.h"
#include "scene/reading/scene_syntax.h"

#include <glm/glm.hpp>

#include <vector>

namespace capsim::scene_file {

// The projection's closed paths under the even-odd rule, in its own frame.
// Refused at the child concerned: an extrusion, a 2-D shape or a module
// capsim does not read under projection(), and a '!' modifier.
std::vector<std::vector<glm::dvec2>> read_projection(const Call& call, const FileAccess& files);

}  // namespace capsim::scene_file
