#pragma once
// The convex pieces of a closed mesh, as OpenSCAD's minkowski() finds them:
// CGAL's convex_decomposition_3 on the mesh's Nef polyhedron (exact
// arithmetic), whose pieces' union is the solid. minkowski() distributes over
// union, so a non-convex child is summed piece by piece. The one translation
// unit that includes CGAL; CGAL's templates stay out of every other.

#include "capsim/triangle_mesh.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace capsim {

// The corners of each convex piece of the solid a mesh bounds, less those of
// `holes` (the holes of an extruded region, inside it), in the mesh's
// coordinates rounded to double from CGAL's exact ones; or why there are
// none: a mesh's triangles do not form a 2-manifold (edges or corners shared
// by more than one sheet), its surface crosses itself, or CGAL refused it (a
// failed precondition). Precondition: the meshes are closed and oriented
// (build_closed_mesh) and have at most kMaxDecomposedTriangles triangles
// together: the Nef polyhedron's exact arithmetic is slow, about 25 s on one
// core for a surface() of 35 x 35 random heights (some 4,900 triangles), 3 s
// for one of 15 x 15.
struct ConvexPieces {
  std::optional<std::vector<std::vector<glm::dvec3>>> corners;
  std::string reason;
};
ConvexPieces convex_pieces(const TriangleMesh& mesh, const std::vector<const TriangleMesh*>& holes = {});
inline constexpr std::size_t kMaxDecomposedTriangles = 5000;

}  // namespace capsim
