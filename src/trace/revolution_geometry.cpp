// Line crossings of a turned profile (revolution_geometry.h).

#include "capsim/trace/revolution_geometry.h"

#include "capsim/trace/polynomial_roots.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace capsim {

namespace {

// The line in the profile plane: rho(s)^2 = a s^2 + 2 b s + c, z(s) = oz + dz s.
struct ProfileLine {
  double a, b, c;
  double oz, dz;
  double rho2(double s) const { return (a * s + 2 * b) * s + c; }
};

// An edge's surface: points whose (rho, z) lies on ab, at f in [0, 1) along
// it. The half-open edge claims a shared corner once, for the edge leaving it;
// but an edge that ends on the axis is closed there, as the edge that leaves
// the axis point next either runs along the axis (and is no surface) or
// claims the point too (two cones meeting at an apex: two crossings at one t,
// which cancel).
void edge_crossings(const RevolvedEdge& e, int surface, const ProfileLine& l, std::vector<LineCrossing>& out) {
  const bool closed_end = e.b.x == 0;
  auto on_edge = [&](double f) { return f >= 0 && (f < 1 || (closed_end && f == 1)); };
  const double ez = e.b.y - e.a.y;
  if (ez == 0) {
    // An annulus in the plane z = a.y.
    if (l.dz == 0) return;
    const double s = (e.a.y - l.oz) / l.dz;
    const double f = (std::sqrt(std::max(l.rho2(s), 0.0)) - e.a.x) / (e.b.x - e.a.x);
    if (on_edge(f)) out.push_back({s, surface, false});
    return;
  }
  // rho = w(s) = w0 + w1 s along the cone through the edge: rho^2 - w^2 = 0.
  const double k = (e.b.x - e.a.x) / ez;
  const double w0 = e.a.x + k * (l.oz - e.a.y), w1 = k * l.dz;
  Polynomial q;
  q.degree = 2;
  q.c = {l.c - w0 * w0, 2 * (l.b - w0 * w1), l.a - w1 * w1, 0, 0};
  std::array<double, 4> roots{};
  const int n = real_roots(q, roots);
  for (int i = 0; i < n; ++i) {
    const double f = (l.oz + l.dz * roots[i] - e.a.y) / ez;
    if (on_edge(f)) out.push_back({roots[i], surface, false});
  }
}

// An ellipse's surface: (u - c)^T A (u - c) = 1 with u = (rho, z) is
// P(s) + rho(s) L(s) = 0, P quadratic and L linear in s. Squared, P^2 -
// rho^2 L^2 = 0 is a quartic; its roots where P = +rho L belong to the mirror
// image at -rho and are dropped (when L vanishes, P = 0 alone is solved).
// Each root is then polished by Newton steps on
// the unsquared P + rho L, which squaring had made less precise.
void ellipse_crossings(const ProfileEllipse& e, int surface, const ProfileLine& l, std::vector<LineCrossing>& out) {
  const double a11 = e.form[0][0], a12 = e.form[1][0], a22 = e.form[1][1];
  const double cx = e.center.x, z0 = l.oz - e.center.y, dz = l.dz;
  // P = a11 rho^2 + a22 zeta^2 - 2 a12 cx zeta + a11 cx^2 - 1, zeta = z0 + dz s.
  const std::array<double, 3> p = {a11 * l.c + a22 * z0 * z0 - 2 * a12 * cx * z0 + a11 * cx * cx - 1,
                                    a11 * 2 * l.b + 2 * a22 * z0 * dz - 2 * a12 * cx * dz,
                                    a11 * l.a + a22 * dz * dz};
  // L = 2 a12 zeta - 2 a11 cx.
  const std::array<double, 2> lin = {2 * a12 * z0 - 2 * a11 * cx, 2 * a12 * dz};
  const std::array<double, 3> r2 = {l.c, 2 * l.b, l.a};
  const std::array<double, 3> l2 = {lin[0] * lin[0], 2 * lin[0] * lin[1], lin[1] * lin[1]};
  Polynomial q;
  if (lin[0] == 0 && lin[1] == 0) {
    // An ellipse centred on the axis, its axes along r and z (a spheroid):
    // L vanishes and the surface is the quadric P = 0, whose roots the
    // square P^2 would only touch.
    q.degree = 2;
    q.c = {p[0], p[1], p[2], 0, 0};
  } else {
    q.degree = 4;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) q.c[i + j] += p[i] * p[j] - r2[i] * l2[j];
  }
  std::array<double, 4> roots{};
  const int n = real_roots(q, roots);
  auto P = [&](double s) { return (p[2] * s + p[1]) * s + p[0]; };
  auto L = [&](double s) { return lin[1] * s + lin[0]; };
  for (int i = 0; i < n; ++i) {
    double s = roots[i];
    double rho = std::sqrt(std::max(l.rho2(s), 0.0));
    if (std::abs(P(s) + rho * L(s)) > std::abs(P(s) - rho * L(s))) continue;
    for (int step = 0; step < 2 && rho > 0; ++step) {
      const double f = P(s) + rho * L(s);
      const double df = 2 * p[2] * s + p[1] + (l.a * s + l.b) / rho * L(s) + rho * lin[1];
      if (f == 0 || df == 0) break;
      const double next = s - f / df;
      const double next_rho = std::sqrt(std::max(l.rho2(next), 0.0));
      if (!(std::abs(P(next) + next_rho * L(next)) < std::abs(f))) break;
      s = next;
      rho = next_rho;
    }
    out.push_back({s, surface, false});
  }
}

// The wedge's inner normals in the x-y plane: the half plane at angle 0 and at
// the sweep, exact at the quarter turns.
glm::dvec2 cap_inner_normal(const Revolution& rev, int which) {
  if (which == 0) return {0, 1};
  const double deg = rev.sweep_deg;
  if (deg == 90) return {1, 0};
  if (deg == 180) return {0, 1};
  if (deg == 270) return {-1, 0};
  const double rad = deg * std::numbers::pi / 180;
  return {std::sin(rad), -std::cos(rad)};
}

struct Span {
  double lo, hi;
  int lo_surface, hi_surface;
};

// The part of the line on the inner side of one cap's plane.
bool half_space(const Revolution& rev, int which, const glm::dvec3& o, const glm::dvec3& d, Span& out) {
  const glm::dvec2 n = cap_inner_normal(rev, which);
  const double no = n.x * o.x + n.y * o.y, nd = n.x * d.x + n.y * d.y;
  const int cap = rev.cap_surface(which);
  if (nd == 0) {
    out = {-kInfinity, kInfinity, cap, cap};
    return no >= 0;
  }
  const double t = -no / nd;
  out = nd > 0 ? Span{t, kInfinity, cap, cap} : Span{-kInfinity, t, cap, cap};
  return true;
}

// The wedge along the line, as sorted disjoint spans: the two half spaces'
// intersection for a sweep up to a half turn, their union beyond.
int wedge_spans(const Revolution& rev, const glm::dvec3& o, const glm::dvec3& d, std::array<Span, 2>& spans) {
  Span h0, h1;
  const bool in0 = half_space(rev, 0, o, d, h0), in1 = half_space(rev, 1, o, d, h1);
  if (rev.sweep_deg <= 180) {
    if (!in0 || !in1) return 0;
    Span s = h0;
    if (h1.lo > s.lo) s.lo = h1.lo, s.lo_surface = h1.lo_surface;
    if (h1.hi < s.hi) s.hi = h1.hi, s.hi_surface = h1.hi_surface;
    if (!(s.lo < s.hi)) return 0;
    spans[0] = s;
    return 1;
  }
  int n = 0;
  if (in0) spans[n++] = h0;
  if (in1) spans[n++] = h1;
  if (n == 2) {
    if (spans[1].lo < spans[0].lo) std::swap(spans[0], spans[1]);
    if (spans[1].lo <= spans[0].hi) {
      if (spans[1].hi > spans[0].hi) spans[0].hi = spans[1].hi, spans[0].hi_surface = spans[1].hi_surface;
      n = 1;
    }
  }
  return n;
}

}  // namespace

void revolution_line_crossings(const Revolution& rev, const glm::dvec3& o_in, const glm::dvec3& d_in,
                               std::vector<LineCrossing>& out, std::vector<LineCrossing>& work, OpCounts& ops) {
  out.clear();
  work.clear();
  // Solved along the unit direction from the line's point nearest the box's
  // centre: the quartic keeps its digits when the eye is far away. Then
  // t = (t_mid + s) / |d|.
  const double len = glm::length(d_in);
  const glm::dvec3 d = d_in / len;
  const double t_mid = glm::dot(rev.bounds.center() - o_in, d);
  const glm::dvec3 o = o_in + t_mid * d;
  const ProfileLine line{d.x * d.x + d.y * d.y, o.x * d.x + o.y * d.y, o.x * o.x + o.y * o.y, o.z, d.z};
  for (std::size_t i = 0; i < rev.edges.size(); ++i) {
    ++ops.revolution_edge_tests;
    edge_crossings(rev.edges[i], static_cast<int>(i), line, work);
  }
  for (std::size_t k = 0; k < rev.profile.ellipses.size(); ++k) {
    ++ops.quartic_tests;
    ellipse_crossings(rev.profile.ellipses[k], static_cast<int>(rev.edges.size() + k), line, work);
  }
  std::sort(work.begin(), work.end(), [](const LineCrossing& a, const LineCrossing& b) {
    return a.t != b.t ? a.t < b.t : a.surface < b.surface;
  });
  // A line through a corner of the profile exactly can leave one crossing
  // unmatched; the solid then ends at the last one.
  if (work.size() % 2) work.pop_back();
  auto emit = [&](double s, int surface, bool enter) { out.push_back({(t_mid + s) / len, surface, enter}); };
  if (rev.full()) {
    for (std::size_t i = 0; i < work.size(); ++i) emit(work[i].t, work[i].surface, i % 2 == 0);
    return;
  }
  std::array<Span, 2> wedge{};
  const int n_wedge = wedge_spans(rev, o, d, wedge);
  // The turned profile's spans, each cut by each of the wedge's.
  for (std::size_t i = 0; i + 1 < work.size(); i += 2) {
    for (int w = 0; w < n_wedge; ++w) {
      const Span& ws = wedge[w];
      Span s{work[i].t, work[i + 1].t, work[i].surface, work[i + 1].surface};
      if (ws.lo > s.lo) s.lo = ws.lo, s.lo_surface = ws.lo_surface;
      if (ws.hi < s.hi) s.hi = ws.hi, s.hi_surface = ws.hi_surface;
      if (!(s.lo < s.hi)) continue;
      emit(s.lo, s.lo_surface, true);
      emit(s.hi, s.hi_surface, false);
    }
  }
}

glm::dvec3 revolution_normal(const Revolution& rev, const glm::dvec3& q, int s) {
  const int edges = static_cast<int>(rev.edges.size());
  const int ellipses = static_cast<int>(rev.profile.ellipses.size());
  if (s >= edges + ellipses) {
    const glm::dvec2 n = cap_inner_normal(rev, s - edges - ellipses);
    return {-n.x, -n.y, 0};
  }
  const double rho = std::hypot(q.x, q.y);
  glm::dvec2 n2;
  if (s < edges) {
    n2 = rev.edges[static_cast<std::size_t>(s)].outward;
  } else {
    const ProfileEllipse& e = rev.profile.ellipses[static_cast<std::size_t>(s - edges)];
    n2 = e.form * (glm::dvec2(rho, q.z) - e.center);
  }
  // On the axis the radial part has no direction; the axis is the limit.
  if (rho == 0) return {0, 0, n2.y != 0 ? n2.y : 1.0};
  return {n2.x * q.x / rho, n2.x * q.y / rho, n2.y};
}

}  // namespace capsim
