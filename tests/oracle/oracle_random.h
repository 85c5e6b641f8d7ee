#pragma once
// Random CSG scenes and rays for the oracle test. Everything is drawn from a
// seeded std::mt19937_64 through the helpers below (not the standard
// distributions, whose output may differ between library versions), so every run
// tests the same trees and rays.

#include "oracle/oracle_geometry.h"

#include "capsim/scene/scene.h"
#include "capsim/trace/ray.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

namespace oracle {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : gen_(seed) {}
  double uniform() { return static_cast<double>(gen_() >> 11) * 0x1.0p-53; }  // [0, 1)
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  int below(int n) { return static_cast<int>(gen_() % static_cast<std::uint64_t>(n)); }
  bool chance(double p) { return uniform() < p; }
  glm::dvec3 unit_vector() {
    const double z = uniform(-1, 1), phi = uniform(0, 2 * std::numbers::pi);
    const double s = std::sqrt(1 - z * z);
    return {s * std::cos(phi), s * std::sin(phi), z};
  }
  glm::dvec3 in_box(const capsim::Aabb& b) {
    return {uniform(b.lo.x, b.hi.x), uniform(b.lo.y, b.hi.y), uniform(b.lo.z, b.hi.z)};
  }

 private:
  std::mt19937_64 gen_;
};

// Uniform random rotation (Shoemake's unit quaternion).
inline glm::dmat4 random_rotation(Rng& rng) {
  const double u1 = rng.uniform(), u2 = rng.uniform(), u3 = rng.uniform();
  const double a = std::sqrt(1 - u1), b = std::sqrt(u1), tau = 2 * std::numbers::pi;
  const glm::dquat q(b * std::cos(tau * u3), a * std::sin(tau * u2), a * std::cos(tau * u2),
                     b * std::sin(tau * u3));
  return glm::mat4_cast(q);
}

inline glm::dmat4 translation(const glm::dvec3& v) {
  glm::dmat4 m(1.0);
  m[3] = glm::dvec4(v, 1.0);
  return m;
}

inline glm::dmat4 scaling(const glm::dvec3& s) {
  glm::dmat4 m(1.0);
  m[0][0] = s.x;
  m[1][1] = s.y;
  m[2][2] = s.z;
  return m;
}

// A primitive somewhere in [-1.2, 1.2]^3 (so that primitives overlap and
// intersections and differences are rarely empty), centred on its placement
// point. Axis-aligned ones have no rotation and no shear, so that axis-parallel
// rays keep exactly zero direction components in object space; the others get a
// random rotation and usually a shear. Scales are non-uniform; some are mirrors.
inline capsim::Primitive random_primitive(Rng& rng, bool axis_aligned) {
  capsim::Primitive p;
  p.kind = static_cast<capsim::PrimitiveKind>(rng.below(3));
  glm::dvec3 centering(0);
  if (p.kind == capsim::PrimitiveKind::Box) centering = glm::dvec3(-0.5);
  if (p.kind == capsim::PrimitiveKind::Cone) {
    centering = {0, 0, -0.5};
    // One radius is 1; the other is 0 (pointed), 1 (cylinder) or in between.
    const int shape = rng.below(4);
    const double other = shape == 0 ? 0.0 : shape == 1 ? 1.0 : rng.uniform(0.05, 1.0);
    if (rng.chance(0.5)) {
      p.cone_r1 = 1, p.cone_r2 = other;
    } else {
      p.cone_r1 = other, p.cone_r2 = 1;
    }
  }
  glm::dvec3 scale(rng.uniform(0.3, 1.4), rng.uniform(0.3, 1.4), rng.uniform(0.3, 1.4));
  if (rng.chance(0.15)) scale[rng.below(3)] *= -1;  // a mirror: negative determinant
  glm::dmat4 linear = scaling(scale);
  if (!axis_aligned) {
    glm::dmat4 shear(1.0);
    if (rng.chance(0.7)) {
      const int count = 1 + rng.below(3);
      for (int i = 0; i < count; ++i) {
        const int row = rng.below(3), col = (row + 1 + rng.below(2)) % 3;
        shear[col][row] = rng.uniform(-0.6, 0.6);
      }
    }
    linear = random_rotation(rng) * shear * linear;
  }
  const glm::dvec3 center(rng.uniform(-1.2, 1.2), rng.uniform(-1.2, 1.2), rng.uniform(-1.2, 1.2));
  p.to_world = translation(center) * linear * translation(centering);
  return p;
}

struct TreeShape {
  int depth = 0;  // operator levels on the longest root-to-leaf path
  int ops[3] = {0, 0, 0};
  int kinds[3] = {0, 0, 0};
  int empty_groups = 0;
};

inline constexpr int kMaxPrimitivesPerTree = 40;

// A random subtree. Operator nodes mostly have 2-4 children; a few have one
// (a pass-through) or none (OpenSCAD's empty group, the empty set).
inline capsim::CsgNode random_node(Rng& rng, int depth, int max_depth, double axis_aligned_share,
                                   capsim::LargeVector<capsim::Primitive>& prims, TreeShape& shape) {
  const bool leaf = depth == max_depth || static_cast<int>(prims.size()) >= kMaxPrimitivesPerTree ||
                    (depth > 0 && rng.chance(0.12 + 0.1 * depth));
  capsim::CsgNode node;
  if (leaf) {
    node.is_leaf = true;
    node.primitive = static_cast<int>(prims.size());
    prims.push_back(random_primitive(rng, rng.chance(axis_aligned_share)));
    ++shape.kinds[static_cast<int>(prims.back().kind)];
    return node;
  }
  node.op = static_cast<capsim::CsgOp>(rng.below(3));
  ++shape.ops[static_cast<int>(node.op)];
  shape.depth = std::max(shape.depth, depth + 1);
  const double r = rng.uniform();
  const int children = r < 0.03 ? 0 : r < 0.07 ? 1 : r < 0.67 ? 2 : r < 0.9 ? 3 : 4;
  if (children == 0) ++shape.empty_groups;
  for (int i = 0; i < children; ++i)
    node.children.push_back(random_node(rng, depth + 1, max_depth, axis_aligned_share, prims, shape));
  return node;
}

struct RandomScene {
  capsim::Scene scene;
  TreeShape shape;
};

// Usually a union of top-level objects, as the parser builds it; sometimes the
// tree itself is the root.
inline RandomScene random_scene(Rng& rng, int max_depth) {
  RandomScene rs;
  const double axis_aligned_share = rng.chance(0.25) ? 1.0 : 0.25;
  capsim::CsgNode sub = random_node(rng, 0, max_depth, axis_aligned_share, rs.scene.primitives, rs.shape);
  if (rng.chance(0.2)) {
    rs.scene.root = std::move(sub);
  } else {
    rs.scene.root.op = capsim::CsgOp::Union;
    rs.scene.root.children.push_back(std::move(sub));
    const int extra = rng.below(3);
    for (int i = 0; i < extra; ++i)
      rs.scene.root.children.push_back(
          random_node(rng, 1, max_depth, axis_aligned_share, rs.scene.primitives, rs.shape));
  }
  return rs;
}

// A point strictly inside a canonical primitive, carried to world space.
inline glm::dvec3 point_inside(Rng& rng, const capsim::Primitive& p) {
  glm::dvec3 q(0);
  switch (p.kind) {
    case capsim::PrimitiveKind::Sphere:
      do q = rng.in_box({glm::dvec3(-1), glm::dvec3(1)});
      while (glm::dot(q, q) >= 1);
      break;
    case capsim::PrimitiveKind::Box: q = rng.in_box({glm::dvec3(0), glm::dvec3(1)}); break;
    case capsim::PrimitiveKind::Cone: {
      double r;
      do {
        q = rng.in_box({glm::dvec3(-1, -1, 0), glm::dvec3(1)});
        r = p.cone_r1 + (p.cone_r2 - p.cone_r1) * q.z;
      } while (q.x * q.x + q.y * q.y >= r * r);
      break;
    }
    case capsim::PrimitiveKind::Mesh:
    case capsim::PrimitiveKind::Revolution: refuse_mesh();
  }
  return glm::dvec3(p.to_world * glm::dvec4(q, 1.0));
}

inline const capsim::Primitive& pick(Rng& rng, const capsim::Scene& scene) {
  return scene.primitives[rng.below(static_cast<int>(scene.primitives.size()))];
}

// A point on the surface of a canonical primitive with the outward normal there
// (object space), each surface drawn with a fixed share.
struct SurfacePoint {
  glm::dvec3 p;
  glm::dvec3 n;
};

inline SurfacePoint point_on_surface(Rng& rng, const capsim::Primitive& prim) {
  switch (prim.kind) {
    case capsim::PrimitiveKind::Sphere: {
      const glm::dvec3 u = rng.unit_vector();
      return {u, u};
    }
    case capsim::PrimitiveKind::Box: {
      const int face = rng.below(6), axis = face / 2;
      glm::dvec3 p = rng.in_box({glm::dvec3(0), glm::dvec3(1)}), n(0);
      p[axis] = face % 2;
      n[axis] = face % 2 ? 1.0 : -1.0;
      return {p, n};
    }
    case capsim::PrimitiveKind::Cone: {
      const double r1 = prim.cone_r1, r2 = prim.cone_r2, k = r2 - r1;
      const double phi = rng.uniform(0, 2 * std::numbers::pi);
      const glm::dvec3 radial(std::cos(phi), std::sin(phi), 0);
      const int surface = rng.below(3);  // side, cap z=0, cap z=1
      if (surface == 0 || (surface == 1 && r1 == 0) || (surface == 2 && r2 == 0)) {
        const double z = rng.uniform(0, 1), r = r1 + k * z;
        return {r * radial + glm::dvec3(0, 0, z), glm::normalize(radial + glm::dvec3(0, 0, -k))};
      }
      const double z = surface == 1 ? 0.0 : 1.0;
      const double r = (surface == 1 ? r1 : r2) * std::sqrt(rng.uniform());
      return {r * radial + glm::dvec3(0, 0, z), glm::dvec3(0, 0, surface == 1 ? -1.0 : 1.0)};
    }
    case capsim::PrimitiveKind::Mesh:
    case capsim::PrimitiveKind::Revolution: refuse_mesh();
  }
  return {};
}

// A point on an edge of a canonical primitive (object space): a box edge, a cone
// rim or a pointed cone's apex; on a sphere, which has none, any surface point.
inline glm::dvec3 point_on_edge(Rng& rng, const capsim::Primitive& prim) {
  switch (prim.kind) {
    case capsim::PrimitiveKind::Sphere: return rng.unit_vector();
    case capsim::PrimitiveKind::Box: {
      const int axis = rng.below(3);
      glm::dvec3 p(rng.below(2), rng.below(2), rng.below(2));
      p[axis] = rng.uniform();
      return p;
    }
    case capsim::PrimitiveKind::Cone: {
      const bool top = rng.chance(0.5);
      const double r = top ? prim.cone_r2 : prim.cone_r1;  // 0: the apex
      const double phi = rng.uniform(0, 2 * std::numbers::pi);
      return {r * std::cos(phi), r * std::sin(phi), top ? 1.0 : 0.0};
    }
    case capsim::PrimitiveKind::Mesh:
    case capsim::PrimitiveKind::Revolution: refuse_mesh();
  }
  return {};
}

enum class RayKind { Outside, AxisParallel, Planar, Inside, Silhouette, Edge };
inline constexpr int kRayKinds = 6;

// Rays of every kind the tracer must handle: from outside the universe toward a
// point in it (usually inside a primitive); along a coordinate axis (two direction components exactly zero);
// parallel to a coordinate plane (one zero); and from a point inside a primitive
// in any direction. Directions have random lengths (t is not distance). A tenth
// start later (tmin > 0) and a tenth stop early (finite tmax).
inline capsim::Ray random_ray(Rng& rng, const capsim::Scene& scene, const capsim::Aabb& universe,
                              RayKind kind) {
  const glm::dvec3 c = universe.center();
  const double radius = 0.5 * glm::length(universe.extent());
  capsim::Aabb target_box = universe;
  target_box.lo -= 0.05 * universe.extent();
  target_box.hi += 0.05 * universe.extent();
  capsim::Ray ray;
  const double length = std::exp2(rng.uniform(-2, 2));
  switch (kind) {
    case RayKind::Outside: {
      // Mostly aimed through a primitive, so that most rays have something to
      // classify; a tenth start far away, where the grid set-up loses precision.
      const double distance = rng.chance(0.1) ? 50 * radius : 1.5 * radius + 1;
      ray.origin = c + distance * rng.unit_vector();
      const glm::dvec3 target = rng.chance(0.7) ? point_inside(rng, pick(rng, scene))
                                                : rng.in_box(target_box);
      ray.dir = glm::normalize(target - ray.origin) * length;
      break;
    }
    case RayKind::AxisParallel: {
      const int axis = rng.below(3);
      const double sign = rng.chance(0.5) ? 1.0 : -1.0;
      ray.origin = rng.in_box(target_box);
      ray.origin[axis] = sign > 0 ? universe.lo[axis] - rng.uniform(0.5, 2)
                                  : universe.hi[axis] + rng.uniform(0.5, 2);
      ray.dir = glm::dvec3(0);
      ray.dir[axis] = sign * length;
      break;
    }
    case RayKind::Planar: {
      const int axis = rng.below(3);
      glm::dvec3 d = rng.unit_vector();
      d[axis] = 0;
      d = glm::normalize(d);
      ray.origin = rng.in_box(target_box) - (radius + 1) * d;
      ray.dir = d * length;
      break;
    }
    case RayKind::Inside: {
      ray.origin = point_inside(rng, pick(rng, scene));
      glm::dvec3 d = rng.unit_vector();
      if (rng.chance(0.2)) {
        d = glm::dvec3(0);
        d[rng.below(3)] = rng.chance(0.5) ? 1.0 : -1.0;
      }
      ray.dir = d * length;
      break;
    }
    case RayKind::Silhouette: {
      // Tangent to a primitive's surface at a random point, moved off it along the
      // normal by 1e-15 .. 1e-3 of the universe's size, either way: rays that
      // skim spheres and cones and run along box faces, where the exact answer
      // hangs on rounding and the grazing tolerance is exercised.
      const capsim::Primitive& prim = pick(rng, scene);
      const SurfacePoint sp = point_on_surface(rng, prim);
      const glm::dvec3 tangent = glm::cross(sp.n, rng.unit_vector());
      const glm::dvec3 p(prim.to_world * glm::dvec4(sp.p, 1.0));
      const glm::dvec3 t = glm::normalize(glm::dvec3(prim.to_world * glm::dvec4(tangent, 0.0)));
      const glm::dvec3 n = glm::normalize(glm::transpose(glm::inverse(glm::dmat3(prim.to_world))) * sp.n);
      const double offset = (rng.chance(0.5) ? 1 : -1) * std::pow(10.0, rng.uniform(-15, -3)) * 2 * radius;
      ray.origin = p + offset * n - (2 * radius + 1) * t;
      ray.dir = t * length;
      break;
    }
    case RayKind::Edge: {
      // Through a point 1e-15 .. 1e-3 of the universe's size from an edge, a
      // rim or an apex, in any direction: the surface hit, and so the normal, is
      // ambiguous there although the distance is not.
      const capsim::Primitive& prim = pick(rng, scene);
      const glm::dvec3 p(prim.to_world * glm::dvec4(point_on_edge(rng, prim), 1.0));
      const double offset = std::pow(10.0, rng.uniform(-15, -3)) * 2 * radius;
      const glm::dvec3 d = rng.unit_vector();
      ray.origin = p + offset * rng.unit_vector() - (2 * radius + 1) * d;
      ray.dir = d * length;
      break;
    }
  }
  // t of the universe centre's projection: a natural unit for tmin and tmax.
  const double t_mid = std::max(0.0, glm::dot(c - ray.origin, ray.dir) / glm::dot(ray.dir, ray.dir));
  const double extra = radius / glm::length(ray.dir);
  const double r = rng.uniform();
  if (r < 0.1) ray.tmin = rng.uniform(0, t_mid + extra);
  else if (r < 0.2) ray.tmax = rng.uniform(0, t_mid + extra);
  return ray;
}

}  // namespace oracle
