#pragma once
// projection(): the 2-D shape of solids seen from above. With cut = false it
// is their shadow on the plane z = 0 (the points (x, y) whose vertical line
// meets the solid); with cut = true their section by that plane (the points
// (x, y, 0) inside it).
//
// The solids are given as closed triangle meshes in the projection's own
// space (OpenSCAD's tessellation of spheres, cubes and cylinders, or a
// mesh's own triangles) under a CSG tree, as OpenSCAD projects the
// polyhedron it renders. No boolean of meshes is formed: a vertical line's
// intervals in each mesh are combined through the tree, which decides any
// point exactly. The outline is then found on a grid of such points
// (marching squares, the cell's centre deciding a saddle), and each
// boundary crossing refined by bisection along its grid edge to the
// double's precision. So every outline vertex lies on the true boundary;
// what the grid can miss is a corner (cut within one cell) and a feature
// narrower than a cell. The grid has kProjectionGrid cells along the longer
// side of the solids' box.

#include "capsim/scene/scene.h"
#include "scene/meshes/meshed_solids.h"

#include <glm/glm.hpp>

#include <vector>

namespace capsim::scene_file {

inline constexpr int kProjectionGrid = 512;

// Closed paths, none crossing another, under the even-odd rule; empty when
// the shadow or section is empty. Deterministic: the same solids give the
// same paths.
std::vector<std::vector<glm::dvec2>> project_solids(const MeshedSolids& solids, bool cut);

}  // namespace capsim::scene_file
