#pragma once
// What each supported module call means, read from its arguments with every
// value checked. These functions look at one call only (not its children, not
// its place in the tree); parser.cpp walks the tree and composes them.

#include <glm/glm.hpp>
#include <optional>

#include "capsim/scene/scene.h"
#include "scene/reading/scene_syntax.h"

namespace capsim::scene_file {

// sphere, cube or cylinder: kind, cone radii, loc and to_world as placed by the
// call's own arguments (the enclosing transforms are applied by the caller).
Primitive read_primitive(const Call& call);

// multmatrix, translate, rotate, scale or mirror: the call's matrix, refused when
// singular.
glm::dmat4 read_transform(const Call& call);

// color(): `rgb` empty when the call names no colour (OpenSCAD writes
// [-1, -1, -1, a] for that), in which case the enclosing colour stays.
struct ColorSetting {
  std::optional<glm::dvec3> linear_rgb;
  double alpha = 1;
};
ColorSetting read_color(const Call& call);

// material(): the enclosing material with the fields the call names replaced.
Material read_material(const Call& call, const Material& enclosing);

// render(...) and the operators: only checks their arguments.
void read_pass_through(const Call& call);

// hull() and minkowski(), of solids or of 2-D shapes: only checks their
// arguments (they take only OpenSCAD's preview hint, convexity, by name).
void read_hull_arguments(const Call& call);

Camera read_camera(const Call& call);
Light read_light(const Call& call);
glm::dvec3 read_background(const Call& call);  // linear RGB

// |det| of the linear part, relative to the cube of its largest column, below
// this is a singular (flattened) placement.
constexpr double kSingularRelativeDet = 1e-12;
bool is_singular(const glm::dmat4& m);

}  // namespace capsim::scene_file
