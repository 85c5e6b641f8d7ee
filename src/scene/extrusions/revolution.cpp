// The profile of a revolution made ready to trace: edges clipped to the
// turned half plane and oriented, and the solid's box.

#include "capsim/scene/revolution.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace capsim {

namespace {

double signed_area2(const std::vector<glm::dvec2>& p) {
  double a = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const glm::dvec2 &u = p[i], &v = p[(i + 1) % p.size()];
    a += u.x * v.y - u.y * v.x;
  }
  return a;
}

bool holds(const std::vector<glm::dvec2>& poly, const glm::dvec2& pt) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const glm::dvec2 &a = poly[i], &b = poly[j];
    if ((a.y > pt.y) != (b.y > pt.y) && pt.x < (b.x - a.x) * (pt.y - a.y) / (b.y - a.y) + a.x) in = !in;
  }
  return in;
}

// The ellipse's half extents along x and y: sqrt of the diagonal of form^-1.
glm::dvec2 half_extent(const ProfileEllipse& e) {
  const glm::dmat2 inv = glm::inverse(e.form);
  return {std::sqrt(inv[0][0]), std::sqrt(inv[1][1])};
}

// The part of edge ab at x >= 0, if any of it is there (and it has length).
bool clip_to_half_plane(glm::dvec2& a, glm::dvec2& b) {
  if (a.x < 0 && b.x < 0) return false;
  if (a.x < 0 || b.x < 0) {
    const double s = a.x / (a.x - b.x);
    const glm::dvec2 on_axis(0.0, a.y + s * (b.y - a.y));
    (a.x < 0 ? a : b) = on_axis;
  }
  return a != b;
}

// The box of the sector of radius r from angle 0 to sweep (degrees), the
// axis included: its corners and the quarter directions it passes.
void extend_by_sector(Aabb& box, double r, double sweep_deg, double z_lo, double z_hi) {
  auto at = [&](double deg) {
    const double rad = deg * std::numbers::pi / 180;
    // The quarter directions exactly, so that a half turn's box is exact.
    const double c = deg == 90 || deg == 270 ? 0.0 : deg == 180 ? -1.0 : std::cos(rad);
    const double s = deg == 180 || deg == 360 ? 0.0 : deg == 90 ? 1.0 : deg == 270 ? -1.0 : std::sin(rad);
    box.extend(glm::dvec3(r * c, r * s, z_lo));
    box.extend(glm::dvec3(r * c, r * s, z_hi));
  };
  box.extend(glm::dvec3(0, 0, z_lo));
  box.extend(glm::dvec3(0, 0, z_hi));
  at(0);
  for (double q : {90.0, 180.0, 270.0})
    if (q < sweep_deg) at(q);
  at(std::min(sweep_deg, 360.0));
}

}  // namespace

Revolution make_revolution(RevolvedProfile profile, double sweep_deg) {
  Revolution rev;
  rev.sweep_deg = std::min(sweep_deg, 360.0);
  double r_hi = 0, far_x = 0, z_lo = kInfinity, z_hi = -kInfinity;
  const auto& paths = profile.paths;
  for (std::size_t k = 0; k < paths.size(); ++k) {
    // Out of the even-odd region: to the right of a counter-clockwise path's
    // edges, flipped for a clockwise path and for one inside an odd number of
    // others.
    int depth = 0;
    for (std::size_t j = 0; j < paths.size(); ++j)
      if (j != k && holds(paths[j], paths[k][0])) ++depth;
    const double orientation = (signed_area2(paths[k]) > 0 ? 1.0 : -1.0) * (depth % 2 ? -1.0 : 1.0);
    for (std::size_t i = 0; i < paths[k].size(); ++i) {
      glm::dvec2 a = paths[k][i], b = paths[k][(i + 1) % paths[k].size()];
      far_x = std::max({far_x, std::abs(a.x)});
      z_lo = std::min(z_lo, a.y);
      z_hi = std::max(z_hi, a.y);
      const glm::dvec2 dir = b - a;
      if (!clip_to_half_plane(a, b)) continue;
      r_hi = std::max({r_hi, a.x, b.x});
      rev.edges.push_back({a, b, orientation * glm::normalize(glm::dvec2(dir.y, -dir.x))});
    }
  }
  for (const ProfileEllipse& e : profile.ellipses) {
    const glm::dvec2 h = half_extent(e);
    far_x = std::max(far_x, std::abs(e.center.x) + h.x);
    r_hi = std::max(r_hi, e.center.x + h.x);
    z_lo = std::min(z_lo, e.center.y - h.y);
    z_hi = std::max(z_hi, e.center.y + h.y);
  }
  // A profile wholly at x < 0 turns into nothing; its box stays that of the
  // shape's reach, so that the leaf is placed somewhere (it has no crossings).
  const double r = r_hi > 0 ? r_hi : far_x;
  extend_by_sector(rev.bounds, r, rev.sweep_deg, z_lo, z_hi);
  rev.profile = std::move(profile);
  return rev;
}

RevolvedProfile mirrored(const RevolvedProfile& profile) {
  RevolvedProfile m = profile;
  for (auto& path : m.paths)
    for (glm::dvec2& p : path) p.x = -p.x;
  for (ProfileEllipse& e : m.ellipses) {
    e.center.x = -e.center.x;
    e.form[0][1] = -e.form[0][1];
    e.form[1][0] = -e.form[1][0];
  }
  return m;
}

glm::dvec2 profile_x_range(const RevolvedProfile& profile) {
  glm::dvec2 range(kInfinity, -kInfinity);
  for (const auto& path : profile.paths)
    for (const glm::dvec2& p : path) range = {std::min(range.x, p.x), std::max(range.y, p.x)};
  for (const ProfileEllipse& e : profile.ellipses) {
    const double h = half_extent(e).x;
    range = {std::min(range.x, e.center.x - h), std::max(range.y, e.center.x + h)};
  }
  return range;
}

}  // namespace capsim
