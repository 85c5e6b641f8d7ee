#pragma once
// linear_extrude() and the 2-D shapes under it. A straight extrusion (no
// twist, one scale for both axes) commutes with the 2-D booleans and
// transforms: the extrusion of A - B is the extrusion of A minus that of B.
// So each 2-D leaf becomes an exact solid leaf of its own (a circle a cone
// or cylinder, a square a box, a polygon a prism or frustum mesh), and the
// 2-D CSG tree becomes the 3-D one; nothing is tessellated or clipped.

#include "capsim/scene.h"
#include "scene/scene_syntax.h"

#include <vector>

namespace capsim::scene_file {

// linear_extrude's arguments. The solid spans z = 0 .. height (-height/2 ..
// height/2 when centred); at height z the shape is scaled by
// 1 + (scale - 1) z / height about the origin.
struct Extrusion {
  double height = 100;
  bool center = false;
  double scale = 1;
  // The height fractions each leaf's solid spans: 0 to 1, or beyond both
  // caps (as far as the scale keeps the shape from shrinking to nothing)
  // when the extrusion holds several leaves, whose common caps a slab then
  // cuts once (extrusion_slab): coplanar caps of a leaf and of the leaf
  // subtracted from it would leave the hole's cap undecided.
  double f0 = 0, f1 = 1;
  double factor(double f) const { return 1 + (scale - 1) * f; }
};

// Extends the leaves' span beyond both caps (Extrusion::f0, f1).
void extend_beyond_caps(Extrusion& e);

// The box z = 0 .. height (extrusion space) over the leaves' x-y bounds,
// padded: intersected with the leaves' CSG tree, it gives the caps.
Primitive extrusion_slab(const std::vector<Primitive>& leaves, const Extrusion& e, const Loc& loc);

// Refuses a twist other than 0 and a scale that differs between x and y
// (their side faces are curved) with the reason.
Extrusion read_linear_extrude(const Call& call);

// A 2-D transform's matrix (x' = m * (x, y, 1)): the plane part of the call's
// 3-D matrix, refused when it flattens the plane.
glm::dmat3 read_transform_2d(const Call& call);

// circle's radius (r or d/2) and square's corner and size, checked.
double circle_radius(const Call& call);
struct SquareSpan {
  glm::dvec2 lo, size;
};
SquareSpan read_square(const Call& call);

// polygon's paths placed by `plane`, each with where it is given (the points
// when there are no paths), and text()'s glyph contours placed by `plane`
// (see extrude_text), not yet checked.
std::vector<std::vector<glm::dvec2>> polygon_paths(const Call& call, const glm::dmat3& plane,
                                                   std::vector<Loc>& path_locs);
std::vector<std::vector<glm::dvec2>> text_paths(const Call& call, const glm::dmat3& plane);

// Refuses paths that cross themselves or each other and paths of no area,
// at the path's place; `what` names the shape.
void check_simple_paths(const std::vector<std::vector<glm::dvec2>>& paths, const std::vector<Loc>& path_locs,
                        std::string_view what);

// The extruded solid of a circle or a square placed by `plane` in extrusion
// space (to_world is the extrusion's, before the enclosing 3-D transforms).
Primitive extrude_circle(const Call& call, const glm::dmat3& plane, const Extrusion& e);
Primitive extrude_square(const Call& call, const glm::dmat3& plane, const Extrusion& e);

// A polygon's extruded paths, each a prism (or frustum) mesh, with the path
// each lies directly inside (-1 for none). OpenSCAD's even-odd rule over
// paths that do not cross: a point is in the polygon when an odd number of
// paths hold it, so a path at even depth is an outline and those directly
// inside it are its holes. Refuses paths that cross themselves or each other
// and paths of no area.
struct ExtrudedPaths {
  std::vector<Primitive> prisms;
  std::vector<int> parent;
};
ExtrudedPaths extrude_polygon(const Call& call, const glm::dmat3& plane, const Extrusion& e);

// Closed paths (already in extrusion space) extruded under the even-odd rule,
// as extrude_polygon does; `what` names the shape in errors.
ExtrudedPaths extrude_paths(const std::vector<std::vector<glm::dvec2>>& paths, const std::vector<Loc>& path_locs,
                            const Extrusion& e, const Loc& loc, std::string_view what);

// text(): its glyphs' contours as OpenSCAD draws them (scene/text_glyphs.h),
// extruded as a polygon's paths. A font's contours do not cross, and its
// holes wind against its solids, so the even-odd rule gives OpenSCAD's
// non-zero union; glyphs that overlap are refused as crossing paths.
ExtrudedPaths extrude_text(const Call& call, const glm::dmat3& plane, const Extrusion& e);

}  // namespace capsim::scene_file
