// linear_extrude of circles, squares and polygons as exact solids.

#include "scene/extrusions/scene_extrusion.h"

#include "scene/extrusions/openscad_tessellation.h"
#include "scene/regions/text_glyphs.h"
#include "scene/extrusions/twisted_extrusion.h"

#include "capsim/scene/scene_limits.h"
#include "scene/reading/scene_args.h"
#include "scene/reading/scene_modules.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace capsim::scene_file {

namespace {

// The placement of extrusion space: z from 0 to the height, or centred.
glm::dmat4 base(const Extrusion& e) {
  glm::dmat4 m(1.0);
  if (e.center) m[3][2] = -e.height / 2;
  return m;
}

glm::dvec2 apply(const glm::dmat3& m, const glm::dvec2& p) { return glm::dvec2(m * glm::dvec3(p, 1.0)); }

double cross(const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

double area2(const std::vector<glm::dvec2>& p) {
  double a = 0;
  for (std::size_t i = 0; i < p.size(); ++i) a += cross(glm::dvec2(0), p[i], p[(i + 1) % p.size()]);
  return a;
}

// Closed segments ab and cd meet (touching counts).
bool segments_meet(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, const glm::dvec2& d) {
  const double d1 = cross(a, b, c), d2 = cross(a, b, d), d3 = cross(c, d, a), d4 = cross(c, d, b);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  auto on = [](const glm::dvec2& p, const glm::dvec2& q, const glm::dvec2& r, double side) {
    return side == 0 && std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) && std::min(p.y, q.y) <= r.y &&
           r.y <= std::max(p.y, q.y);
  };
  return on(a, b, c, d1) || on(a, b, d, d2) || on(c, d, a, d3) || on(c, d, b, d4);
}

// Whether two edges of a path (same: p is q), or of two paths, meet where
// they should not. Edges next to each other in one path share their corner.
bool paths_cross(const std::vector<glm::dvec2>& p, const std::vector<glm::dvec2>& q, bool same) {
  if (!same) {
    // Paths whose boxes are apart cannot cross (a text's glyphs, mostly).
    glm::dvec2 plo(kInfinity), phi(-kInfinity), qlo(kInfinity), qhi(-kInfinity);
    for (const glm::dvec2& v : p) plo = glm::min(plo, v), phi = glm::max(phi, v);
    for (const glm::dvec2& v : q) qlo = glm::min(qlo, v), qhi = glm::max(qhi, v);
    if (phi.x < qlo.x || qhi.x < plo.x || phi.y < qlo.y || qhi.y < plo.y) return false;
  }
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = same ? i + 1 : 0; j < q.size(); ++j) {
      if (same && (j == i + 1 || (i == 0 && j + 1 == p.size()))) continue;
      if (segments_meet(p[i], p[(i + 1) % p.size()], q[j], q[(j + 1) % q.size()])) return true;
    }
  return false;
}

bool inside(const std::vector<glm::dvec2>& poly, const glm::dvec2& pt) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const glm::dvec2 &a = poly[i], &b = poly[j];
    if ((a.y > pt.y) != (b.y > pt.y) && pt.x < (b.x - a.x) * (pt.y - a.y) / (b.y - a.y) + a.x) in = !in;
  }
  return in;
}

// A number (for both) or a vector of 2 numbers.
glm::dvec2 number_or_vec2(const Args& args, std::string_view name, glm::dvec2 fallback) {
  if (!args.has(name)) return fallback;
  const Value& v = args.value(name);
  if (v.kind == Value::Kind::Number) return glm::dvec2(v.number);
  if (v.kind != Value::Kind::Vector || v.items.size() != 2 || v.items[0].kind != Value::Kind::Number ||
      v.items[1].kind != Value::Kind::Number)
    args.fail_type(name, "a number or a vector of 2 numbers");
  return {v.items[0].number, v.items[1].number};
}

// A curved extrusion's leaf: OpenSCAD's tessellation of the path swept.
Primitive swept_prism(const std::vector<glm::dvec2>& path, const Extrusion& e, const Loc& loc) {
  check_swept_points(path.size(), e.slices, loc, "this twisted or unevenly scaled extrusion");
  const Sweep sweep{e.height, e.twist, e.scale_xy, e.slices, e.collars};
  MeshBuild built = build_closed_mesh(sweep_mesh(path, sweep));
  if (!built.mesh)
    throw SceneError(loc, fmt::format("this twisted or unevenly scaled extrusion is not a solid: {}", built.defect.reason));
  Primitive p;
  p.kind = PrimitiveKind::Mesh;
  p.mesh = std::make_shared<const TriangleMesh>(std::move(*built.mesh));
  p.to_world = base(e);
  p.loc = loc;
  return p;
}

// The prism (or frustum, or pyramid at scale 0) over a simple path.
Primitive prism(const std::vector<glm::dvec2>& path, const Extrusion& e, const Loc& loc) {
  if (e.curved()) return swept_prism(path, e, loc);
  PolygonMesh m;
  const auto n = static_cast<std::uint32_t>(path.size());
  const double k0 = e.factor(e.f0), k1 = e.factor(e.f1);
  const bool apex = k1 == 0;
  for (const glm::dvec2& p : path) m.points.emplace_back(k0 * p, e.f0 * e.height);
  if (!apex) {
    for (const glm::dvec2& p : path) m.points.emplace_back(k1 * p, e.f1 * e.height);
  } else {
    m.points.emplace_back(0.0, 0.0, e.f1 * e.height);  // the apex all sides meet at
  }
  std::vector<std::uint32_t> bottom;
  for (std::uint32_t i = n; i-- > 0;) bottom.push_back(i);
  m.faces.push_back(bottom);
  if (!apex) {
    std::vector<std::uint32_t> top;
    for (std::uint32_t i = 0; i < n; ++i) top.push_back(n + i);
    m.faces.push_back(top);
  }
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t k = (i + 1) % n;
    if (!apex) {
      m.faces.push_back({i, k, n + k, n + i});
    } else {
      m.faces.push_back({i, k, n});
    }
  }
  MeshBuild built = build_closed_mesh(m);
  if (!built.mesh) throw SceneError(loc, fmt::format("this extruded shape is not a solid: {}", built.defect.reason));
  Primitive p;
  p.kind = PrimitiveKind::Mesh;
  p.mesh = std::make_shared<const TriangleMesh>(std::move(*built.mesh));
  p.to_world = base(e);
  p.loc = loc;
  return p;
}

}  // namespace

void check_swept_points(std::size_t path_points, int slices, const Loc& loc, std::string_view what) {
  const double points = static_cast<double>(path_points) * (slices + 3);
  if (points > static_cast<double>(kMaxTessellatedPoints))
    throw SceneError(loc, fmt::format("{} would have {:g} points ({} slices of {}), more than the {} capsim tessellates",
                                      what, points, slices, path_points, kMaxTessellatedPoints));
}

void extend_beyond_caps(Extrusion& e) {
  if (e.curved()) {
    e.collars = true;
    return;
  }
  // Half the height each way, less where the shape would shrink below half
  // its size at the cap (k(f) >= k(cap) / 2); at scale 0 the top is a point
  // and is not passed.
  const double s = e.scale;
  e.f0 = s > 1 ? -std::min(0.5, 0.5 / (s - 1)) : -0.5;
  e.f1 = s < 1 ? 1 + std::min(0.5, s / (2 * (1 - s))) : 1.5;
}

Primitive extrusion_slab(const std::vector<Primitive>& leaves, const Extrusion& e, const Loc& loc) {
  Aabb b;
  const glm::dmat4 to_extrusion = glm::inverse(base(e));
  for (const Primitive& leaf : leaves) {
    const Aabb o = object_bounds(leaf);
    for (int k = 0; k < 8; ++k) {
      const glm::dvec4 c((k & 1) ? o.hi.x : o.lo.x, (k & 2) ? o.hi.y : o.lo.y, (k & 4) ? o.hi.z : o.lo.z, 1.0);
      b.extend(glm::dvec3(to_extrusion * leaf.to_world * c));
    }
  }
  const glm::dvec3 pad = 0.01 * b.extent();
  glm::dmat4 m(1.0);
  m[0][0] = b.hi.x - b.lo.x + 2 * pad.x;
  m[1][1] = b.hi.y - b.lo.y + 2 * pad.y;
  m[2][2] = e.height;
  m[3] = glm::dvec4(b.lo.x - pad.x, b.lo.y - pad.y, 0, 1);
  Primitive p;
  p.kind = PrimitiveKind::Box;
  p.to_world = base(e) * m;
  p.loc = loc;
  return p;
}

Extrusion read_linear_extrude(const Call& call) {
  Args args(call, {"height", "center", "convexity", "twist", "slices"}, {"scale", "segments", "v", "file", "layer",
                                                                          "origin"});
  for (std::string_view unused : {"file", "layer", "origin", "v"})
    if (args.has(unused))
      args.fail_value(unused, fmt::format("linear_extrude's '{}' is not supported; extrude 2-D children", unused));
  Extrusion e;
  e.height = args.number("height", 100);
  if (!(e.height > 0)) args.fail_value("height", fmt::format("{} must be positive, got {}", args.what("height"), e.height));
  static_assert(kMaxLength == 1e30, "the message names the range");
  if (!(e.height <= kMaxLength)) args.fail_value("height", "the height must be at most 1e30");
  e.center = args.boolean("center", false);
  args.number("convexity", 1);
  args.number("segments", 0);
  // OpenSCAD takes the whole part of slices, and computes them when that is not positive.
  const double slices = std::trunc(args.number("slices", 0));
  if (slices > kMaxSlices)
    args.fail_value("slices", fmt::format("{} slices are more than the {} capsim tessellates", slices, kMaxSlices));
  e.slices = slices > 0 ? static_cast<int>(slices) : 0;
  e.twist = args.number("twist", 0);
  if (args.has("scale")) {
    const glm::dvec2 sc = number_or_vec2(args, "scale", glm::dvec2(1));
    if (!(sc.x >= 0 && sc.y >= 0)) args.fail_value("scale", "the scale must not be negative");
    e.scale_xy = sc;
    e.scale = sc.x;
  }
  const Resolution res = read_resolution(call);
  e.fn = res.fn;
  e.fa = res.fa;
  e.fs = res.fs;
  if (!e.curved()) e.slices = 0;
  return e;
}

glm::dmat3 read_transform_2d(const Call& call) {
  const glm::dmat4 m = read_transform(call);
  // OpenSCAD applies a transform to 2-D shapes by its plane part: x and y
  // from x, y and the translation.
  glm::dmat3 p(1.0);
  p[0] = {m[0][0], m[0][1], 0};
  p[1] = {m[1][0], m[1][1], 0};
  p[2] = {m[3][0], m[3][1], 1};
  const double det = p[0][0] * p[1][1] - p[0][1] * p[1][0];
  const double scale = std::max({std::abs(p[0][0]), std::abs(p[0][1]), std::abs(p[1][0]), std::abs(p[1][1])});
  if (!(scale > 0) || !(std::abs(det) / (scale * scale) >= kSingularRelativeDet))
    throw SceneError(call.loc, fmt::format("{} flattens the plane of the 2-D shapes under it (its x-y part is "
                                           "singular)",
                                           call.name));
  return p;
}

double circle_radius(const Call& call) {
  Args args(call, {"r"}, {"d"});
  if (args.has("r") && args.has("d")) throw SceneError(args.name_loc("d"), "circle takes either r or d, not both");
  const std::string_view given = args.has("d") ? "d" : "r";
  const double v = args.number(given, given == "d" ? 2 : 1);
  if (!(v > 0 && v <= kMaxLength))
    args.fail_value(given, fmt::format("{} must be positive and at most 1e30, got {}", args.what(given), v));
  return given == "d" ? v / 2 : v;
}

Primitive extrude_circle(const Call& call, const glm::dmat3& plane, const Extrusion& e) {
  const double r = circle_radius(call);
  if (e.curved()) {
    // No closed form: the circle is OpenSCAD's polygon of it.
    std::vector<glm::dvec2> path;
    for (const glm::dvec2& q : openscad_circle(r, fragments_for(r, read_resolution(call), call.loc)))
      path.push_back(apply(plane, q));
    return prism(path, e, call.loc);
  }
  // The cone's canonical frustum has radius r1 at z = 0 and r2 at z = 1, the
  // larger 1; at height fraction f the circle is scaled by k(f) = 1 + (s - 1) f,
  // so its centre t moves to k(f) t: a shear along z.
  const double k0 = e.factor(e.f0), k1 = e.factor(e.f1), big = std::max(k0, k1);
  const glm::dvec2 t(plane[2]);
  glm::dmat4 m(1.0);
  m[0] = glm::dvec4(glm::dvec2(plane[0]) * r * big, 0, 0);
  m[1] = glm::dvec4(glm::dvec2(plane[1]) * r * big, 0, 0);
  m[2] = glm::dvec4((k1 - k0) * t, e.height * (e.f1 - e.f0), 0);
  m[3] = glm::dvec4(k0 * t, e.height * e.f0, 1);
  Primitive p;
  p.kind = PrimitiveKind::Cone;
  p.cone_r1 = k0 / big;
  p.cone_r2 = k1 / big;
  p.to_world = base(e) * m;
  p.loc = call.loc;
  return p;
}

SquareSpan read_square(const Call& call) {
  Args args(call, {"size", "center"});
  const glm::dvec2 size = number_or_vec2(args, "size", glm::dvec2(1));
  if (!(size.x > 0 && size.y > 0 && size.x <= kMaxLength && size.y <= kMaxLength))
    args.fail_value("size", fmt::format("square size must be positive (and at most 1e30) in both dimensions, got "
                                        "[{}, {}]",
                                        size.x, size.y));
  return {args.boolean("center", false) ? -size / 2.0 : glm::dvec2(0), size};
}

Primitive extrude_square(const Call& call, const glm::dmat3& plane, const Extrusion& e) {
  const auto [lo, size] = read_square(call);
  if (e.scale != 1 || e.curved()) {
    const glm::dvec2 c[4] = {lo, lo + glm::dvec2(size.x, 0), lo + size, lo + glm::dvec2(0, size.y)};
    std::vector<glm::dvec2> path;
    for (const glm::dvec2& k : c) path.push_back(apply(plane, k));
    return prism(path, e, call.loc);
  }
  // Unscaled, a parallelogram's prism: the unit cube carried there.
  glm::dmat4 m(1.0);
  m[0] = glm::dvec4(glm::dvec2(plane[0]) * size.x, 0, 0);
  m[1] = glm::dvec4(glm::dvec2(plane[1]) * size.y, 0, 0);
  m[2] = glm::dvec4(0, 0, e.height * (e.f1 - e.f0), 0);
  m[3] = glm::dvec4(apply(plane, lo), e.height * e.f0, 1);
  Primitive p;
  p.kind = PrimitiveKind::Box;
  p.to_world = base(e) * m;
  p.loc = call.loc;
  return p;
}

PolygonPaths read_polygon_paths(const Call& call, const glm::dmat3& plane) {
  Args args(call, {"points", "paths", "convexity"});
  args.number("convexity", 1);
  if (!args.has("points")) throw SceneError(call.loc, "polygon needs its points");
  const Value& pts = args.value("points");
  if (pts.kind != Value::Kind::Vector || pts.items.size() < 3) args.fail_type("points", "a vector of at least 3 [x, y] points");
  std::vector<glm::dvec2> points;
  for (std::size_t i = 0; i < pts.items.size(); ++i) {
    const Value& p = pts.items[i];
    if (p.kind != Value::Kind::Vector || p.items.size() != 2 || p.items[0].kind != Value::Kind::Number ||
        p.items[1].kind != Value::Kind::Number || !(std::abs(p.items[0].number) <= kMaxLength) ||
        !(std::abs(p.items[1].number) <= kMaxLength))
      throw SceneError(p.loc, fmt::format("point {} of polygon must be [x, y], two numbers within 1e30, got {}", i,
                                          describe(p)));
    points.push_back(apply(plane, {p.items[0].number, p.items[1].number}));
  }
  PolygonPaths out;
  std::vector<std::vector<glm::dvec2>>& paths = out.paths;
  std::vector<Loc>& path_locs = out.locs;
  if (args.has("paths")) {
    const Value& ps = args.value("paths");
    if (ps.kind != Value::Kind::Vector || ps.items.empty()) args.fail_type("paths", "a vector of paths");
    for (std::size_t k = 0; k < ps.items.size(); ++k) {
      const Value& path = ps.items[k];
      if (path.kind != Value::Kind::Vector || path.items.size() < 3)
        throw SceneError(path.loc, fmt::format("path {} of polygon must list at least 3 point indices, got {}", k,
                                               describe(path)));
      std::vector<glm::dvec2> q;
      for (const Value& i : path.items) {
        if (i.kind != Value::Kind::Number || i.number != std::floor(i.number) || i.number < 0 ||
            i.number >= static_cast<double>(points.size()))
          throw SceneError(i.loc, fmt::format("path {} names point {}, but the points are numbered 0 to {}", k,
                                              i.kind == Value::Kind::Number ? fmt::format("{}", i.number) : describe(i),
                                              points.size() - 1));
        q.push_back(points[static_cast<std::size_t>(i.number)]);
      }
      paths.push_back(std::move(q));
      path_locs.push_back(path.loc);
    }
  } else {
    paths.push_back(points);
    path_locs.push_back(pts.loc);
  }
  return out;
}

ExtrudedPaths extrude_polygon(const Call& call, const glm::dmat3& plane, const Extrusion& e) {
  const PolygonPaths p = read_polygon_paths(call, plane);
  return extrude_paths(p.paths, p.locs, e, call.loc, "polygon");
}

void check_simple_paths(const std::vector<std::vector<glm::dvec2>>& paths, const std::vector<Loc>& path_locs,
                        std::string_view what) {
  for (std::size_t k = 0; k < paths.size(); ++k) {
    if (area2(paths[k]) == 0 || paths_cross(paths[k], paths[k], true))
      throw SceneError(path_locs[k], fmt::format("{} {} crosses itself or encloses no area: capsim extrudes "
                                                 "simple outlines only",
                                                 what,
                                                 paths.size() == 1 ? std::string("outline") : fmt::format("path {}", k)));
    for (std::size_t j = 0; j < k; ++j)
      if (paths_cross(paths[j], paths[k], false))
        throw SceneError(path_locs[k], fmt::format("{} paths {} and {} cross: capsim extrudes paths that lie "
                                                   "apart or one inside another",
                                                   what, j, k));
  }
}

ExtrudedPaths extrude_paths(const std::vector<std::vector<glm::dvec2>>& paths, const std::vector<Loc>& path_locs,
                            const Extrusion& e, const Loc& loc, std::string_view what) {
  check_simple_paths(paths, path_locs, what);
  // Each path's parent: the smallest path that holds it (paths do not cross,
  // so one corner tells).
  ExtrudedPaths out;
  for (std::size_t k = 0; k < paths.size(); ++k) {
    int parent = -1;
    for (std::size_t j = 0; j < paths.size(); ++j)
      if (j != k && inside(paths[j], paths[k][0]) &&
          (parent < 0 || std::abs(area2(paths[j])) < std::abs(area2(paths[static_cast<std::size_t>(parent)]))))
        parent = static_cast<int>(j);
    out.parent.push_back(parent);
    out.prisms.push_back(prism(paths[k], e, loc));
  }
  return out;
}

bool paths_meet(const std::vector<std::vector<glm::dvec2>>& paths) {
  for (std::size_t k = 0; k < paths.size(); ++k) {
    if (paths_cross(paths[k], paths[k], true)) return true;
    for (std::size_t j = 0; j < k; ++j)
      if (paths_cross(paths[j], paths[k], false)) return true;
  }
  return false;
}

ExtrudedPaths extrude_nested_paths(const std::vector<std::vector<glm::dvec2>>& paths, const std::vector<int>& parent,
                                   const Extrusion& e, const Loc& loc) {
  ExtrudedPaths out;
  out.parent = parent;
  for (const auto& path : paths) out.prisms.push_back(prism(path, e, loc));
  return out;
}

constexpr std::size_t kMaxTextVertices = 20000;

std::vector<std::vector<glm::dvec2>> read_text_paths(const Call& call, const glm::dmat3& plane) {
  Args args(call, {"text", "size", "font"},
            {"halign", "valign", "spacing", "direction", "language", "script"});
  TextSpec spec;
  auto text = [&](std::string_view name, std::string& out) {
    if (!args.has(name)) return;
    const Value& v = args.value(name);
    if (v.kind != Value::Kind::String) args.fail_type(name, "a string");
    out = std::string(v.string);
  };
  text("text", spec.text);
  text("font", spec.font);
  text("halign", spec.halign);
  text("valign", spec.valign);
  text("direction", spec.direction);
  text("language", spec.language);
  text("script", spec.script);
  spec.size = args.number("size", 10);
  if (!(spec.size > 0 && spec.size <= kMaxLength))
    args.fail_value("size", fmt::format("size must be positive and at most 1e30, got {}", spec.size));
  spec.spacing = args.number("spacing", 1);
  spec.fn = args.number("$fn", 0);
  spec.fa = args.number("$fa", 12);
  spec.fs = args.number("$fs", 2);
  std::vector<TextContour> contours;
  try {
    contours = text_contours(spec);
  } catch (const TextError& error) {
    throw SceneError(call.loc, error.what());
  }
  // OpenSCAD closes each contour by repeating its first point, and a curve
  // can end where a line began: drop repeated points, which are no edges.
  std::vector<std::vector<glm::dvec2>> paths;
  for (const TextContour& c : contours) {
    std::vector<glm::dvec2> path;
    for (const glm::dvec2& v : c) {
      const glm::dvec2 q = apply(plane, v);
      // A huge size or spacing carries glyphs past the range every shape keeps to.
      if (!(std::abs(q.x) <= kMaxLength && std::abs(q.y) <= kMaxLength))
        throw SceneError(call.loc, "text() reaches beyond 1e30 from the origin (its size or spacing is too large)");
      if (path.empty() || q != path.back()) path.push_back(q);
    }
    while (path.size() > 1 && path.back() == path.front()) path.pop_back();
    if (path.size() >= 3) paths.push_back(std::move(path));
  }
  if (paths.empty()) throw SceneError(call.loc, "text() draws nothing here (an empty text, or only spaces)");
  // Checking that no outline crosses another takes time quadratic in the
  // vertices; beyond this a text is refused rather than left running.
  std::size_t vertices = 0;
  for (const auto& path : paths) vertices += path.size();
  if (vertices > kMaxTextVertices)
    throw SceneError(call.loc, fmt::format("text() has {} outline vertices, more than the {} capsim checks: use "
                                           "a shorter text or a smaller $fn",
                                           vertices, kMaxTextVertices));
  return paths;
}

ExtrudedPaths extrude_text(const Call& call, const glm::dmat3& plane, const Extrusion& e) {
  const std::vector<std::vector<glm::dvec2>> paths = read_text_paths(call, plane);
  return extrude_paths(paths, std::vector<Loc>(paths.size(), call.loc), e, call.loc, "text");
}

}  // namespace capsim::scene_file

namespace capsim::scene_file {

int extrusion_slices(const std::vector<glm::dvec2>& points, const Extrusion& e) {
  double reach_sqr = 0, move_sqr = 0;
  for (const glm::dvec2& p : points) {
    reach_sqr = std::max(reach_sqr, glm::dot(p, p));
    const glm::dvec2 moved = p - p * e.scale_xy;
    move_sqr = std::max(move_sqr, glm::dot(moved, moved));
  }
  const Sweep sweep{e.height, e.twist, e.scale_xy, 1, false};
  return std::min(openscad_slices(reach_sqr, move_sqr, sweep, e.fn, e.fa, e.fs), kMaxSlices);
}

}  // namespace capsim::scene_file
