#pragma once
// A ray of the tracer.

#include "capsim/scene/bounds.h"

#include <glm/glm.hpp>

namespace capsim {

// x(t) = origin + t * dir for t in [tmin, tmax]. dir need not be unit length:
// rays carried into object space keep the world t.
struct Ray {
  glm::dvec3 origin{0};
  glm::dvec3 dir{0, 0, 1};
  double tmin = 0;
  double tmax = kInfinity;

  glm::dvec3 at(double t) const { return origin + t * dir; }
};

}  // namespace capsim
