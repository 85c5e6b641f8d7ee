// Real roots of low-degree polynomials by isolation between the derivative's
// roots (polynomial_roots.h).

#include "capsim/trace/polynomial_roots.h"

#include <algorithm>
#include <cmath>

namespace capsim {

namespace {

// The one root in [lo, hi] of a polynomial monotonic there, whose values at
// the ends differ in sign: bisection, with a Newton step taken whenever it
// lands inside the bracket. Stops when the bracket holds no double between its
// ends.
double root_in_bracket(const Polynomial& p, const Polynomial& dp, double lo, double hi, double p_lo) {
  double t = 0.5 * (lo + hi);
  for (int step = 0; step < 200; ++step) {
    const double v = p(t);
    if (v == 0) return t;
    if ((v < 0) == (p_lo < 0)) {
      lo = t;
      p_lo = v;
    } else {
      hi = t;
    }
    const double mid = 0.5 * (lo + hi);
    if (!(mid > lo && mid < hi)) break;
    const double slope = dp(t);
    const double newton = slope != 0 ? t - v / slope : mid;
    t = newton > lo && newton < hi ? newton : mid;
  }
  return std::abs(p(lo)) <= std::abs(p(hi)) ? lo : hi;
}

// A bound on the roots' size (Cauchy's): 1 + max |c[i] / c[degree]|.
double root_bound(const Polynomial& p) {
  double m = 0;
  for (int i = 0; i < p.degree; ++i) m = std::max(m, std::abs(p.c[i] / p.c[p.degree]));
  return 1 + m;
}

}  // namespace

double Polynomial::operator()(double t) const {
  double v = c[degree];
  for (int i = degree; i-- > 0;) v = v * t + c[i];
  return v;
}

Polynomial Polynomial::derivative() const {
  Polynomial d;
  d.degree = std::max(degree - 1, 0);
  for (int i = 1; i <= degree; ++i) d.c[i - 1] = i * c[i];
  return d;
}

int real_roots(const Polynomial& in, std::array<double, 4>& roots) {
  Polynomial p = in;
  while (p.degree > 0 && p.c[p.degree] == 0) --p.degree;
  if (p.degree == 0) return 0;
  if (p.degree == 1) {
    roots[0] = -p.c[0] / p.c[1];
    return 1;
  }
  if (p.degree == 2) {
    // The stable quadratic formula: no cancellation between -b and the root.
    const double a = p.c[2], b = p.c[1], c = p.c[0];
    const double disc = b * b - 4 * a * c;
    if (disc < 0) return 0;
    if (disc == 0) {
      roots[0] = -b / (2 * a);
      return 1;
    }
    const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    double r0 = q / a, r1 = q != 0 ? c / q : -r0;
    if (r0 > r1) std::swap(r0, r1);
    roots[0] = r0;
    roots[1] = r1;
    return 2;
  }
  const Polynomial dp = p.derivative();
  std::array<double, 4> critical{};
  const int m = real_roots(dp, critical);
  const double bound = root_bound(p);
  // The ends of the monotonic pieces: the bound's, and the critical points.
  std::array<double, 6> ends{};
  int n_ends = 0;
  ends[n_ends++] = -bound;
  for (int i = 0; i < m; ++i)
    if (critical[i] > -bound && critical[i] < bound) ends[n_ends++] = critical[i];
  ends[n_ends++] = bound;
  int n = 0;
  for (int i = 0; i + 1 < n_ends && n < p.degree; ++i) {
    const double lo = ends[i], hi = ends[i + 1];
    const double v_lo = p(lo), v_hi = p(hi);
    if (v_lo == 0) {
      if (n == 0 || roots[n - 1] != lo) roots[n++] = lo;
      continue;
    }
    if (v_hi == 0 || (v_lo < 0) == (v_hi < 0)) continue;
    roots[n++] = root_in_bracket(p, dp, lo, hi, v_lo);
  }
  if (n < p.degree && p(ends[n_ends - 1]) == 0 && (n == 0 || roots[n - 1] != ends[n_ends - 1])) roots[n++] = ends[n_ends - 1];
  return n;
}

}  // namespace capsim
