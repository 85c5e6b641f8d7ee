#pragma once
// Exact line-revolution intersection (revolution.h): a line meets a turned
// profile in any number of intervals. In the profile plane the line becomes
// the curve (rho(t), z(t)) with rho^2 quadratic in t; it crosses a straight
// edge's surface where a quadratic vanishes (a cone, cylinder or annulus) and
// an ellipse's where a quartic does (polynomial_roots.h). The crossings, in
// order, alternate in and out (even-odd); a partial turn keeps the part of
// them inside its wedge, whose two half planes are the caps.

#include "capsim/scene/revolution.h"
#include "capsim/trace/mesh_geometry.h"
#include "capsim/trace/op_counts.h"

#include <vector>

namespace capsim {

// The crossings of the whole line o + t d (object space, d != 0) with the
// solid, sorted by t, entries and exits alternating from an entry, each with
// its surface (Revolution's numbering). Counts each edge and each ellipse
// tested. `work` is working space.
void revolution_line_crossings(const Revolution& rev, const glm::dvec3& o, const glm::dvec3& d,
                               std::vector<LineCrossing>& out, std::vector<LineCrossing>& work, OpCounts& ops);

// The outward normal (not normalised), object space, at a point q on surface s.
glm::dvec3 revolution_normal(const Revolution& rev, const glm::dvec3& q, int s);

}  // namespace capsim
