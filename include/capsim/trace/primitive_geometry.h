#pragma once
// Exact ray-primitive intersection. The paper's primitives are convex solids, so a
// line meets one in one interval [t_enter, t_exit] (possibly empty); a mesh is met
// in any number of intervals, given as its sorted boundary crossings. The tracer
// turns both into the crossings that drive the status tree.

#include "capsim/scene/scene.h"
#include "capsim/trace/mesh_geometry.h"
#include "capsim/trace/op_counts.h"
#include "capsim/trace/ray.h"
#include "capsim/trace/revolution_geometry.h"

#include <cmath>

namespace capsim {

// A primitive ready for tracing: the inverse transform and the normal matrix are
// computed once. What a test of a round sphere reads comes first, in the first
// cache line of the record.
struct alignas(64) PreparedPrimitive {
  PrimitiveKind kind = PrimitiveKind::Sphere;
  // A sphere whose transform is a similarity (rotation, uniform scale, mirror,
  // translation) is a round sphere in world space too: centre and radius let it
  // be intersected there, without carrying the ray into object space.
  bool round_sphere = false;
  glm::dvec3 center{0};
  double radius = 1;
  glm::dmat4 to_world{1.0};
  glm::dmat4 to_object{1.0};
  glm::dmat3 normal_to_world{1.0};  // inverse transpose of to_world's linear part
  double cone_r1 = 1, cone_r2 = 1;
  Aabb world_bounds;                // the 8 corners of the object box, transformed
  std::shared_ptr<const MeshHierarchy> mesh;  // Mesh only
  std::shared_ptr<const Revolution> revolution;  // Revolution only
};

PreparedPrimitive prepare_primitive(const Primitive& p);

// The object-space bounding box of a prepared primitive (scene.h's object_bounds).
inline Aabb object_bounds(const PreparedPrimitive& p) {
  if (p.kind == PrimitiveKind::Revolution) return p.revolution->bounds;
  return p.kind == PrimitiveKind::Mesh ? p.mesh->mesh->bounds : object_bounds(p.kind);
}

// Whether a line meets the primitive in any number of intervals (leaf_crossings)
// rather than in one (intersect_line).
inline bool has_many_intervals(PrimitiveKind kind) {
  return kind == PrimitiveKind::Mesh || kind == PrimitiveKind::Revolution;
}

// Which surface of the primitive a crossing lies on (box: face 0..5 as -x,+x,-y,+y,
// -z,+z; cone: 0 side, 1 cap z=0, 2 cap z=1; sphere: 0; mesh: its triangle;
// revolution: as Revolution numbers them).
using SurfaceId = int;

struct LineSpan {
  double t_enter = kInfinity;
  double t_exit = -kInfinity;
  SurfaceId enter_surface = 0;
  SurfaceId exit_surface = 0;
};

// Intersects the whole line origin + t dir (ignoring tmin/tmax) with a convex
// solid (not a Mesh or a Revolution). Returns false when the line misses or only grazes it (an
// empty or one-point interval). Counts one test of the primitive's kind; its
// cost, as in the paper's Table 4-1, includes carrying the ray into object space.
bool intersect_line(const PreparedPrimitive& p, const Ray& world_ray, LineSpan& span,
                    OpCounts& ops);

// |o + t d|^2 = r2, solved about the line's closest point to the centre,
// p = o + tc d with tc = -(o . d) / a: it becomes a (t - tc)^2 = r2 - |p|^2,
// which keeps its digits when the origin is far away (b^2 - a c would cancel).
// Most tests miss, and the miss test needs no division: with q = a p =
// a o - (o . d) d, the line meets the sphere where a^2 r2 > |q|^2. The test
// of a round sphere (o = the ray's origin less the centre) and of the unit
// sphere in object space.
inline bool intersect_round_sphere(const glm::dvec3& o, const glm::dvec3& d, double r2, LineSpan& s) {
  const double a = glm::dot(d, d);
  const double b = glm::dot(o, d);
  const glm::dvec3 q = a * o - b * d;
  const double excess = a * a * r2 - glm::dot(q, q);  // a^2 (r2 - |p|^2)
  if (!(excess > 0)) return false;
  const double tc = -b / a;
  const double h = std::sqrt(excess / a) / a;  // sqrt((r2 - |p|^2) / a)
  s = {tc - h, tc + h, 0, 0};
  return s.t_enter < s.t_exit;
}

// A round sphere's centre and squared radius, packed for the voxel walk: the
// walk reads a voxel's spheres from these 32 bytes each, not from their
// PreparedPrimitives (several hundred bytes apart, most of a crowded
// voxel's time went to fetching them). r2 < 0: the primitive is not a round
// sphere. intersect_round_sphere(origin - center, dir, r2) is, to the bit,
// intersect_line's test of the primitive.
struct RoundSphereSlot {
  glm::dvec3 center{0};
  double r2 = -1;
};
RoundSphereSlot round_sphere_slot(const PreparedPrimitive& p);

// The crossings of the whole line origin + t dir with a Mesh (mesh_line_crossings):
// sorted, entries and exits alternating from an entry. Counts one mesh test (the
// ray carried into the mesh's space) and the work mesh_line_crossings counts.
void mesh_crossings(const PreparedPrimitive& p, const Ray& world_ray, std::vector<LineCrossing>& out,
                    std::vector<LineCrossing>& work, OpCounts& ops);

// The crossings of the whole line with a Revolution (revolution_line_crossings),
// sorted, alternating from an entry. Counts one revolution test (the ray
// carried into its space) and the work revolution_line_crossings counts.
void revolution_crossings(const PreparedPrimitive& p, const Ray& world_ray, std::vector<LineCrossing>& out,
                          std::vector<LineCrossing>& work, OpCounts& ops);

// The crossings of a primitive with many intervals (has_many_intervals).
void leaf_crossings(const PreparedPrimitive& p, const Ray& world_ray, std::vector<LineCrossing>& out,
                    std::vector<LineCrossing>& work, OpCounts& ops);

// The primitive's outward unit normal, in world space, at a world point on
// surface s; adds world_normal_matvecs(p, s) to ops.matvec.
glm::dvec3 world_normal(const PreparedPrimitive& p, const glm::dvec3& world_point, SurfaceId s,
                        OpCounts& ops);

// The matrix-vector products world_normal(p, point, s, ops) counts in ops.matvec
// (the same at every point of surface s): the machine's cost of a normal.
std::uint64_t world_normal_matvecs(const PreparedPrimitive& p, SurfaceId s);

// world_normal of a round sphere about `center`, to the bit: the same normal
// as through the matrices, uncounted.
inline glm::dvec3 round_sphere_unit_normal(const glm::dvec3& center, const glm::dvec3& world_point) {
  return glm::normalize(world_point - center);
}
// The same with world_normal's count for a round sphere (the simulated
// machine does the general work), for callers that hold its centre but not
// its primitive.
inline constexpr std::uint64_t kRoundSphereNormalMatvecs = 2;
inline glm::dvec3 round_sphere_normal(const glm::dvec3& center, const glm::dvec3& world_point, OpCounts& ops) {
  ops.matvec += kRoundSphereNormalMatvecs;
  return round_sphere_unit_normal(center, world_point);
}

}  // namespace capsim
