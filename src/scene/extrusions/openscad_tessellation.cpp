// OpenSCAD's meshes of its solid primitives, written as OpenSCAD writes them.

#include "scene/extrusions/openscad_tessellation.h"

#include "scene/reading/scene_args.h"
#include "scene/reading/scene_expression.h"
#include "scene/reading/scene_modules.h"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <map>
#include <numbers>

namespace capsim::scene_file {

namespace {

// OpenSCAD's GRID_FINE: below this radius a circle has 3 fragments.
constexpr double kGridFine = 0.00000095367431640625;
// OpenSCAD's F_MINIMUM, the least $fa and $fs it uses.
constexpr double kLeastAngleOrSize = 0.01;

double special(const Call& call, std::string_view name, double fallback) {
  for (const Argument& a : call.args)
    if (a.name == name && a.value.kind == Value::Kind::Number) return a.value.number;
  return fallback;
}

}  // namespace

std::uint32_t PolySetBuilder::index(double x, double y, double z) {
  // +0 turns -0 into 0.
  const auto [at, added] = ids_.try_emplace({x + 0.0, y + 0.0, z + 0.0}, static_cast<std::uint32_t>(mesh_.points.size()));
  if (added) mesh_.points.emplace_back(x, y, z);
  return at->second;
}

Resolution read_resolution(const Call& call, bool clamped) {
  Resolution r;
  r.fn = special(call, "$fn", 0);
  r.fa = special(call, "$fa", 12);
  r.fs = special(call, "$fs", 2);
  if (clamped) {
    r.fa = std::max(r.fa, kLeastAngleOrSize);
    r.fs = std::max(r.fs, kLeastAngleOrSize);
  }
  return r;
}

int fragments_for(double r, const Resolution& res, const Loc& loc) {
  if (r < kGridFine || std::isinf(res.fn) || std::isnan(res.fn)) return 3;
  const double fragments = res.fn > 0.0 ? (res.fn >= 3 ? std::trunc(res.fn) : 3)
                                        : std::ceil(std::fmax(std::fmin(360.0 / res.fa, r * 2 * std::numbers::pi / res.fs), 5));
  if (!(fragments <= kMaxFragments))
    throw SceneError(loc, fmt::format("$fn = {}, $fa = {}, $fs = {} give {:g} fragments for a circle of radius {}, more "
                                      "than the {} capsim tessellates",
                                      res.fn, res.fa, res.fs, fragments, r, kMaxFragments));
  return static_cast<int>(fragments);
}

std::vector<glm::dvec2> openscad_circle(double r, int fragments) {
  std::vector<glm::dvec2> c(static_cast<std::size_t>(fragments));
  for (int i = 0; i < fragments; ++i) {
    const double phi = (360.0 * i) / fragments;
    c[static_cast<std::size_t>(i)] = {r * cos_degrees(phi), r * sin_degrees(phi)};
  }
  return c;
}

PolygonMesh openscad_sphere(double r, int fragments) {
  struct Ring {
    std::vector<glm::dvec2> points;
    double z;
  };
  const int rings = (fragments + 1) / 2;
  std::vector<Ring> ring(static_cast<std::size_t>(rings));
  for (int i = 0; i < rings; ++i) {
    const double phi = (180.0 * (i + 0.5)) / rings;
    ring[static_cast<std::size_t>(i)] = {openscad_circle(r * sin_degrees(phi), fragments), r * cos_degrees(phi)};
  }
  PolySetBuilder p;
  p.append_poly();
  for (const glm::dvec2& v : ring.front().points) p.append_vertex(v.x, v.y, ring.front().z);
  for (std::size_t i = 0; i + 1 < ring.size(); ++i) {
    const Ring &r1 = ring[i], &r2 = ring[i + 1];
    // OpenSCAD walks both rings at once, a triangle on the ring behind.
    int r1i = 0, r2i = 0;
    const auto at = [&](const Ring& rg, int k) { return rg.points[static_cast<std::size_t>(k % fragments)]; };
    while (r1i < fragments || r2i < fragments) {
      const bool next_r1 = r2i >= fragments || (r1i < fragments && static_cast<double>(r1i) / fragments <
                                                                         static_cast<double>(r2i) / fragments);
      p.append_poly();
      if (next_r1) {
        const glm::dvec2 a = at(r1, r1i), b = at(r1, r1i + 1), c = at(r2, r2i);
        p.insert_vertex(a.x, a.y, r1.z);
        p.insert_vertex(b.x, b.y, r1.z);
        p.insert_vertex(c.x, c.y, r2.z);
        ++r1i;
      } else {
        const glm::dvec2 a = at(r2, r2i), b = at(r2, r2i + 1), c = at(r1, r1i);
        p.append_vertex(a.x, a.y, r2.z);
        p.append_vertex(b.x, b.y, r2.z);
        p.append_vertex(c.x, c.y, r1.z);
        ++r2i;
      }
    }
  }
  p.append_poly();
  for (const glm::dvec2& v : ring.back().points) p.insert_vertex(v.x, v.y, ring.back().z);
  return p.take();
}

PolygonMesh openscad_cylinder(double h, double r1, double r2, bool center, int fragments) {
  const double z1 = center ? -h / 2 : 0, z2 = center ? h / 2 : h;
  const std::vector<glm::dvec2> c1 = openscad_circle(r1, fragments), c2 = openscad_circle(r2, fragments);
  PolySetBuilder p;
  for (std::size_t i = 0; i < c1.size(); ++i) {
    const std::size_t j = (i + 1) % c1.size();
    if (r1 == r2) {
      p.append_poly();
      p.insert_vertex(c1[i].x, c1[i].y, z1);
      p.insert_vertex(c2[i].x, c2[i].y, z2);
      p.insert_vertex(c2[j].x, c2[j].y, z2);
      p.insert_vertex(c1[j].x, c1[j].y, z1);
      continue;
    }
    if (r1 > 0) {
      p.append_poly();
      p.insert_vertex(c1[i].x, c1[i].y, z1);
      p.insert_vertex(c2[i].x, c2[i].y, z2);
      p.insert_vertex(c1[j].x, c1[j].y, z1);
    }
    if (r2 > 0) {
      p.append_poly();
      p.insert_vertex(c2[i].x, c2[i].y, z2);
      p.insert_vertex(c2[j].x, c2[j].y, z2);
      p.insert_vertex(c1[j].x, c1[j].y, z1);
    }
  }
  if (r1 > 0) {
    p.append_poly();
    for (const glm::dvec2& v : c1) p.insert_vertex(v.x, v.y, z1);
  }
  if (r2 > 0) {
    p.append_poly();
    for (const glm::dvec2& v : c2) p.append_vertex(v.x, v.y, z2);
  }
  return p.take();
}

PolygonMesh openscad_cube(const glm::dvec3& size, bool center) {
  const glm::dvec3 lo = center ? -size / 2.0 : glm::dvec3(0), hi = center ? size / 2.0 : size;
  const double x1 = lo.x, y1 = lo.y, z1 = lo.z, x2 = hi.x, y2 = hi.y, z2 = hi.z;
  PolySetBuilder p;
  const auto quad = [&p](std::array<glm::dvec3, 4> q) {
    p.append_poly();
    for (const glm::dvec3& v : q) p.append_vertex(v.x, v.y, v.z);
  };
  quad({{{x1, y1, z2}, {x2, y1, z2}, {x2, y2, z2}, {x1, y2, z2}}});  // top
  quad({{{x1, y2, z1}, {x2, y2, z1}, {x2, y1, z1}, {x1, y1, z1}}});  // bottom
  quad({{{x1, y1, z1}, {x2, y1, z1}, {x2, y1, z2}, {x1, y1, z2}}});
  quad({{{x2, y1, z1}, {x2, y2, z1}, {x2, y2, z2}, {x2, y1, z2}}});
  quad({{{x2, y2, z1}, {x1, y2, z1}, {x1, y2, z2}, {x2, y2, z2}}});
  quad({{{x1, y2, z1}, {x1, y1, z1}, {x1, y1, z2}, {x1, y2, z2}}});
  return p.take();
}

PolygonMesh tessellate_primitive(const Call& call) {
  // read_primitive checks the arguments and gives the shape's measures.
  const Primitive shape = read_primitive(call);
  const Resolution res = read_resolution(call);
  const glm::dmat4& m = shape.to_world;
  if (shape.kind == PrimitiveKind::Box) return openscad_cube({m[0][0], m[1][1], m[2][2]}, m[3][0] != 0);
  const double r = m[0][0];
  const int fragments = fragments_for(r, res, call.loc);
  const double points = shape.kind == PrimitiveKind::Sphere ? static_cast<double>(fragments) * ((fragments + 1) / 2)
                                                             : 2.0 * fragments;
  if (points > static_cast<double>(kMaxTessellatedPoints))
    throw SceneError(call.loc, fmt::format("{} would have {:g} points at $fn = {}, $fa = {}, $fs = {}, more than the {} "
                                           "capsim tessellates",
                                           call.name, points, res.fn, res.fa, res.fs, kMaxTessellatedPoints));
  if (shape.kind == PrimitiveKind::Sphere) return openscad_sphere(r, fragments);
  return openscad_cylinder(m[2][2], shape.cone_r1 * r, shape.cone_r2 * r, m[3][2] != 0, fragments);
}

}  // namespace capsim::scene_file
