// Closed triangle meshes from polygon faces: the check that they bound a
// solid, the triangulation of each face and the orientation of the whole.

#include "capsim/scene/triangle_mesh.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

namespace capsim {

namespace {

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) { return (std::uint64_t{a} << 32) | b; }

// The first face whose indices are out of range or that has too few points.
std::optional<MeshDefect> face_defect(const PolygonMesh& m) {
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const std::vector<std::uint32_t>& face = m.faces[f];
    const long id = static_cast<long>(f);
    if (face.size() < 3)
      return MeshDefect{id, fmt::format("face {} has {} points; a face needs at least 3", f, face.size())};
    for (std::size_t i = 0; i < face.size(); ++i) {
      if (face[i] >= m.points.size())
        return MeshDefect{id, fmt::format("face {} names point {}, but there are only {} points (0 to {})", f,
                                          face[i], m.points.size(), m.points.size() - 1)};
      if (face[i] == face[(i + 1) % face.size()])
        return MeshDefect{id, fmt::format("face {} names point {} twice in a row", f, face[i])};
    }
  }
  return std::nullopt;
}

// Closed: every directed edge a -> b of a face is met by exactly one face
// running b -> a, and no two faces run the same way along an edge.
std::optional<MeshDefect> closedness_defect(const PolygonMesh& m) {
  std::unordered_map<std::uint64_t, std::uint32_t> owner;  // directed edge -> its face
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const std::vector<std::uint32_t>& face = m.faces[f];
    for (std::size_t i = 0; i < face.size(); ++i) {
      const std::uint32_t a = face[i], b = face[(i + 1) % face.size()];
      const auto [it, fresh] = owner.emplace(edge_key(a, b), static_cast<std::uint32_t>(f));
      if (!fresh)
        return MeshDefect{static_cast<long>(f),
                          fmt::format("faces {} and {} both run from point {} to point {}: the mesh is not closed "
                                      "(more than two faces meet at that edge, or one of them is turned the wrong "
                                      "way)",
                                      it->second, f, a, b)};
    }
  }
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const std::vector<std::uint32_t>& face = m.faces[f];
    for (std::size_t i = 0; i < face.size(); ++i) {
      const std::uint32_t a = face[i], b = face[(i + 1) % face.size()];
      if (!owner.contains(edge_key(b, a)))
        return MeshDefect{static_cast<long>(f),
                          fmt::format("the edge from point {} to point {} of face {} has no face on its other side "
                                      "running from point {} to point {}: the mesh is not closed (it has a hole "
                                      "there, or the face beside it is turned the wrong way)",
                                      a, b, f, b, a)};
    }
  }
  return std::nullopt;
}

double cross2(const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Is p inside or on the triangle (a, b, c) of orientation sign s?
bool in_triangle(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, double s) {
  return s * cross2(a, b, p) >= 0 && s * cross2(b, c, p) >= 0 && s * cross2(c, a, p) >= 0;
}

// Ear clipping of one face, projected onto the coordinate plane its Newell
// normal is most nearly perpendicular to. The triangles keep the face's
// winding. A face with no ear left (it crosses itself) is cut as a fan.
void triangulate(const PolygonMesh& m, const std::vector<std::uint32_t>& face,
                 std::vector<std::array<std::uint32_t, 3>>& out) {
  if (face.size() == 3) {
    out.push_back({face[0], face[1], face[2]});
    return;
  }
  glm::dvec3 normal(0);
  for (std::size_t i = 0; i < face.size(); ++i) {
    const glm::dvec3 &p = m.points[face[i]], &q = m.points[face[(i + 1) % face.size()]];
    normal += glm::dvec3((p.y - q.y) * (p.z + q.z), (p.z - q.z) * (p.x + q.x), (p.x - q.x) * (p.y + q.y));
  }
  const glm::dvec3 n = glm::abs(normal);
  const int drop = n.x >= n.y && n.x >= n.z ? 0 : n.y >= n.z ? 1 : 2;
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  std::vector<glm::dvec2> p;
  for (std::uint32_t i : face) p.emplace_back(m.points[i][u], m.points[i][v]);
  const double s = normal[drop] >= 0 ? 1.0 : -1.0;  // the face's orientation in the (u, v) plane

  std::vector<std::size_t> left(face.size());
  for (std::size_t i = 0; i < left.size(); ++i) left[i] = i;
  while (left.size() > 3) {
    bool clipped = false;
    for (std::size_t k = 0; k < left.size() && !clipped; ++k) {
      const std::size_t a = left[(k + left.size() - 1) % left.size()], b = left[k], c = left[(k + 1) % left.size()];
      if (s * cross2(p[a], p[b], p[c]) <= 0) continue;  // reflex or flat: not an ear
      bool empty = true;
      for (std::size_t j : left)
        if (j != a && j != b && j != c && in_triangle(p[j], p[a], p[b], p[c], s)) empty = false;
      if (!empty) continue;
      out.push_back({face[a], face[b], face[c]});
      left.erase(left.begin() + static_cast<std::ptrdiff_t>(k));
      clipped = true;
    }
    if (!clipped) break;
  }
  for (std::size_t k = 1; k + 1 < left.size(); ++k) out.push_back({face[left[0]], face[left[k]], face[left[k + 1]]});
}

}  // namespace

MeshBuild build_closed_mesh(const PolygonMesh& polygons) {
  MeshBuild r;
  if (polygons.faces.empty()) {
    r.defect = {-1, "the mesh has no faces"};
    return r;
  }
  if (auto d = face_defect(polygons)) {
    r.defect = *d;
    return r;
  }
  if (auto d = closedness_defect(polygons)) {
    r.defect = *d;
    return r;
  }
  TriangleMesh mesh;
  mesh.vertices = polygons.points;
  for (const std::vector<std::uint32_t>& face : polygons.faces) triangulate(polygons, face, mesh.triangles);
  double volume6 = 0;  // six times the signed volume enclosed
  for (const auto& t : mesh.triangles) {
    const glm::dvec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    volume6 += glm::dot(a, glm::cross(b, c));
    mesh.bounds.extend(a);
    mesh.bounds.extend(b);
    mesh.bounds.extend(c);
  }
  const glm::dvec3 e = mesh.bounds.extent();
  const double size = std::max({e.x, e.y, e.z});
  if (!(std::abs(volume6) > 1e-12 * size * size * size)) {
    r.defect = {-1, "the faces enclose no volume (every point lies in one plane, or the faces cancel out)"};
    return r;
  }
  if (volume6 < 0)
    for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
  r.mesh = std::move(mesh);
  return r;
}

PolygonMesh weld_triangles(const std::vector<std::array<glm::dvec3, 3>>& triangles) {
  PolygonMesh m;
  auto less = [](const glm::dvec3& a, const glm::dvec3& b) {
    return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
  };
  std::map<glm::dvec3, std::uint32_t, decltype(less)> index(less);
  m.faces.reserve(triangles.size());
  for (const auto& t : triangles) {
    std::vector<std::uint32_t> face;
    for (const glm::dvec3& corner : t) {
      const auto [it, fresh] = index.emplace(corner, static_cast<std::uint32_t>(m.points.size()));
      if (fresh) m.points.push_back(corner);
      face.push_back(it->second);
    }
    m.faces.push_back(std::move(face));
  }
  return m;
}

}  // namespace capsim
