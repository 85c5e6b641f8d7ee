#pragma once
// linear_extrude() and the 2-D shapes under it. A straight extrusion (no
// twist, one scale for both axes) commutes with the 2-D booleans and
// transforms: the extrusion of A - B is the extrusion of A minus that of B.
// So each 2-D leaf becomes an exact solid leaf of its own (a circle a cone
// or cylinder, a square a box, a polygon a prism or frustum mesh), and the
// 2-D CSG tree becomes the 3-D one; nothing is tessellated or clipped.

#include "capsim/scene/scene.h"
#include "scene/reading/scene_syntax.h"

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

  // A twist, or different scales in x and y (`scale` is then unused): the
  // sides are curved, and each leaf is OpenSCAD's tessellation of it
  // (scene/extrusions/twisted_extrusion.h) with `slices` slices, 0 until the shape's
  // points are known (extrusion_slices).
  double twist = 0;
  glm::dvec2 scale_xy{1.0, 1.0};
  int slices = 0;
  double fn = 0, fa = 12, fs = 2;  // the extrusion's own, for its slices
  bool collars = false;            // leaves reach a slice beyond both caps
  bool curved() const { return twist != 0 || scale_xy.x != scale_xy.y; }
};

// OpenSCAD's number of slices of a curved extrusion, from the points of its
// shape (in extrusion space, at the bottom). Capsim takes every point of
// every leaf, where OpenSCAD takes those of the shape's outline after its
// 2-D booleans; the two agree unless a leaf's points lie outside the shape.
int extrusion_slices(const std::vector<glm::dvec2>& points, const Extrusion& e);

// Refuses a sweep of `path_points` points in `slices` slices whose points
// would pass kMaxTessellatedPoints, before any is made; `what` names the
// extrusion at the head of the message ("this twisted extrusion").
void check_swept_points(std::size_t path_points, int slices, const Loc& loc, std::string_view what);

// Extends the leaves' span beyond both caps (Extrusion::f0, f1).
void extend_beyond_caps(Extrusion& e);

// The box z = 0 .. height (extrusion space) over the leaves' x-y bounds,
// padded: intersected with the leaves' CSG tree, it gives the caps.
Primitive extrusion_slab(const std::vector<Primitive>& leaves, const Extrusion& e, const Loc& loc);

// linear_extrude's arguments, checked: a height within 1e30, scales not
// negative, at most kMaxSlices slices.
Extrusion read_linear_extrude(const Call& call);
inline constexpr int kMaxSlices = 100000;

// A 2-D transform's matrix (x' = m * (x, y, 1)): the plane part of the call's
// 3-D matrix, refused when it flattens the plane.
glm::dmat3 read_transform_2d(const Call& call);

// circle's radius (r or d/2) and square's corner and size, checked.
double circle_radius(const Call& call);
struct SquareSpan {
  glm::dvec2 lo, size;
};
SquareSpan read_square(const Call& call);

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

// A polygon's paths (placed by `plane`) and where each is written.
struct PolygonPaths {
  std::vector<std::vector<glm::dvec2>> paths;
  std::vector<Loc> locs;
};
PolygonPaths read_polygon_paths(const Call& call, const glm::dmat3& plane);

// Whether any path crosses or touches itself or another: such paths are
// clipped first (scene/regions/region_2d.h), not extruded one by one.
bool paths_meet(const std::vector<std::vector<glm::dvec2>>& paths);

// Paths whose nesting is known (parent[k]: the path directly around path k,
// -1 for none), extruded each to a prism; paths may touch at vertices, as
// Clipper's output does.
ExtrudedPaths extrude_nested_paths(const std::vector<std::vector<glm::dvec2>>& paths, const std::vector<int>& parent,
                                   const Extrusion& e, const Loc& loc);

// text()'s glyph contours placed by `plane` (empty contours dropped), refused
// when beyond 1e30 or too many to check.
std::vector<std::vector<glm::dvec2>> read_text_paths(const Call& call, const glm::dmat3& plane);

// text(): its glyphs' contours as OpenSCAD draws them (scene/regions/text_glyphs.h),
// extruded as a polygon's paths. A font's contours do not cross, and its
// holes wind against its solids, so the even-odd rule gives OpenSCAD's
// non-zero union; glyphs that overlap are refused as crossing paths.
ExtrudedPaths extrude_text(const Call& call, const glm::dmat3& plane, const Extrusion& e);

}  // namespace capsim::scene_file
