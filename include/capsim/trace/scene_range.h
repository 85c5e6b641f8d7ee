#pragma once
// The scene-relative part of the range capsim traces (capsim/scene/scene_limits.h
// gives the whole range and its reasons), checked as a scene is prepared.

#include "capsim/scene/scene_limits.h"
#include "capsim/trace/primitive_geometry.h"

#include <span>
#include <vector>

namespace capsim {

// The scene-relative bounds on a scene being prepared (placed primitives and
// their universe): throws SceneError at the first placed primitive, in file
// order, that is too small or too far for the scene's size, then at the
// camera if its eye is too far.
void check_scene_range(const Scene& scene, std::span<const PreparedPrimitive> prims,
                       const std::vector<bool>& placed, const Aabb& universe);

}  // namespace capsim
