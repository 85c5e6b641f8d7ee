#pragma once
// Solids as OpenSCAD meshes them, under their CSG tree: for what needs the
// polyhedron OpenSCAD renders rather than the exact solid. projection()
// projects it (scene/regions/projection_2d.h); minkowski() and hull() take
// the points of a difference, an intersection or a rotate_extrude from it,
// evaluated by CGAL (scene/meshes/convex_decomposition.h). A sphere, cube or
// cylinder is OpenSCAD's polyhedron of it (scene/extrusions/openscad_tessellation.h),
// a linear_extrude each outline of its region less the paths in it, a
// rotate_extrude OpenSCAD's mesh of the revolution (scene/extrusions/revolved_mesh.h).

#include "capsim/scene/scene.h"
#include "capsim/scene/triangle_mesh.h"
#include "scene/meshes/scene_hulls.h"
#include "scene/reading/scene_syntax.h"

#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace capsim::scene_file {

// Closed meshes under a CSG tree whose leaves index them. A leaf's mesh
// may hold several closed surfaces (a revolved region with holes): the
// solid is then what lies inside an odd number of them.
struct MeshedSolids {
  std::vector<TriangleMesh> meshes;  // CsgNode::primitive indexes these, in the reading's space
  CsgNode root;
  // Per mesh: a path inside an extruded region's outline, taken from it;
  // what it takes never reaches the outline's bounding box.
  std::vector<bool> hole;
};

// The operator the solids are read under, for refusals: `inside` names it
// ("projection()"), `does` says what capsim does with the solids there
// ("projects": "capsim projects sphere, cube, ...").
struct MeshingContext {
  std::string_view inside;
  std::string_view does;
};

// The union of `calls` (each under its transforms and CSG operators) as
// meshes in the calls' own space. Refused at the call concerned: a 2-D
// shape or a module capsim does not mesh, a '!' modifier, and what reading
// each solid refuses (an import's missing file, a sphere of no volume, ...).
// Calls left out by '%' or '*' add nothing.
MeshedSolids read_meshed_solids(std::span<const Call> calls, const FileAccess& files, const MeshingContext& context);

// The bounding box of the solid, when its meshes' boxes decide it: a union's
// is its operands' together, an extruded outline less its holes the
// outline's. nullopt where a difference or intersection must be evaluated.
std::optional<Aabb> known_bounds(const MeshedSolids& solids);

// Whether the tree takes any solid away (a difference or an intersection):
// if not, its points are those of its meshes.
bool only_unions(const CsgNode& node);

}  // namespace capsim::scene_file
