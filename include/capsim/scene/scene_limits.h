#pragma once
// The range of scene values capsim guarantees to trace correctly
// (docs/scene-format.md, "Range"). Two kinds of bound:
//   - absolute, checked by the parser where each value enters: lengths and
//     coordinates between kMinLength and kMaxLength, so that no intermediate
//     of the intersection arithmetic (up to the sixth power of a length, once
//     a ray is carried into a primitive's own space) leaves the normal doubles;
//   - relative to the scene's size, checked by prepare_scene: every placed
//     primitive at least 1/kMaxSceneRatio of the scene's size, and every
//     coordinate (and the camera's eye) within kMaxSceneRatio times it of the
//     origin, so that the tracer's offsets (1e-7 of the scene's diagonal) are
//     thinner than any primitive and far wider than the rounding of any
//     coordinate (2.2e-16 of it).
// The scene-relative check runs as the scene is prepared
// (capsim/trace/scene_range.h).

#include "capsim/scene/scene.h"

#include <glm/glm.hpp>


namespace capsim {

inline constexpr double kMinLength = 1e-30;     // least radius, side or height
inline constexpr double kMaxLength = 1e30;      // largest length and |coordinate|
inline constexpr double kMaxSceneRatio = 1e6;   // see above
inline constexpr double kMinIor = 1e-3;         // material ior, both ways of 1
inline constexpr double kMaxIor = 1e3;
// Material ambient, diffuse and specular weights and light colour components:
// products of a few of them stay far inside the range of the float images.
inline constexpr double kMaxWeight = 1e6;

// The largest factor by which `a` stretches any direction: its largest
// singular value.
double largest_stretch(const glm::dmat3& a);

// The least factor by which `a` stretches any direction: its smallest
// singular value, found as the reciprocal of the largest of a's inverse (the
// largest eigenvalue of a symmetric matrix is computed accurately; the
// smallest is not). For a primitive's placement: a sphere's radius, a box's
// shortest side, a cylinder's height or larger radius, whichever is less.
// Precondition: a is invertible.
inline double smallest_stretch(const glm::dmat3& a) { return 1 / largest_stretch(glm::inverse(a)); }

// The bounding box of a primitive as placed: its canonical box's corners
// carried by to_world (PreparedPrimitive::world_bounds, without preparing).
Aabb placed_bounds(const Primitive& p);

}  // namespace capsim
