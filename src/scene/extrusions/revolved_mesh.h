#pragma once
// OpenSCAD 2021.01's mesh of rotate_extrude (GeometryEvaluator.cc,
// rotatePolygon), for what needs the polyhedron OpenSCAD renders rather
// than the exact solid (projection()). Each outline of the sanitized 2-D
// shape is swept through rings at OpenSCAD's angles: for a full turn from
// the -x axis, ring k at -90 + 360 k / n degrees of sin/cos (the legacy
// start), otherwise from the +x axis, ring k at 90 - angle k / n; a point
// (x, z) of the outline goes to (x sin a, x cos a, z). Each side quad is
// the two triangles OpenSCAD writes, and a partial turn is closed by the
// outline itself at both ends.

#include "capsim/scene/triangle_mesh.h"
#include "scene/extrusions/openscad_tessellation.h"
#include "scene/regions/clipper_utils.h"
#include "scene/reading/scene_syntax.h"

#include <glm/glm.hpp>

#include <vector>

namespace capsim::scene_file {

struct RevolvedMeshing {
  double angle = 360;  // degrees: 360, or non-zero in (-360, 360)
  int fragments = 1;   // the rings after the first
  bool flip = false;   // OpenSCAD's flip_faces: each outline walked backwards
};

// OpenSCAD's fragments for `shape` turned by `angle` (as read_rotate_extrude
// reads it): Calc::get_fragments_from_r of the largest |x| scaled by
// |angle| / 360, at least 1. Refuses at loc a shape on both sides of the
// axis, a fragment count fragments_for refuses, and a mesh of more than
// kMaxTessellatedPoints points.
RevolvedMeshing plan_revolved_mesh(const Polygon2d& shape, double angle, const Resolution& res, const Loc& loc);

// One outline's closed surface: OpenSCAD's triangles less those whose
// corners met on the axis (a ring of x = 0 is one point), and the outline
// as a face at each end of a partial turn.
PolygonMesh revolved_outline_mesh(const std::vector<glm::dvec2>& outline, const RevolvedMeshing& plan);

}  // namespace capsim::scene_file
