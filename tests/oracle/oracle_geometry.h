#pragma once
// The oracle's own exact ray-primitive intersection, written apart from the
// tracer's (src/trace/primitive_geometry.cpp) so that the two can disagree. Each
// canonical primitive is a convex solid, so a line meets it in one interval; the
// interval is built as the intersection of the solid's defining constraints
// (slabs, a quadric, a nappe half-space), all in double precision.
//
// Besides the interval, every end reports the t-gap to the runner-up constraint:
// a small gap means the crossing lies near an edge (box edge, cone rim), where
// the surface and hence the normal are ambiguous although t is not.

#include "capsim/scene/scene.h"
#include "capsim/trace/ray.h"

#include <glm/glm.hpp>

#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace oracle {

using capsim::kInfinity;

// Surfaces, numbered only for the oracle: sphere 0; box faces 0..5 (-x,+x,-y,+y,
// -z,+z); cone 0 side, 1 cap z=0, 2 cap z=1, 3 the apex plane of the nappe.
struct Span {
  double t_enter = kInfinity;
  double t_exit = -kInfinity;
  int enter_surface = -1;
  int exit_surface = -1;
  double enter_margin = kInfinity;  // t-gap to the next-tightest lower bound
  double exit_margin = kInfinity;   // t-gap to the next-tightest upper bound
  bool empty() const { return !(t_enter < t_exit); }
};

// The running intersection of half-line constraints on t, remembering which
// constraint is tightest on each side and how far the runner-up is.
class Bounds {
 public:
  void at_least(double t, int surface) {
    if (t > lo_) {
      lo2_ = lo_;
      lo_ = t;
      lo_s_ = surface;
    } else if (t > lo2_) {
      lo2_ = t;
    }
  }
  void at_most(double t, int surface) {
    if (t < hi_) {
      hi2_ = hi_;
      hi_ = t;
      hi_s_ = surface;
    } else if (t < hi2_) {
      hi2_ = t;
    }
  }
  void make_empty() { lo_ = kInfinity; hi_ = -kInfinity; }
  bool empty() const { return !(lo_ < hi_); }
  double length() const { return hi_ - lo_; }
  Span span() const {
    return {lo_, hi_, lo_s_, hi_s_, lo_ - lo2_, hi2_ - hi_};
  }

 private:
  double lo_ = -kInfinity, hi_ = kInfinity;
  double lo2_ = -kInfinity, hi2_ = kInfinity;
  int lo_s_ = -1, hi_s_ = -1;
};

// a <= o + t d <= b on one axis; a zero direction keeps the whole line or none of
// it, with no division (the case axis-parallel rays exercise).
inline void clip_slab(Bounds& b, double o, double d, double lo, double hi, int lo_surface,
                      int hi_surface) {
  if (d == 0.0) {
    if (!(lo < o && o < hi)) b.make_empty();
    return;
  }
  const double t_lo = (lo - o) / d;
  const double t_hi = (hi - o) / d;
  if (d > 0) {
    b.at_least(t_lo, lo_surface);
    b.at_most(t_hi, hi_surface);
  } else {
    b.at_least(t_hi, hi_surface);
    b.at_most(t_lo, lo_surface);
  }
}

// Unit sphere. Solved about the point of closest approach so that distant
// origins lose no precision to cancellation.
inline Span sphere_span(const glm::dvec3& o, const glm::dvec3& d) {
  const double a = glm::dot(d, d);
  const double tc = -glm::dot(o, d) / a;
  const glm::dvec3 p = o + tc * d;
  const double h2 = 1.0 - glm::dot(p, p);
  if (!(h2 > 0)) return {};
  const double s = std::sqrt(h2 / a);
  return {tc - s, tc + s, 0, 0, kInfinity, kInfinity};
}

// Unit cube [0,1]^3: three slabs.
inline Span box_span(const glm::dvec3& o, const glm::dvec3& d) {
  Bounds b;
  for (int axis = 0; axis < 3; ++axis) clip_slab(b, o[axis], d[axis], 0.0, 1.0, 2 * axis, 2 * axis + 1);
  return b.empty() ? Span{} : b.span();
}

// Frustum 0 <= z <= 1, sqrt(x^2 + y^2) <= r(z) = r1 + (r2 - r1) z. Written as
// slab AND r(z) >= 0 AND Q <= 0 with Q = x^2 + y^2 - r(z)^2: the last two together
// are exactly the one nappe, which is convex, so the result is one interval. Q <= 0
// alone along a line is up to two pieces (the two nappes); each is intersected with
// the other constraints and the non-empty one kept.
inline Span cone_span(const glm::dvec3& o, const glm::dvec3& d, double r1, double r2) {
  Bounds base;
  clip_slab(base, o.z, d.z, 0.0, 1.0, 1, 2);
  const double k = r2 - r1;
  const double r0 = r1 + k * o.z;  // r along the line: r0 + rk t
  const double rk = k * d.z;
  if (rk == 0.0) {
    if (r0 < 0) base.make_empty();
  } else if (rk > 0) {
    base.at_least(-r0 / rk, 3);
  } else {
    base.at_most(-r0 / rk, 3);
  }
  if (base.empty()) return {};

  const double A = d.x * d.x + d.y * d.y - rk * rk;
  const double Bh = o.x * d.x + o.y * d.y - r0 * rk;  // half the linear coefficient
  const double C = o.x * o.x + o.y * o.y - r0 * r0;

  // The pieces of Q <= 0 as [lo, hi] (infinite ends allowed).
  std::array<std::array<double, 2>, 2> pieces{};
  int n = 0;
  if (A == 0.0) {
    if (Bh == 0.0) {
      if (C <= 0) pieces[n++] = {-kInfinity, kInfinity};
    } else if (Bh > 0) {
      pieces[n++] = {-kInfinity, -C / (2 * Bh)};
    } else {
      pieces[n++] = {-C / (2 * Bh), kInfinity};
    }
  } else {
    const double disc = Bh * Bh - A * C;
    if (disc > 0) {
      // The cancellation-free pair of roots.
      const double q = -(Bh + std::copysign(std::sqrt(disc), Bh));
      double ta = q / A, tb = C / q;
      if (ta > tb) std::swap(ta, tb);
      if (A > 0) {
        pieces[n++] = {ta, tb};
      } else {
        pieces[n++] = {-kInfinity, ta};
        pieces[n++] = {tb, kInfinity};
      }
    } else if (A < 0) {
      pieces[n++] = {-kInfinity, kInfinity};  // Q <= 0 everywhere on the line
    }
  }

  Span best{};
  double best_len = -1;
  for (int i = 0; i < n; ++i) {
    Bounds b = base;
    if (pieces[i][0] > -kInfinity) b.at_least(pieces[i][0], 0);
    if (pieces[i][1] < kInfinity) b.at_most(pieces[i][1], 0);
    if (!b.empty() && b.length() > best_len) {
      best_len = b.length();
      best = b.span();
    }
  }
  return best;
}

// A scene primitive as the oracle sees it: the inverse and normal matrices are
// computed here with glm in double, independently of the tracer's preparation.
struct OraclePrimitive {
  capsim::PrimitiveKind kind = capsim::PrimitiveKind::Sphere;
  double r1 = 1, r2 = 1;
  glm::dmat4 to_world{1.0};
  glm::dmat4 to_object{1.0};
  glm::dmat3 normal_to_world{1.0};
  capsim::Aabb world_bounds;
};

// The oracle's scenes hold the paper's convex primitives only; meshes are
// judged against OpenSCAD's own meshes (mesh_oracle_test.cpp).
[[noreturn]] inline void refuse_mesh() {
  throw std::logic_error("the oracle traces only spheres, boxes and cones; mesh_oracle_test.cpp judges meshes");
}

inline capsim::Aabb canonical_bounds(capsim::PrimitiveKind kind) {
  switch (kind) {
    case capsim::PrimitiveKind::Sphere: return {glm::dvec3(-1), glm::dvec3(1)};
    case capsim::PrimitiveKind::Box: return {glm::dvec3(0), glm::dvec3(1)};
    case capsim::PrimitiveKind::Cone: return {glm::dvec3(-1, -1, 0), glm::dvec3(1)};
    case capsim::PrimitiveKind::Mesh:
    case capsim::PrimitiveKind::Revolution: refuse_mesh();
  }
  return {};
}

inline OraclePrimitive make_oracle_primitive(const capsim::Primitive& p) {
  OraclePrimitive o;
  o.kind = p.kind;
  o.r1 = p.cone_r1;
  o.r2 = p.cone_r2;
  o.to_world = p.to_world;
  o.to_object = glm::inverse(p.to_world);
  o.normal_to_world = glm::transpose(glm::inverse(glm::dmat3(p.to_world)));
  const capsim::Aabb c = canonical_bounds(p.kind);
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 corner((i & 1) ? c.hi.x : c.lo.x, (i & 2) ? c.hi.y : c.lo.y,
                            (i & 4) ? c.hi.z : c.lo.z);
    o.world_bounds.extend(glm::dvec3(p.to_world * glm::dvec4(corner, 1.0)));
  }
  return o;
}

// The whole line origin + t dir against the primitive (world t: the object-space
// direction is not renormalised).
inline Span line_span(const OraclePrimitive& p, const capsim::Ray& ray) {
  const glm::dvec3 o(p.to_object * glm::dvec4(ray.origin, 1.0));
  const glm::dvec3 d(p.to_object * glm::dvec4(ray.dir, 0.0));
  switch (p.kind) {
    case capsim::PrimitiveKind::Sphere: return sphere_span(o, d);
    case capsim::PrimitiveKind::Box: return box_span(o, d);
    case capsim::PrimitiveKind::Cone: return cone_span(o, d, p.r1, p.r2);
    case capsim::PrimitiveKind::Mesh:
    case capsim::PrimitiveKind::Revolution: refuse_mesh();
  }
  return {};
}

// Outward unit normal in world space at the crossing t on surface s.
inline glm::dvec3 world_normal(const OraclePrimitive& p, const capsim::Ray& ray, double t, int s) {
  const glm::dvec3 q(p.to_object * glm::dvec4(ray.at(t), 1.0));
  glm::dvec3 n(0);
  switch (p.kind) {
    case capsim::PrimitiveKind::Sphere: n = q; break;
    case capsim::PrimitiveKind::Box: n[s / 2] = (s % 2) ? 1.0 : -1.0; break;
    case capsim::PrimitiveKind::Cone: {
      const double k = p.r2 - p.r1;
      if (s == 1) n = {0, 0, -1};
      else if (s == 2) n = {0, 0, 1};
      else n = {q.x, q.y, -(p.r1 + k * q.z) * k};  // gradient of x^2 + y^2 - r(z)^2
      break;
    }
    case capsim::PrimitiveKind::Mesh:
    case capsim::PrimitiveKind::Revolution: refuse_mesh();
  }
  return glm::normalize(p.normal_to_world * n);
}

// The cone's radius r(z) at the crossing t (object space; 0 at a pointed
// cone's apex), for telling crossings near the apex, where the surface is
// singular, from the rest.
inline double cone_radius_at(const OraclePrimitive& p, const capsim::Ray& ray, double t) {
  const glm::dvec3 q(p.to_object * glm::dvec4(ray.at(t), 1.0));
  return p.r1 + (p.r2 - p.r1) * q.z;
}

}  // namespace oracle
