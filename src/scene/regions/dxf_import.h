#pragma once
// 2-D import() of a DXF file, read as OpenSCAD 2021.01 reads it (its
// dxfdata.cc): the LINE, LWPOLYLINE, CIRCLE, ARC, ELLIPSE and INSERT (of a
// block's lines) entities of the ENTITIES section, of one layer or of all;
// circles, arcs and ellipses cut by the $fn/$fa/$fs fragments rule; end
// points snapped to a grid of 2^-10 units and joined into contours.
// Where OpenSCAD warns and reads on, capsim stops with the file's line: an
// entity OpenSCAD skips (it would leave a hole in an outline), a value that
// is not a number, a contour that does not close (OpenSCAD closes it with a
// straight edge the drawing does not have), a layer with nothing in it.

#include "scene/regions/clipper_utils.h"

#include <stdexcept>
#include <string>
#include <string_view>

namespace capsim::scene_file {

// import()'s arguments for a DXF file.
struct DxfOptions {
  std::string layer;  // empty: every layer
  glm::dvec2 origin{0.0};
  double scale = 1;
  double fn = 0, fa = 12, fs = 2;
};

// What() is "LINE: message" (the DXF file's line), or the message alone for
// the file as a whole.
class DxfError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// At most this many line segments are read from one file: the joining of
// contours and the clipping after it take memory and time in proportion.
inline constexpr std::size_t kMaxDxfSegments = 1000000;

// The contours of the DXF text, as drawn (not sanitized: OpenSCAD reads them
// under the even-odd rule).
Polygon2d read_dxf(std::string_view text, const DxfOptions& options);

}  // namespace capsim::scene_file
