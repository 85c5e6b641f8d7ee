#pragma once
// 2-D import() of an SVG file, read as OpenSCAD 2021.01's libsvg reads it:
// the shapes rect, circle, ellipse, polygon, polyline and path, in user units
// converted to millimetres at the import's dpi (OpenSCAD's default 72), y
// pointing up, each shape a closed outline under the even-odd rule.

#include "scene/clipper_utils.h"

#include <stdexcept>
#include <string_view>

namespace capsim::scene_file {

struct SvgOptions {
  double dpi = 72;
  bool center = false;
  double fn = 0, fa = 12, fs = 2;
};

// What() is "LINE: message" (the SVG file's line).
class SvgError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

Polygon2d read_svg(std::string_view text, const SvgOptions& options);

}  // namespace capsim::scene_file
