// rotate_extrude's polyhedron, point for point and triangle for triangle as
// OpenSCAD 2021.01's rotatePolygon writes it.

#include "scene/extrusions/revolved_mesh.h"

#include "scene/extrusions/scene_revolve.h"
#include "scene/reading/scene_expression.h"

#include <fmt/format.h>

#include <cmath>
#include <cstddef>

namespace capsim::scene_file {

namespace {

// fill_ring: the outline at angle a (backwards under flip).
std::vector<glm::dvec3> ring(const std::vector<glm::dvec2>& outline, double a, bool flip) {
  const std::size_t n = outline.size();
  std::vector<glm::dvec3> r(n);
  const double s = sin_degrees(a), c = cos_degrees(a);
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec2 v = outline[flip ? n - 1 - i : i];
    r[i] = {v.x * s, v.x * c, v.y};
  }
  return r;
}

}  // namespace

RevolvedMeshing plan_revolved_mesh(const Polygon2d& shape, double angle, const Resolution& res, const Loc& loc) {
  double min_x = 0, max_x = 0;
  std::size_t points = 0;
  for (const Outline2d& o : shape.outlines) {
    for (const glm::dvec2& v : o.vertices) min_x = std::fmin(min_x, v.x), max_x = std::fmax(max_x, v.x);
    points += o.vertices.size();
  }
  check_one_side_of_axis(min_x, max_x, loc);
  RevolvedMeshing plan;
  plan.angle = angle;
  plan.fragments = static_cast<int>(std::fmax(fragments_for(max_x - min_x, res, loc) * std::abs(angle) / 360, 1));
  plan.flip = (min_x >= 0 && angle > 0 && angle != 360) || (min_x < 0 && (angle < 0 || angle == 360));
  const std::size_t rings = static_cast<std::size_t>(plan.fragments) + (angle == 360 ? 0 : 1);
  if (points * rings > kMaxTessellatedPoints)
    throw SceneError(loc, fmt::format("rotate_extrude() would be meshed with {} points ({} rings of {}), more than "
                                      "the {} capsim tessellates",
                                      points * rings, rings, points, kMaxTessellatedPoints));
  return plan;
}

PolygonMesh revolved_outline_mesh(const std::vector<glm::dvec2>& outline, const RevolvedMeshing& plan) {
  const bool full = plan.angle == 360;
  const std::size_t n = outline.size();
  PolySetBuilder p;
  auto triangle = [&](const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    if (a == b || b == c || c == a) return;  // collapsed on the axis
    p.append_poly();
    for (const glm::dvec3& v : {a, b, c}) p.append_vertex(v.x, v.y, v.z);
  };
  auto cap = [&](const std::vector<glm::dvec3>& r, bool backwards) {
    p.append_poly();
    for (std::size_t i = 0; i < n; ++i) {
      const glm::dvec3& v = r[backwards ? n - 1 - i : i];
      p.append_vertex(v.x, v.y, v.z);
    }
  };
  std::vector<glm::dvec3> prev = ring(outline, full ? -90 : 90, plan.flip);
  // The caps run against the sides along the end rings, so that every edge
  // is walked both ways: the first ring backwards, the last forwards.
  if (!full) cap(prev, true);
  const int f = plan.fragments;
  for (int j = 0; j < f; ++j) {
    const double a = full ? -90 + ((j + 1) % f) * 360.0 / f : 90 - (j + 1) * plan.angle / f;
    std::vector<glm::dvec3> next = ring(outline, a, plan.flip);
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t k = (i + 1) % n;
      // OpenSCAD inserts each corner at the front: these are its orders.
      triangle(prev[k], next[k], prev[i]);
      triangle(next[k], next[i], prev[i]);
    }
    prev = std::move(next);
  }
  if (!full) cap(prev, false);
  return p.take();
}

}  // namespace capsim::scene_file
