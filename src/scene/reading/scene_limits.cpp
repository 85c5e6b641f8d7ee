// The range of scene values capsim guarantees to trace correctly: the
// placement bounds the parser checks.

#include "capsim/scene/scene_limits.h"

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

}  // namespace

double largest_stretch(const glm::dmat3& a) {
  return std::sqrt(largest_eigenvalue(glm::transpose(a) * a));
}

Aabb placed_bounds(const Primitive& p) {
  const Aabb canonical = object_bounds(p);
  Aabb placed;
  for (int k = 0; k < 8; ++k) {
    const glm::dvec4 corner((k & 1) ? canonical.hi.x : canonical.lo.x,
                            (k & 2) ? canonical.hi.y : canonical.lo.y,
                            (k & 4) ? canonical.hi.z : canonical.lo.z, 1.0);
    placed.extend(glm::dvec3(p.to_world * corner));
  }
  return placed;
}

}  // namespace capsim
