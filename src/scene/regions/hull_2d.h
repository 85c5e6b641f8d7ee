#pragma once
// hull() of 2-D shapes, as OpenSCAD 2021.01's applyHull2D forms it: the
// convex hull (CGAL's convex_hull_2, exact predicates) of every vertex of
// every outline of the shapes, one outline counter-clockwise from the
// lowest-x point, collinear points left out.

#include "scene/regions/clipper_utils.h"

#include <optional>
#include <vector>

namespace capsim::scene_file {

// The hull as one outline (not sanitized, as OpenSCAD leaves it); nullopt
// when the points span no area (fewer than three off one line).
std::optional<Polygon2d> hull_2d(const std::vector<Polygon2d>& shapes);

}  // namespace capsim::scene_file
