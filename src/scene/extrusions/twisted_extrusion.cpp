// OpenSCAD's tessellation of twisted and unevenly scaled extrusions.

#include "scene/extrusions/twisted_extrusion.h"

#include "scene/extrusions/openscad_tessellation.h"
#include "scene/reading/scene_expression.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace capsim::scene_file {

namespace {

// OpenSCAD's GRID_FINE.
constexpr double kGridFine = 0.00000095367431640625;

double deg2rad(double d) { return d * std::numbers::pi / 180.0; }

int helix_slices(double r_sqr, double height, double twist, double fn, double fs, double fa) {
  twist = std::fabs(twist);
  const int min_slices = std::max(static_cast<int>(std::ceil(twist / 120.0)), 1);
  if (std::sqrt(r_sqr) < kGridFine || std::isinf(fn) || std::isnan(fn)) return min_slices;
  if (fn > 0.0) return std::max(static_cast<int>(std::ceil(twist / 360.0 * fn)), min_slices);
  const double t = deg2rad(twist), c = height / t;
  const double arc = t * std::sqrt(r_sqr + c * c);
  const int fa_slices = static_cast<int>(std::ceil(twist / fa));
  const int fs_slices = static_cast<int>(std::ceil(arc / fs));
  return std::max(std::min(fa_slices, fs_slices), min_slices);
}

double archimedes_length(double a, double theta) {
  return 0.5 * a * (theta * std::sqrt(1 + theta * theta) + std::asinh(theta));
}

int conical_helix_slices(double r_sqr, double height, double twist, double scale, double fn, double fs, double fa) {
  twist = std::fabs(twist);
  const double r = std::sqrt(r_sqr);
  const int min_slices = std::max(static_cast<int>(std::ceil(twist / 120.0)), 1);
  if (r < kGridFine || std::isinf(fn) || std::isnan(fn)) return min_slices;
  if (fn > 0.0) return std::max(static_cast<int>(std::ceil(twist * fn / 360)), min_slices);
  const double rads = deg2rad(twist);
  const double angle_end = scale > 1 ? rads * scale / (scale - 1) : rads / (1 - scale);
  const double angle_start = angle_end - rads;
  const double a = r / angle_end;
  const double spiral = archimedes_length(a, angle_end) - archimedes_length(a, angle_start);
  const double total = std::sqrt(spiral * spiral + height * height);
  const int fs_slices = static_cast<int>(std::ceil(total / fs));
  const int fa_slices = static_cast<int>(std::ceil(twist / fa));
  return std::max(std::min(fa_slices, fs_slices), min_slices);
}

int diagonal_slices(double delta_sqr, double height, double fn, double fs) {
  if (std::sqrt(delta_sqr) < kGridFine || std::isinf(fn) || std::isnan(fn)) return 1;
  if (fn > 0.0) return std::max(static_cast<int>(fn), 1);
  return std::max(static_cast<int>(std::ceil(std::sqrt(delta_sqr + height * height) / fs)), 1);
}

// OpenSCAD's sgn_vdiff: which diagonal is shorter, equal within 10 ppm.
int shorter(const glm::dvec2& v1, const glm::dvec2& v2) {
  const double l1 = glm::length(v1), l2 = glm::length(v2);
  return 2 * std::fabs(l1 - l2) * 1e5 > l1 + l2 ? (l1 < l2 ? -1 : 1) : 0;
}

// The outline at slice j: scaled after being turned by -twist j / slices.
std::vector<glm::dvec2> ring(const std::vector<glm::dvec2>& outline, const Sweep& s, int j) {
  const double rot = s.twist * j / s.slices;
  const glm::dvec2 k(1 - (1 - s.scale.x) * j / s.slices, 1 - (1 - s.scale.y) * j / s.slices);
  const double c = cos_degrees(-rot), sn = sin_degrees(-rot);
  std::vector<glm::dvec2> out;
  out.reserve(outline.size());
  for (const glm::dvec2& v : outline) out.emplace_back(k.x * (c * v.x - sn * v.y), k.y * (sn * v.x + c * v.y));
  return out;
}

}  // namespace

int openscad_slices(double reach_sqr, double move_sqr, const Sweep& s, double fn, double fa, double fs) {
  if (s.twist != 0) {
    if ((s.scale.x == 1.0 && s.scale.y == 1.0) || s.scale.x != s.scale.y)
      return helix_slices(reach_sqr, s.height, s.twist, fn, fs, fa);
    return conical_helix_slices(reach_sqr, s.height, s.twist, s.scale.x, fn, fs, fa);
  }
  if (s.scale.x != s.scale.y) return diagonal_slices(move_sqr, s.height, fn, fs);
  return 1;
}

PolygonMesh sweep_mesh(std::vector<glm::dvec2> outline, const Sweep& s) {
  double area2 = 0;
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const glm::dvec2 &a = outline[i], &b = outline[(i + 1) % outline.size()];
    area2 += a.x * b.y - a.y * b.x;
  }
  if (area2 < 0) std::reverse(outline.begin(), outline.end());
  const std::size_t n = outline.size();
  PolySetBuilder p;
  const bool top_cap = s.scale.x > 0 && s.scale.y > 0;
  const double step = s.height / s.slices;
  const double bottom = s.collars ? -step : 0, top = s.collars && top_cap ? s.height + step : s.height;
  // The bottom, turned to face down, then the top.
  p.append_poly();
  for (std::size_t i = n; i-- > 0;) p.append_vertex(outline[i].x, outline[i].y, bottom);
  std::vector<glm::dvec2> prev = ring(outline, s, 0);
  if (s.collars) {
    for (std::size_t i = 0; i < n; ++i) {
      const glm::dvec2 &a = prev[i], &b = prev[(i + 1) % n];
      p.append_poly();
      p.append_vertex(a.x, a.y, bottom);
      p.append_vertex(b.x, b.y, bottom);
      p.append_vertex(b.x, b.y, 0);
      p.append_vertex(a.x, a.y, 0);
    }
  }
  for (int j = 0; j < s.slices; ++j) {
    const std::vector<glm::dvec2> next = ring(outline, s, j + 1);
    const double h1 = s.height * j / s.slices, h2 = s.height * (j + 1) / s.slices;
    const double rot1 = s.twist * j / s.slices, rot2 = s.twist * (j + 1) / s.slices;
    const glm::dvec2 k2(1 - (1 - s.scale.x) * (j + 1) / s.slices, 1 - (1 - s.scale.y) * (j + 1) / s.slices);
    const bool any_zero = k2.x == 0 || k2.y == 0, any_non_zero = k2.x != 0 || k2.y != 0;
    // Equal diagonals: OpenSCAD's choice for a positive outline.
    const bool flip = !(rot2 <= rot1);
    for (std::size_t i = 1; i <= n; ++i) {
      const glm::dvec2 &prev1 = prev[i - 1], &prev2 = next[i - 1], &curr1 = prev[i % n], &curr2 = next[i % n];
      const int diff = shorter(prev1 - curr2, curr1 - prev2);
      const bool split_first = diff == -1 || (diff == 0 && !flip);
      const bool second = !any_zero || (any_non_zero && prev2 != curr2);
      if (split_first != any_zero) {
        p.append_poly();
        p.insert_vertex(prev1.x, prev1.y, h1);
        p.insert_vertex(curr2.x, curr2.y, h2);
        p.insert_vertex(curr1.x, curr1.y, h1);
        if (second) {
          p.append_poly();
          p.insert_vertex(curr2.x, curr2.y, h2);
          p.insert_vertex(prev1.x, prev1.y, h1);
          p.insert_vertex(prev2.x, prev2.y, h2);
        }
      } else {
        p.append_poly();
        p.insert_vertex(prev1.x, prev1.y, h1);
        p.insert_vertex(prev2.x, prev2.y, h2);
        p.insert_vertex(curr1.x, curr1.y, h1);
        if (second) {
          p.append_poly();
          p.insert_vertex(prev2.x, prev2.y, h2);
          p.insert_vertex(curr2.x, curr2.y, h2);
          p.insert_vertex(curr1.x, curr1.y, h1);
        }
      }
    }
    prev = next;
  }
  if (top_cap) {
    if (s.collars) {
      for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec2 &a = prev[i], &b = prev[(i + 1) % n];
        p.append_poly();
        p.append_vertex(a.x, a.y, s.height);
        p.append_vertex(b.x, b.y, s.height);
        p.append_vertex(b.x, b.y, top);
        p.append_vertex(a.x, a.y, top);
      }
    }
    p.append_poly();
    for (const glm::dvec2& v : prev) p.append_vertex(v.x, v.y, top);
  }
  return p.take();
}

}  // namespace capsim::scene_file
