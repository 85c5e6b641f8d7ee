#pragma once
// hull() and minkowski(): solids OpenSCAD builds out of its children's
// points, as closed meshes. The children are read here (not placed as leaves
// of the CSG tree): their transforms, and the points OpenSCAD's meshes of
// them have (scene/extrusions/openscad_tessellation.h, polyhedra, imports, surfaces).

#include "capsim/scene.h"
#include "scene/reading/scene_syntax.h"

#include <cstddef>
#include <string>

namespace capsim::scene_file {

// Where files named by import() and surface() under a hull are found, and how
// large they may be (as for the leaves of the tree).
struct FileAccess {
  std::string import_dir;
  std::size_t max_bytes = 0;
};

// hull(): the convex hull of every point of its children, exact for the
// children's meshes (a sphere is OpenSCAD's polyhedron of it, not the true
// sphere). Refused when the children give no volume (none, or all their
// points in one plane), and at a child whose points are not known without
// evaluating CSG (difference, intersection) or that is 2-D.
Primitive read_hull(const Call& call, const FileAccess& files);

// minkowski(): the Minkowski sum of convex children, which is the convex
// hull of the sums of their points (exact for convex meshes). A child that is
// not convex as written (a union of several solids, a non-convex polyhedron,
// import or surface) is refused: its sum needs a convex decomposition.
Primitive read_minkowski(const Call& call, const FileAccess& files);

}  // namespace capsim::scene_file
