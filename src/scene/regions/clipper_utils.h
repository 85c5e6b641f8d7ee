#pragma once
// OpenSCAD 2021.01's 2-D geometry engine (its ClipperUtils over Clipper 1):
// a shape is a set of outlines in doubles; every boolean and offset scales
// them by 2^16 to Clipper's integers (truncating), runs Clipper, and cleans
// the result back into doubles. Keeping OpenSCAD's steps, scale and fill
// rules gives OpenSCAD's own vertices, so an extrusion of the result matches
// the mesh OpenSCAD exports.

#include <glm/glm.hpp>

#include <polyclipping/clipper.hpp>

#include <stdexcept>
#include <vector>

namespace capsim::scene_file {

// OpenSCAD's CLIPPER_SCALE: 2-D coordinates are multiples of 2^-16 after
// any clipping.
inline constexpr double kClipperScale = 65536.0;
// The farthest from the origin a clipped coordinate may lie: Clipper's
// integers hold up to 2^62 (its hiRange) after scaling.
inline constexpr double kMaxClippedCoordinate = 4.6e18 / kClipperScale;

// One closed outline; `positive` for one wound counter-clockwise (a solid
// under the non-zero rule), false for a hole.
struct Outline2d {
  std::vector<glm::dvec2> vertices;
  bool positive = true;
};

// A 2-D shape. Sanitized: outlines that do not cross, solids counter-
// clockwise and holes clockwise (Clipper's output). Not sanitized: as drawn,
// read under the even-odd rule.
struct Polygon2d {
  std::vector<Outline2d> outlines;
  bool sanitized = false;
};

// A coordinate beyond kMaxClippedCoordinate (Clipper cannot hold it).
class ClipperRangeError : public std::range_error {
 public:
  using std::range_error::range_error;
};

// The even-odd union of the outlines (OpenSCAD's ClipperUtils::sanitize).
Polygon2d sanitize(const Polygon2d& shape);

// Union, difference (the first less the rest) or intersection of shapes,
// under the non-zero rule, each shape sanitized first when it is not
// (ClipperUtils::apply). An intersection runs pairwise from the first.
Polygon2d clip_shapes(const std::vector<Polygon2d>& shapes, ClipperLib::ClipType type);

// ClipperOffset of every outline by `delta` (negative: inwards) with the
// join, miter limit and arc tolerance (in shape units) given
// (ClipperUtils::applyOffset).
Polygon2d apply_offset(const Polygon2d& shape, double delta, ClipperLib::JoinType join, double miter_limit,
                       double arc_tolerance);

// The Minkowski sum of 2-D shapes, as OpenSCAD 2021.01's applyMinkowski
// forms it: pairwise from the first, each step the union (non-zero rule) of
// the quadrilaterals one shape's outlines sweep along the other's edges and
// of each shape placed inside the other's solid outlines. Precondition: at
// least one shape.
Polygon2d minkowski_sum(const std::vector<Polygon2d>& shapes);

// The outlines as Clipper paths, orientation kept when sanitized, else
// every outline turned counter-clockwise (ClipperUtils::fromPolygon2d).
ClipperLib::Paths to_clipper(const Polygon2d& shape);

// A PolyTree's contours, each cleaned (ClipperLib::CleanPolygon) and kept when
// 3 or more vertices remain (ClipperUtils::toPolygon2d).
Polygon2d from_clipper(const ClipperLib::PolyTree& tree);

}  // namespace capsim::scene_file
