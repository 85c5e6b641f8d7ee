#pragma once
// Colour names and codes as OpenSCAD's color() accepts them, and the sRGB
// decoding that turns file colours into the linear values the tracer shades with.

#include "capsim/image/srgb.h"

#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace capsim::scene_file {

// sRGB components in [0, 1] with alpha, for one of the CSS/SVG colour names
// (case-insensitive; OpenSCAD's extra "transparent" included) or a hex code
// "#rgb", "#rgba", "#rrggbb", "#rrggbbaa". Empty when `text` is neither.
std::optional<glm::dvec4> lookup_color(std::string_view text);

// Every accepted colour name, lower case, for suggestions in error messages.
const std::vector<std::string>& color_names();

// The sRGB transfer function inverted: an sRGB component in [0, 1] -> linear.
glm::dvec3 srgb_to_linear(const glm::dvec3& c);

}  // namespace capsim::scene_file
