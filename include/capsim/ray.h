#pragma once
#include <glm/glm.hpp>

#include <limits>

namespace capsim {

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

// x(t) = origin + t * dir for t in [tmin, tmax]. dir need not be unit length:
// rays carried into object space keep the world t.
struct Ray {
  glm::dvec3 origin{0};
  glm::dvec3 dir{0, 0, 1};
  double tmin = 0;
  double tmax = kInfinity;

  glm::dvec3 at(double t) const { return origin + t * dir; }
};

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
