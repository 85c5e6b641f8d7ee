#pragma once
// linear_extrude() as closed meshes, as OpenSCAD meshes it: for the readers
// that need its solid's points rather than exact leaves (projection, hull,
// minkowski). Each path of its region (scene/regions/region_2d.h) swept as
// OpenSCAD sweeps it (one slice when straight); the region's even-odd rule
// makes the solid each path at even depth less the paths directly in it.

#include "capsim/scene/triangle_mesh.h"
#include "scene/regions/region_2d.h"
#include "scene/reading/scene_syntax.h"

#include <glm/glm.hpp>

#include <string_view>
#include <vector>

namespace capsim::scene_file {

struct ExtrudedRegion {
  std::vector<TriangleMesh> meshes;  // one per path, in the extrusion's frame
  std::vector<int> parent;           // the path directly around each, or -1
  glm::dmat4 to_call{1.0};           // the extrusion's frame in the call's (centring)
  // Whether path k bounds solid (an outline) rather than a hole.
  bool outline(std::size_t k) const {
    int depth = 0;
    for (int at = parent[k]; at >= 0; at = parent[static_cast<std::size_t>(at)]) ++depth;
    return depth % 2 == 0;
  }
};

// Refused at the call when a swept path is not a closed solid, the message
// naming `under` (the operator it is read under, e.g. "projection()").
ExtrudedRegion extruded_region(const Call& call, const RegionSources& sources, std::string_view under);

}  // namespace capsim::scene_file
