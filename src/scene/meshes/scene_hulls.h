#pragma once
// hull() and minkowski(): solids OpenSCAD builds out of its children's
// points, as closed meshes. The children are read here (not placed as leaves
// of the CSG tree): their transforms, and the points OpenSCAD's meshes of
// them have (scene/extrusions/openscad_tessellation.h, polyhedra, imports,
// surfaces, linear extrusions as scene/extrusions/extruded_region.h meshes them).

#include "capsim/scene/scene.h"
#include "scene/reading/scene_syntax.h"
#include "scene/work_limits.h"

#include <cstddef>
#include <string>
#include <vector>

namespace capsim::scene_file {

// Where files named by import() and surface() under a hull are found, and how
// large they may be (as for the leaves of the tree).
struct FileAccess {
  std::string import_dir;
  std::size_t max_bytes = 0;
};

// hull(): the convex hull of every point of its children, exact for the
// children's meshes (a sphere is OpenSCAD's polyhedron of it, not the true
// sphere). A difference or intersection gives the corners of the solid
// CGAL evaluates it to from OpenSCAD's meshes (scene/meshes/meshed_solids.h),
// a rotate_extrude those of OpenSCAD's mesh of it. Refused when the children
// give no volume (none, or all their points in one plane), at a 2-D child,
// and at a difference or intersection CGAL cannot evaluate or of more than
// kMaxDecomposedTriangles triangles.
Primitive read_hull(const Call& call, const FileAccess& files);

// minkowski(): the Minkowski sum of its children, as OpenSCAD makes it. The
// sum distributes over union, so each child is taken as convex parts (each
// solid of a union; a non-convex polyhedron, import, surface or
// linear_extrude, each outline of the extrusion less its holes, a
// rotate_extrude, and the solid a difference or intersection evaluates to,
// split into convex pieces by CGAL, scene/meshes/convex_decomposition.h,
// as OpenSCAD splits them) and the sum is
// the union of the hulls of the point sums of every choice of one part per
// child: one convex mesh leaf each (exact for the children's meshes).
// Refused: what hull() refuses, a non-convex solid CGAL cannot split (not a
// 2-manifold, crossing itself) or of more than kMaxDecomposedTriangles
// triangles, more than kMaxMinkowskiParts parts, and more than
// kMaxTessellatedPoints point sums at one child.
std::vector<Primitive> read_minkowski(const Call& call, const FileAccess& files);

}  // namespace capsim::scene_file
