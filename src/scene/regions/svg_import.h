#pragma once
// 2-D import() of an SVG file, read as OpenSCAD 2021.01 reads it (its
// import_svg.cc over its libsvg): the shapes rect, circle, ellipse, line,
// polygon, polyline and path, under the transforms of their groups, placed
// on the page by the svg element's width, height, viewBox and
// preserveAspectRatio in millimetres at the import's dpi (OpenSCAD's default
// 72), y pointing up. Each shape is its outlines under the even-odd rule, an
// open outline (a line, a polyline, a path that does not come back to its
// start) stroked by Clipper's offset at its stroke-width; the shapes are
// united. Curves are cut into OpenSCAD's fixed numbers of segments (40 for a
// circle or an ellipse, 20 for a Bezier curve, 4 + 10 per 180 degrees for an
// arc), whatever $fn, $fa and $fs.
// Where OpenSCAD reads a value it cannot parse as 0 or skips a transform,
// capsim stops with the file's line: a number, length or transform that
// does not parse, a path that does not follow the path grammar, an arc or
// viewBox that gives coordinates that are not finite.

#include "scene/regions/clipper_utils.h"

#include <cstddef>
#include <stdexcept>
#include <string_view>

namespace capsim::scene_file {

struct SvgOptions {
  double dpi = 72;
  bool center = false;
};

// What() is "LINE: message" (the SVG file's line).
class SvgError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// At most this many points (a curve's and a stroke's included) are read
// from one file: the clipping after them takes memory and time in
// proportion.
inline constexpr std::size_t kMaxSvgPoints = 1000000;

Polygon2d read_svg(std::string_view text, const SvgOptions& options);

}  // namespace capsim::scene_file
