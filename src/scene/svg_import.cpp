// SVG shapes as outlines (OpenSCAD's import_svg.cc over libsvg).

#include "scene/svg_import.h"

namespace capsim::scene_file {

Polygon2d read_svg(std::string_view, const SvgOptions&) {
  throw SvgError("1: SVG import is not read yet");
}

}  // namespace capsim::scene_file
