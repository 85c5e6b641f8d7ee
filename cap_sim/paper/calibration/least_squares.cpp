#include "paper/calibration/least_squares.h"

#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

namespace capsim::sim {

namespace {

// The least-squares solution of a x = b for the columns in `cols`, by
// Householder QR on column-scaled copies; nothing when the columns are
// linearly dependent (to rounding).
std::optional<std::vector<double>> solve_columns(const std::vector<std::vector<double>>& a,
                                                 const std::vector<double>& b, const std::vector<int>& cols) {
  const std::size_t m = a.size(), n = cols.size();
  if (n > m) return std::nullopt;
  std::vector<std::vector<double>> r(m, std::vector<double>(n));
  std::vector<double> scale(n, 0.0);
  for (std::size_t j = 0; j < n; ++j) {
    for (std::size_t i = 0; i < m; ++i) scale[j] = std::max(scale[j], std::abs(a[i][cols[j]]));
    if (scale[j] == 0) return std::nullopt;
    for (std::size_t i = 0; i < m; ++i) r[i][j] = a[i][cols[j]] / scale[j];
  }
  std::vector<double> y = b;
  for (std::size_t k = 0; k < n; ++k) {
    double norm = 0;
    for (std::size_t i = k; i < m; ++i) norm += r[i][k] * r[i][k];
    norm = std::sqrt(norm);
    if (norm < 1e-12) return std::nullopt;
    const double alpha = r[k][k] > 0 ? -norm : norm;
    std::vector<double> v(m, 0.0);
    for (std::size_t i = k; i < m; ++i) v[i] = r[i][k];
    v[k] -= alpha;
    double vv = 0;
    for (std::size_t i = k; i < m; ++i) vv += v[i] * v[i];
    if (vv == 0) continue;
    for (std::size_t j = k; j < n; ++j) {
      double dot = 0;
      for (std::size_t i = k; i < m; ++i) dot += v[i] * r[i][j];
      for (std::size_t i = k; i < m; ++i) r[i][j] -= 2 * dot / vv * v[i];
    }
    double dot = 0;
    for (std::size_t i = k; i < m; ++i) dot += v[i] * y[i];
    for (std::size_t i = k; i < m; ++i) y[i] -= 2 * dot / vv * v[i];
  }
  std::vector<double> x(n);
  for (std::size_t k = n; k-- > 0;) {
    double s = y[k];
    for (std::size_t j = k + 1; j < n; ++j) s -= r[k][j] * x[j];
    if (std::abs(r[k][k]) < 1e-12) return std::nullopt;
    x[k] = s / r[k][k];
  }
  for (std::size_t j = 0; j < n; ++j) x[j] /= scale[j];
  return x;
}

double squared_residual(const std::vector<std::vector<double>>& a, const std::vector<double>& b,
                        const std::vector<double>& x) {
  double sum = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    double r = -b[i];
    for (std::size_t j = 0; j < x.size(); ++j) r += a[i][j] * x[j];
    sum += r * r;
  }
  return sum;
}

}  // namespace

std::vector<double> nonnegative_least_squares(const std::vector<std::vector<double>>& a,
                                              const std::vector<double>& b) {
  if (a.empty() || a.size() != b.size()) throw std::invalid_argument("least squares: no equations, or not one right-hand side per row");
  const std::size_t n = a[0].size();
  if (n == 0 || n > 16) throw std::invalid_argument("least squares: 1 to 16 unknowns");
  for (const auto& row : a)
    if (row.size() != n) throw std::invalid_argument("least squares: rows of different lengths");

  std::vector<double> best(n, 0.0);
  double best_residual = squared_residual(a, b, best);
  for (unsigned subset = 1; subset < (1u << n); ++subset) {
    std::vector<int> cols;
    for (std::size_t j = 0; j < n; ++j)
      if (subset & (1u << j)) cols.push_back(static_cast<int>(j));
    const std::optional<std::vector<double>> x = solve_columns(a, b, cols);
    if (!x) continue;
    bool feasible = true;
    for (double v : *x) feasible = feasible && v >= 0;
    if (!feasible) continue;
    std::vector<double> full(n, 0.0);
    for (std::size_t k = 0; k < cols.size(); ++k) full[cols[k]] = (*x)[k];
    const double residual = squared_residual(a, b, full);
    if (residual < best_residual) {
      best_residual = residual;
      best = full;
    }
  }
  return best;
}

}  // namespace capsim::sim
