// rotate_extrude of circles, squares, polygons and text as exact revolved leaves.

#include "scene/extrusions/scene_revolve.h"

#include "scene/reading/scene_args.h"
#include "scene/extrusions/scene_extrusion.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <span>

namespace capsim::scene_file {

namespace {

glm::dvec2 apply(const glm::dmat3& m, const glm::dvec2& p) { return glm::dvec2(m * glm::dvec3(p, 1.0)); }

Primitive revolved(RevolvedProfile profile, const Revolve& r, const Loc& loc) {
  Primitive p;
  p.kind = PrimitiveKind::Revolution;
  p.revolution = std::make_shared<const Revolution>(make_revolution(std::move(profile), std::abs(r.angle)));
  p.loc = loc;
  return p;
}

// A circle under `plane`: the ellipse c + M v r, |v| <= 1, whose form is
// M^-T M^-1 / r^2.
Primitive revolve_circle(const Call& call, const glm::dmat3& plane, const Revolve& r) {
  const double radius = circle_radius(call);
  const glm::dmat2 m_inv = glm::inverse(glm::dmat2(glm::dvec2(plane[0]), glm::dvec2(plane[1])));
  RevolvedProfile profile;
  profile.ellipses.push_back({glm::dvec2(plane[2]), glm::transpose(m_inv) * m_inv / (radius * radius)});
  return revolved(std::move(profile), r, call.loc);
}

Primitive revolve_square(const Call& call, const glm::dmat3& plane, const Revolve& r) {
  const auto [lo, size] = read_square(call);
  RevolvedProfile profile;
  profile.paths.push_back({apply(plane, lo), apply(plane, lo + glm::dvec2(size.x, 0)), apply(plane, lo + size),
                           apply(plane, lo + glm::dvec2(0, size.y))});
  return revolved(std::move(profile), r, call.loc);
}

// The x range the 2-D result of the tree can reach.
glm::dvec2 reach(const CsgNode& node, std::span<const Primitive> all) {
  if (node.is_leaf) return profile_x_range(all[static_cast<std::size_t>(node.primitive)].revolution->profile);
  glm::dvec2 range(kInfinity, -kInfinity);
  for (std::size_t i = 0; i < node.children.size(); ++i) {
    const glm::dvec2 c = reach(node.children[i], all);
    if (node.op == CsgOp::Union || i == 0) {
      range = {std::min(range.x, c.x), std::max(range.y, c.y)};
    } else if (node.op == CsgOp::Intersection) {
      range = {std::max(range.x, c.x), std::min(range.y, c.y)};
    }
  }
  return range;
}

void for_each_leaf(const CsgNode& node, const auto& f) {
  if (node.is_leaf) {
    f(static_cast<std::size_t>(node.primitive));
    return;
  }
  for (const CsgNode& child : node.children) for_each_leaf(child, f);
}

// A turn about z by `deg` degrees, exact at the quarter turns.
glm::dmat4 turn(double deg) {
  deg = std::fmod(deg + 360, 360);
  const double rad = deg * std::numbers::pi / 180;
  double c = std::cos(rad), s = std::sin(rad);
  if (deg == 0) c = 1, s = 0;
  if (deg == 90) c = 0, s = 1;
  if (deg == 180) c = -1, s = 0;
  if (deg == 270) c = 0, s = -1;
  glm::dmat4 m(1.0);
  m[0] = {c, s, 0, 0};
  m[1] = {-s, c, 0, 0};
  return m;
}

}  // namespace

Revolve read_rotate_extrude(const Call& call) {
  Args args(call, {}, {"angle", "convexity", "file", "layer", "origin", "scale"});
  for (std::string_view unused : {"file", "layer", "origin", "scale"})
    if (args.has(unused))
      args.fail_value(unused, fmt::format("rotate_extrude's '{}' is not supported; turn 2-D children", unused));
  args.number("convexity", 1);
  args.number("$fn", 0);
  args.number("$fa", 12);
  args.number("$fs", 2);
  Revolve r;
  r.angle = args.number("angle", 360);
  if (!std::isfinite(r.angle)) args.fail_value("angle", fmt::format("the angle must be a finite number, got {}", r.angle));
  if (r.angle == 0) args.fail_value("angle", "an angle of 0 turns the shape into no solid");
  if (std::abs(r.angle) >= 360) r.angle = 360;
  return r;
}

Primitive revolve_shape(const Call& call, const glm::dmat3& plane, const Revolve& r) {
  if (call.name == "circle") return revolve_circle(call, plane, r);
  if (call.name == "square") return revolve_square(call, plane, r);
  if (call.name == "polygon") {
    const PolygonPaths p = read_polygon_paths(call, plane);
    return revolve_paths(p.paths, p.locs, r, call.loc, "polygon");
  }
  const auto paths = read_text_paths(call, plane);
  return revolve_paths(paths, std::vector<Loc>(paths.size(), call.loc), r, call.loc, "text");
}

Primitive revolve_paths(const std::vector<std::vector<glm::dvec2>>& paths, const std::vector<Loc>& path_locs,
                        const Revolve& r, const Loc& loc, std::string_view what) {
  check_simple_paths(paths, path_locs, what);
  return revolve_region(paths, r, loc);
}

Primitive revolve_region(const std::vector<std::vector<glm::dvec2>>& paths, const Revolve& r, const Loc& loc) {
  RevolvedProfile profile;
  profile.paths = paths;
  return revolved(std::move(profile), r, loc);
}

void check_one_side_of_axis(double min_x, double max_x, const Loc& loc) {
  if (min_x < 0 && max_x > 0)
    throw SceneError(loc, fmt::format("all points for rotate_extrude() must have the same X coordinate sign (the "
                                      "2-D shape reaches x = {:g} to {:g})",
                                      min_x, max_x));
}

void finish_revolution(const CsgNode& tree, LargeVector<Primitive>& all, const Revolve& r, const Loc& loc) {
  const glm::dvec2 range = reach(tree, all);
  check_one_side_of_axis(range.x, range.y, loc);
  const bool mirror = range.x < 0;
  // The wedge from `start` through |angle|: counter-clockwise from +x, or
  // from -x for a mirrored shape; a negative angle ends where it would start.
  const double start = (mirror ? 180.0 : 0.0) + std::min(r.angle, 0.0);
  for_each_leaf(tree, [&](std::size_t i) {
    Primitive& p = all[i];
    if (mirror) {
      p.revolution = std::make_shared<const Revolution>(
          make_revolution(mirrored(p.revolution->profile), p.revolution->sweep_deg));
    }
    if (start != 0 && r.angle != 360) p.to_world = p.to_world * turn(start);
  });
}

}  // namespace capsim::scene_file
