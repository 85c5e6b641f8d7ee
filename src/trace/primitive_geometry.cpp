#include "capsim/trace/primitive_geometry.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace capsim {

namespace {

// The unit-cube corners (0/1 per axis) scaled into a canonical object box.
std::array<glm::dvec3, 8> box_corners(const Aabb& b) {
  std::array<glm::dvec3, 8> c;
  for (int k = 0; k < 8; ++k)
    c[k] = {(k & 1) ? b.hi.x : b.lo.x, (k & 2) ? b.hi.y : b.lo.y, (k & 4) ? b.hi.z : b.lo.z};
  return c;
}

// Affine transforms: the last row of every matrix is (0, 0, 0, 1) (the parser
// refuses others), so only the 3x4 part is multiplied.
glm::dvec3 transform_point(const glm::dmat4& m, const glm::dvec3& p) {
  return glm::dvec3(m[0]) * p.x + glm::dvec3(m[1]) * p.y + glm::dvec3(m[2]) * p.z + glm::dvec3(m[3]);
}
glm::dvec3 transform_vector(const glm::dmat4& m, const glm::dvec3& v) {
  return glm::dvec3(m[0]) * v.x + glm::dvec3(m[1]) * v.y + glm::dvec3(m[2]) * v.z;
}

// [t0, t1] where a <= o + t d <= b along one axis; false if the line never is.
// A zero direction component leaves the interval unbounded (or empty).
bool slab(double o, double d, double a, double b, double& t0, double& t1) {
  if (d == 0) {
    t0 = -kInfinity;
    t1 = kInfinity;
    return o >= a && o <= b;
  }
  const double inv = 1.0 / d;
  t0 = (a - o) * inv;
  t1 = (b - o) * inv;
  if (t0 > t1) std::swap(t0, t1);
  return true;
}

// The unit sphere in object space.
bool intersect_sphere(const glm::dvec3& o, const glm::dvec3& d, LineSpan& s) {
  return intersect_round_sphere(o, d, 1.0, s);
}

bool intersect_box(const glm::dvec3& o, const glm::dvec3& d, LineSpan& s) {
  double t_enter = -kInfinity, t_exit = kInfinity;
  int enter_face = 0, exit_face = 0;
  for (int axis = 0; axis < 3; ++axis) {
    double t0, t1;
    if (!slab(o[axis], d[axis], 0.0, 1.0, t0, t1)) return false;
    if (d[axis] == 0) continue;
    const int near_face = 2 * axis + (d[axis] > 0 ? 0 : 1);
    const int far_face = 2 * axis + (d[axis] > 0 ? 1 : 0);
    if (t0 > t_enter) {
      t_enter = t0;
      enter_face = near_face;
    }
    if (t1 < t_exit) {
      t_exit = t1;
      exit_face = far_face;
    }
  }
  s = {t_enter, t_exit, enter_face, exit_face};
  return t_enter < t_exit;
}

// The frustum 0 <= z <= 1, x^2 + y^2 <= r(z)^2 with r(z) = r1 + k z, k = r2 - r1.
// Inside the slab r(z) >= 0, so the solid there is exactly {f <= 0} with
// f = x^2 + y^2 - r(z)^2; the line meets it in one interval, the part of
// {f(t) <= 0} inside the slab's interval.
bool intersect_cone(const glm::dvec3& o, const glm::dvec3& d, double r1, double r2, LineSpan& s) {
  double slab0, slab1;
  if (!slab(o.z, d.z, 0.0, 1.0, slab0, slab1)) return false;
  const int slab_enter = d.z > 0 ? 1 : 2, slab_exit = d.z > 0 ? 2 : 1;

  const double k = r2 - r1;
  const double ro = r1 + k * o.z;  // r at the origin's height
  const double A = d.x * d.x + d.y * d.y - k * k * d.z * d.z;
  const double B = o.x * d.x + o.y * d.y - k * d.z * ro;
  const double C = o.x * o.x + o.y * o.y - ro * ro;

  // {t : A t^2 + 2 B t + C <= 0} as one interval [q0, q1] overlapping the slab.
  double q0 = -kInfinity, q1 = kInfinity;
  if (A == 0) {
    if (B == 0) {
      if (C > 0) return false;
    } else if (B > 0) {
      q1 = -C / (2 * B);
    } else {
      q0 = -C / (2 * B);
    }
  } else {
    const double disc = B * B - A * C;
    if (disc <= 0) {
      if (A > 0) return false;  // f > 0 everywhere on the line
      // A < 0 and no real root: f < 0 everywhere on the line.
    } else {
      const double q = -(B + std::copysign(std::sqrt(disc), B));
      double ra = q / A, rb = C / q;
      if (ra > rb) std::swap(ra, rb);
      if (A > 0) {
        q0 = ra;
        q1 = rb;
      } else {
        // Two half-lines, one per nappe of the double cone; only the nappe that
        // holds the frustum overlaps the slab. Keep the larger overlap.
        const double left = std::min(ra, slab1) - slab0;
        const double right = slab1 - std::max(rb, slab0);
        if (left >= right) {
          q1 = ra;
        } else {
          q0 = rb;
        }
      }
    }
  }
  s.t_enter = slab0;
  s.enter_surface = slab_enter;
  if (q0 > slab0) {
    s.t_enter = q0;
    s.enter_surface = 0;
  }
  s.t_exit = slab1;
  s.exit_surface = slab_exit;
  if (q1 < slab1) {
    s.t_exit = q1;
    s.exit_surface = 0;
  }
  if (d.z == 0) {
    s.enter_surface = 0;
    s.exit_surface = 0;
  }
  return s.t_enter < s.t_exit;
}

}  // namespace

PreparedPrimitive prepare_primitive(const Primitive& prim) {
  PreparedPrimitive p;
  p.kind = prim.kind;
  p.to_world = prim.to_world;
  p.to_object = glm::inverse(prim.to_world);
  p.normal_to_world = glm::transpose(glm::inverse(glm::dmat3(prim.to_world)));
  p.cone_r1 = prim.cone_r1;
  p.cone_r2 = prim.cone_r2;
  if (p.kind == PrimitiveKind::Mesh) p.mesh = std::make_shared<const MeshHierarchy>(build_mesh_hierarchy(prim.mesh));
  p.revolution = prim.revolution;
  for (const glm::dvec3& c : box_corners(object_bounds(p)))
    p.world_bounds.extend(transform_point(p.to_world, c));
  if (p.kind == PrimitiveKind::Sphere) {
    // A similarity's linear part A has A^T A = s^2 I; the test is exact, so only
    // transforms that are similarities to the last bit take the world-space path.
    const glm::dmat3 a(p.to_world);
    const glm::dmat3 g = glm::transpose(a) * a;
    p.round_sphere = g[0][1] == 0 && g[0][2] == 0 && g[1][2] == 0 && g[0][0] == g[1][1] &&
                     g[1][1] == g[2][2];
    p.center = glm::dvec3(p.to_world[3]);
    p.radius = std::sqrt(g[0][0]);
  }
  return p;
}

RoundSphereSlot round_sphere_slot(const PreparedPrimitive& p) {
  if (!p.round_sphere) return {};
  return {p.center, p.radius * p.radius};
}

bool intersect_line(const PreparedPrimitive& p, const Ray& world_ray, LineSpan& span,
                    OpCounts& ops) {
  if (p.round_sphere) {
    ++ops.sphere_tests;
    return intersect_round_sphere(world_ray.origin - p.center, world_ray.dir, p.radius * p.radius, span);
  }
  const glm::dvec3 o = transform_point(p.to_object, world_ray.origin);
  const glm::dvec3 d = transform_vector(p.to_object, world_ray.dir);
  switch (p.kind) {
    case PrimitiveKind::Sphere:
      ++ops.sphere_tests;
      return intersect_sphere(o, d, span);
    case PrimitiveKind::Box:
      ++ops.box_tests;
      return intersect_box(o, d, span);
    case PrimitiveKind::Cone:
      ++ops.cone_tests;
      return intersect_cone(o, d, p.cone_r1, p.cone_r2, span);
    case PrimitiveKind::Mesh:
    case PrimitiveKind::Revolution:
      break;
  }
  return false;
}

void mesh_crossings(const PreparedPrimitive& p, const Ray& world_ray, std::vector<LineCrossing>& out,
                    std::vector<LineCrossing>& work, OpCounts& ops) {
  ++ops.mesh_tests;
  mesh_line_crossings(*p.mesh, transform_point(p.to_object, world_ray.origin),
                      transform_vector(p.to_object, world_ray.dir), out, work, ops);
}

void revolution_crossings(const PreparedPrimitive& p, const Ray& world_ray, std::vector<LineCrossing>& out,
                          std::vector<LineCrossing>& work, OpCounts& ops) {
  ++ops.revolution_tests;
  revolution_line_crossings(*p.revolution, transform_point(p.to_object, world_ray.origin),
                            transform_vector(p.to_object, world_ray.dir), out, work, ops);
}

void leaf_crossings(const PreparedPrimitive& p, const Ray& world_ray, std::vector<LineCrossing>& out,
                    std::vector<LineCrossing>& work, OpCounts& ops) {
  if (p.kind == PrimitiveKind::Revolution) {
    revolution_crossings(p, world_ray, out, work, ops);
  } else {
    mesh_crossings(p, world_ray, out, work, ops);
  }
}

std::uint64_t world_normal_matvecs(const PreparedPrimitive& p, SurfaceId s) {
  // Into the primitive's space (a transformed sphere, a cone's side, a
  // revolution) and back out with the normal matrix (all): a round sphere is
  // counted as the transformed one, the work the machine does.
  switch (p.kind) {
    case PrimitiveKind::Sphere: return p.round_sphere ? kRoundSphereNormalMatvecs : 2;
    case PrimitiveKind::Box: return 1;
    case PrimitiveKind::Cone: return s == 1 || s == 2 ? 1 : 2;
    case PrimitiveKind::Mesh: return 1;
    case PrimitiveKind::Revolution: return 2;
  }
  return 1;
}

glm::dvec3 world_normal(const PreparedPrimitive& p, const glm::dvec3& world_point, SurfaceId s,
                        OpCounts& ops) {
  // The machine's count, from the one table of it, whichever way the normal
  // is worked out below.
  ops.matvec += world_normal_matvecs(p, s);
  glm::dvec3 n{0, 0, 1};
  switch (p.kind) {
    case PrimitiveKind::Sphere:
      if (p.round_sphere) return round_sphere_unit_normal(p.center, world_point);
      n = transform_point(p.to_object, world_point);
      break;
    case PrimitiveKind::Box: {
      const int axis = s / 2;
      n = glm::dvec3(0);
      n[axis] = (s % 2) ? 1.0 : -1.0;
      break;
    }
    case PrimitiveKind::Cone:
      if (s == 1) {
        n = {0, 0, -1};
      } else if (s == 2) {
        n = {0, 0, 1};
      } else {
        const glm::dvec3 q = transform_point(p.to_object, world_point);
        const double k = p.cone_r2 - p.cone_r1;
        n = {q.x, q.y, -k * (p.cone_r1 + k * q.z)};
        // At a pointed apex the gradient vanishes; the axis is the limit direction.
        if (glm::dot(n, n) == 0) n = {0, 0, k < 0 ? 1.0 : -1.0};
      }
      break;
    case PrimitiveKind::Mesh:
      n = p.mesh->face_normals[static_cast<std::size_t>(s)];
      break;
    case PrimitiveKind::Revolution:
      n = revolution_normal(*p.revolution, transform_point(p.to_object, world_point), s);
      break;
  }
  return glm::normalize(p.normal_to_world * n);
}

}  // namespace capsim
