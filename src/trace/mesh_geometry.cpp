// A mesh leaf's crossings with a line: the hierarchy walked, each triangle
// tested watertight, the hits merged into the solid's boundary crossings.

#include "capsim/trace/mesh_geometry.h"

#include <algorithm>
#include <array>

namespace capsim {

namespace {

constexpr std::uint32_t kLeafTriangles = 4;

// The whole line o + t d meets the box (t unbounded).
bool line_meets_box(const Aabb& b, const glm::dvec3& o, const glm::dvec3& d) {
  double t_near = -kInfinity, t_far = kInfinity;
  for (int axis = 0; axis < 3; ++axis) {
    if (d[axis] == 0) {
      if (o[axis] < b.lo[axis] || o[axis] > b.hi[axis]) return false;
      continue;
    }
    const double inv = 1.0 / d[axis];
    double t0 = (b.lo[axis] - o[axis]) * inv, t1 = (b.hi[axis] - o[axis]) * inv;
    if (t0 > t1) std::swap(t0, t1);
    t_near = std::max(t_near, t0);
    t_far = std::min(t_far, t1);
  }
  return t_near <= t_far;
}

// The line's frame of the watertight test: kz the axis d is longest along,
// kx and ky the other two (swapped when d points down kz, which keeps the
// frame's handedness), and the shear that makes d the kz axis.
struct Shear {
  int kx, ky, kz;
  double sx, sy, sz;
};

Shear shear_of(const glm::dvec3& d) {
  const glm::dvec3 a = glm::abs(d);
  Shear s;
  s.kz = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
  s.kx = (s.kz + 1) % 3;
  s.ky = (s.kx + 1) % 3;
  if (d[s.kz] < 0) std::swap(s.kx, s.ky);
  s.sx = d[s.kx] / d[s.kz];
  s.sy = d[s.ky] / d[s.kz];
  s.sz = 1.0 / d[s.kz];
  return s;
}

// A vertex relative to the line's origin, sheared: the line is the kz axis.
glm::dvec3 sheared(const glm::dvec3& v, const glm::dvec3& o, const Shear& s) {
  const glm::dvec3 a = v - o;
  return {a[s.kx] - s.sx * a[s.kz], a[s.ky] - s.sy * a[s.kz], s.sz * a[s.kz]};
}

// An edge function that is exactly zero (the line passes through the edge)
// counts for the triangle when the edge, turned by the triangle's orientation,
// points up (or right along the x axis): of two triangles that continue the
// surface across the edge exactly one claims the line, of two that fold back
// at it (a silhouette) both or neither. Around a vertex the line passes
// through, exactly one triangle of a fan that surrounds it claims it.
bool edge_counts(double e, double s, const glm::dvec3& p, const glm::dvec3& q) {
  if (e != 0) return s * e > 0;
  const double dx = s * (q.x - p.x), dy = s * (q.y - p.y);
  return dy > 0 || (dy == 0 && dx > 0);
}

// The watertight test of one triangle; on a hit, its t and whether the line
// enters the solid there (the triangle faces against d).
bool hit_triangle(const TriangleMesh& m, std::uint32_t tri, const glm::dvec3& o, const Shear& sh, double& t,
                  bool& enter) {
  const auto& idx = m.triangles[tri];
  const glm::dvec3 a = sheared(m.vertices[idx[0]], o, sh);
  const glm::dvec3 b = sheared(m.vertices[idx[1]], o, sh);
  const glm::dvec3 c = sheared(m.vertices[idx[2]], o, sh);
  const double u = c.x * b.y - c.y * b.x;  // edge b -> c
  const double v = a.x * c.y - a.y * c.x;  // edge c -> a
  const double w = b.x * a.y - b.y * a.x;  // edge a -> b
  const double det = u + v + w;
  if (det == 0) return false;  // seen edge-on
  const double s = det > 0 ? 1.0 : -1.0;
  if (!edge_counts(u, s, b, c) || !edge_counts(v, s, c, a) || !edge_counts(w, s, a, b)) return false;
  t = (u * a.z + v * b.z + w * c.z) / det;
  enter = det > 0;
  return true;
}

}  // namespace

MeshHierarchy build_mesh_hierarchy(std::shared_ptr<const TriangleMesh> mesh) {
  MeshHierarchy h;
  const TriangleMesh& m = *mesh;
  const auto n = static_cast<std::uint32_t>(m.triangles.size());
  std::vector<glm::dvec3> centre(n);
  std::vector<Aabb> box(n);
  h.face_normals.resize(n);
  h.order.resize(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    const glm::dvec3 &a = m.vertices[m.triangles[i][0]], &b = m.vertices[m.triangles[i][1]],
                     &c = m.vertices[m.triangles[i][2]];
    box[i].extend(a);
    box[i].extend(b);
    box[i].extend(c);
    centre[i] = box[i].center();
    h.face_normals[i] = glm::cross(b - a, c - a);
    h.order[i] = i;
  }
  h.nodes.push_back({Aabb{}, 0, n});
  std::vector<std::uint32_t> todo = {0};
  while (!todo.empty()) {
    const std::uint32_t at = todo.back();
    todo.pop_back();
    const std::uint32_t first = h.nodes[at].first, count = h.nodes[at].count;
    Aabb bounds, centres;
    for (std::uint32_t k = first; k < first + count; ++k) {
      bounds.extend(box[h.order[k]]);
      centres.extend(centre[h.order[k]]);
    }
    h.nodes[at].box = bounds;
    if (count <= kLeafTriangles) continue;
    const glm::dvec3 e = centres.extent();
    const int axis = e.x >= e.y && e.x >= e.z ? 0 : e.y >= e.z ? 1 : 2;
    const auto begin = h.order.begin() + first;
    const std::uint32_t half = count / 2;
    std::nth_element(begin, begin + half, begin + count, [&](std::uint32_t x, std::uint32_t y) {
      return centre[x][axis] != centre[y][axis] ? centre[x][axis] < centre[y][axis] : x < y;
    });
    const auto left = static_cast<std::uint32_t>(h.nodes.size());
    h.nodes.push_back({Aabb{}, first, half});
    h.nodes.push_back({Aabb{}, first + half, count - half});
    h.nodes[at].first = left;
    h.nodes[at].count = 0;
    todo.push_back(left + 1);
    todo.push_back(left);
  }
  h.mesh = std::move(mesh);
  return h;
}

void mesh_line_crossings(const MeshHierarchy& h, const glm::dvec3& o, const glm::dvec3& d,
                         std::vector<LineCrossing>& out, std::vector<LineCrossing>& hits, OpCounts& ops) {
  out.clear();
  hits.clear();
  const Shear sh = shear_of(d);
  std::array<std::uint32_t, 64> stack;  // a median split is at most 32 levels deep
  std::size_t top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const MeshNode& node = h.nodes[stack[--top]];
    ++ops.mesh_node_tests;
    if (!line_meets_box(node.box, o, d)) continue;
    if (node.count == 0) {
      stack[top++] = node.first + 1;
      stack[top++] = node.first;
      continue;
    }
    for (std::uint32_t k = node.first; k < node.first + node.count; ++k) {
      ++ops.triangle_tests;
      double t;
      bool enter;
      if (hit_triangle(*h.mesh, h.order[k], o, sh, t, enter)) hits.push_back({t, static_cast<int>(h.order[k]), enter});
    }
  }
  std::sort(hits.begin(), hits.end(), [](const LineCrossing& a, const LineCrossing& b) {
    return a.t != b.t ? a.t < b.t : a.surface < b.surface;
  });
  // The winding number of the surface about the line's points: 0 before the
  // first crossing, up one at each entry, down one at each exit. Inside is
  // positive winding; hits at one t are taken together.
  int winding = 0;
  for (std::size_t i = 0; i < hits.size();) {
    const bool was_inside = winding > 0;
    std::size_t j = i;
    for (; j < hits.size() && hits[j].t == hits[i].t; ++j) winding += hits[j].enter ? 1 : -1;
    const bool inside = winding > 0;
    if (inside != was_inside) {
      // The surface crossed: the first hit of the group that goes the same way.
      std::size_t k = i;
      while (hits[k].enter != inside) ++k;
      out.push_back({hits[i].t, hits[k].surface, inside});
    }
    i = j;
  }
}

}  // namespace capsim
