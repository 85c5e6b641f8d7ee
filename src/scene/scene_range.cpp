// The range of scene values capsim guarantees to trace correctly.

#include "capsim/scene_range.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace capsim {

namespace {

// The largest eigenvalue of the symmetric positive semi-definite m, by the
// closed form for 3x3 symmetric matrices (O. K. Smith, 1961).
double largest_eigenvalue(const glm::dmat3& m) {
  const double off = m[0][1] * m[0][1] + m[0][2] * m[0][2] + m[1][2] * m[1][2];
  if (off == 0) return std::max({m[0][0], m[1][1], m[2][2]});
  const double q = (m[0][0] + m[1][1] + m[2][2]) / 3;
  const double p2 = (m[0][0] - q) * (m[0][0] - q) + (m[1][1] - q) * (m[1][1] - q) +
                    (m[2][2] - q) * (m[2][2] - q) + 2 * off;
  const double p = std::sqrt(p2 / 6);
  const glm::dmat3 b = (m - q * glm::dmat3(1.0)) / p;
  const double r = std::clamp(glm::determinant(b) / 2, -1.0, 1.0);
  return q + 2 * p * std::cos(std::acos(r) / 3);
}

// The largest |coordinate| of a box.
double reach(const Aabb& b) {
  const glm::dvec3 far = glm::max(glm::abs(b.lo), glm::abs(b.hi));
  return std::max({far.x, far.y, far.z});
}

}  // namespace

double largest_stretch(const glm::dmat3& a) {
  return std::sqrt(largest_eigenvalue(glm::transpose(a) * a));
}

Aabb placed_bounds(const Primitive& p) {
  const Aabb canonical = object_bounds(p.kind);
  Aabb placed;
  for (int k = 0; k < 8; ++k) {
    const glm::dvec4 corner((k & 1) ? canonical.hi.x : canonical.lo.x,
                            (k & 2) ? canonical.hi.y : canonical.lo.y,
                            (k & 4) ? canonical.hi.z : canonical.lo.z, 1.0);
    placed.extend(glm::dvec3(p.to_world * corner));
  }
  return placed;
}

void check_scene_range(const Scene& scene, const std::vector<PreparedPrimitive>& prims,
                       const std::vector<bool>& placed, const Aabb& universe) {
  const glm::dvec3 extent = universe.extent();
  const double size = std::max({extent.x, extent.y, extent.z});
  const double least = size / kMaxSceneRatio, farthest = size * kMaxSceneRatio;
  for (std::size_t i = 0; i < prims.size(); ++i) {
    if (!placed[i]) continue;
    const Primitive& p = scene.primitives[i];
    const char* kind = to_string(p.kind);
    // The prepared primitive holds the inverse placement already.
    const double stretch = 1 / largest_stretch(glm::dmat3(prims[i].to_object));
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
