#pragma once
// Axis-aligned bounds of scene geometry.

#include <glm/glm.hpp>

#include <limits>

namespace capsim {

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

// An axis-aligned box; empty when lo > hi on any axis.
struct Aabb {
  glm::dvec3 lo{kInfinity};
  glm::dvec3 hi{-kInfinity};

  bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
  void extend(const glm::dvec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  void extend(const Aabb& b) {
    lo = glm::min(lo, b.lo);
    hi = glm::max(hi, b.hi);
  }
  glm::dvec3 extent() const { return hi - lo; }
  glm::dvec3 center() const { return 0.5 * (lo + hi); }
};

}  // namespace capsim
