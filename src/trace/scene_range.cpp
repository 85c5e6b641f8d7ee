// The scene-relative range of scene values, checked as a scene is prepared.

#include "capsim/trace/scene_range.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace capsim {

namespace {

// The largest |coordinate| of a box.
double reach(const Aabb& b) {
  const glm::dvec3 far = glm::max(glm::abs(b.lo), glm::abs(b.hi));
  return std::max({far.x, far.y, far.z});
}

}  // namespace

void check_scene_range(const Scene& scene, std::span<const PreparedPrimitive> prims,
                       const std::vector<bool>& placed, const Aabb& universe) {
  const glm::dvec3 extent = universe.extent();
  const double size = std::max({extent.x, extent.y, extent.z});
  const double least = size / kMaxSceneRatio, farthest = size * kMaxSceneRatio;
  for (std::size_t i = 0; i < prims.size(); ++i) {
    if (!placed[i]) continue;
    const Primitive& p = scene.primitives[i];
    const char* kind = to_string(p.kind);
    // The prepared primitive holds the inverse placement already.
    double stretch = 1 / largest_stretch(glm::dmat3(prims[i].to_object));
    if (p.kind == PrimitiveKind::Mesh || p.kind == PrimitiveKind::Revolution) {
      // A mesh's (a revolution's) size is in its own coordinates, not in its placement.
      const glm::dvec3 e = object_bounds(p).extent();
      stretch *= std::min({e.x, e.y, e.z});
    }
    static_assert(kMaxSceneRatio == 1e6, "the messages below name the ratio");
    if (!(stretch >= least)) {
      throw SceneError(p.loc, fmt::format("this {} is too small for the scene: its smallest "
                                          "dimension {:g} is less than 1e-6 times the scene's "
                                          "size {:g}, the finest detail capsim traces",
                                          kind, stretch, size));
    }
    const double r = reach(prims[i].world_bounds);
    if (!(r <= farthest)) {
      throw SceneError(p.loc, fmt::format("this {} reaches {:g} from the origin, more than 1e6 "
                                          "times the scene's size {:g}, the farthest capsim "
                                          "traces; move the scene nearer the origin",
                                          kind, r, size));
    }
  }
  if (scene.camera) {
    const glm::dvec3 eye = scene.camera->eye;
    const double r = std::max({std::abs(eye.x), std::abs(eye.y), std::abs(eye.z)});
    if (!(r <= farthest)) {
      throw SceneError(scene.camera->loc,
                       fmt::format("the camera eye is {:g} from the origin, more than 1e6 times "
                                   "the scene's size {:g}, the farthest capsim traces from; "
                                   "move the eye nearer",
                                   r, size));
    }
  }
}

}  // namespace capsim
