#pragma once
// rotate_extrude() and the 2-D shapes under it. A revolution is a pointwise
// preimage: p lies in revolve(S) when (sqrt(px^2 + py^2), pz) lies in S (and p
// in the wedge of a partial turn). So it commutes with the 2-D booleans, as a
// straight extrusion does: each 2-D leaf becomes an exact revolved leaf
// (revolution.h), the 2-D CSG tree the 3-D one, and 2-D transforms act in
// the (r, z) half plane before the turn.

#include "capsim/scene/scene.h"
#include "scene/reading/scene_syntax.h"

#include <string_view>
#include <vector>

namespace capsim::scene_file {

// rotate_extrude's arguments: angle in degrees, from the +x axis,
// counter-clockwise when positive; 360 when |angle| >= 360 (OpenSCAD's rule).
struct Revolve {
  double angle = 360;
};

// Refuses an angle of 0 (no solid) and the 2-D import arguments (file,
// layer, origin, scale): capsim turns 2-D children.
Revolve read_rotate_extrude(const Call& call);

// The revolved leaf of one 2-D shape under rotate_extrude (circle, square,
// polygon or text), placed by `plane` in the (x = r, y = z) half plane. Its
// wedge starts at +x until finish_revolution decides the side.
Primitive revolve_shape(const Call& call, const glm::dmat3& plane, const Revolve& r);

// The revolved leaf of closed paths in the (x = r, y = z) plane under the
// even-odd rule (a 2-D import's outlines): refuses paths that cross and paths
// of no area, at path_locs; `what` names the shape in errors.
Primitive revolve_paths(const std::vector<std::vector<glm::dvec2>>& paths, const std::vector<Loc>& path_locs,
                        const Revolve& r, const Loc& loc, std::string_view what);

// A clipped region's paths (scene/regions/region_2d.h) revolved: Clipper's output
// does not cross, and may touch at vertices, so nothing is checked.
Primitive revolve_region(const std::vector<std::vector<glm::dvec2>>& paths, const Revolve& r, const Loc& loc);

// OpenSCAD's refusal of a 2-D shape whose points reach x = min_x < 0 and
// x = max_x > 0 (both sides of the axis), at loc.
void check_one_side_of_axis(double min_x, double max_x, const Loc& loc);

// After the 2-D tree is built: as OpenSCAD, refuses a shape that reaches both
// sides of the axis (judged by the tree's box: a union's boxes joined, an
// intersection's met, a difference's first), and turns a shape at x <= 0 as
// its mirror image from the -x axis. Rewrites the tree's leaves in `all`.
void finish_revolution(const CsgNode& tree, LargeVector<Primitive>& all, const Revolve& r, const Loc& loc);

}  // namespace capsim::scene_file
