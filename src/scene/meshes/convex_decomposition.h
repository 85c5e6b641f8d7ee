#pragma once
// The convex pieces of a solid, as OpenSCAD's minkowski() finds them: the
// Nef polyhedron of its meshes under their CSG tree (CGAL's booleans, exact
// arithmetic), split by CGAL's convex_decomposition_3; the pieces' union is
// the solid. minkowski() distributes over union, so a non-convex child is
// summed piece by piece. The one translation unit that includes CGAL;
// CGAL's templates stay out of every other.

#include "capsim/scene/triangle_mesh.h"
#include "scene/meshes/meshed_solids.h"
#include "scene/work_limits.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace capsim {

// The corners of each convex piece of the solid `solids` evaluates to
// (`split`), or every corner of it as one piece (for a hull), in the meshes'
// coordinates rounded to double from CGAL's exact ones; or why there are
// none: a mesh's triangles do not form a 2-manifold (edges or corners shared
// by more than one sheet), its surface crosses itself, or CGAL refused it (a
// failed precondition). The result is regularized: a face or edge left
// without volume around it (two operands that only touch) is dropped. A solid that
// evaluates to nothing has no pieces. A mesh's closed surfaces meet under
// the even-odd rule. Preconditions: the meshes are closed (build_closed_mesh)
// and have at most kMaxDecomposedTriangles triangles together (the Nef
// polyhedron's exact arithmetic is slow; scene/work_limits.h).
struct ConvexPieces {
  std::optional<std::vector<std::vector<glm::dvec3>>> corners;
  std::string reason;
};
ConvexPieces solid_pieces(const scene_file::MeshedSolids& solids, bool split = true);

// How the refusals of evaluated_corners name what they refuse:
// "<subject> is not supported: <holder> has N triangles, more than the M
// capsim <action>", and "<subject> is not supported: <why>; CGAL splits (or
// evaluates) only a 2-manifold that does not cross itself".
struct EvaluationWords {
  std::string_view subject;  // "hull() of this mesh"
  std::string_view holder;   // what has the triangles: "it"
  std::string_view action;   // "evaluates with CGAL"
};

// solid_pieces(solids, split)'s corners, refused (a SceneError at `call`)
// where the meshes have more than kMaxDecomposedTriangles triangles (before
// CGAL is run) and where CGAL gives no pieces. Precondition: the meshes are
// closed.
std::vector<std::vector<glm::dvec3>> evaluated_corners(const scene_file::MeshedSolids& solids, bool split,
                                                       const scene_file::Call& call, const EvaluationWords& words);

}  // namespace capsim
