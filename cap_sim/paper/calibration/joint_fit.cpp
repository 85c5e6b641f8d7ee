#include "paper/calibration/joint_fit.h"

#include "paper/calibration/least_squares.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace capsim::sim {

double LinearTime::at(const std::vector<double>& x) const {
  double t = fixed;
  for (std::size_t k = 0; k < per_param.size(); ++k) t += per_param[k] * x[k];
  return t;
}

double FigureModel::time(const std::vector<double>& x, std::vector<double>* gradient) const {
  if (parts.empty()) throw std::invalid_argument("a figure's model has no parts");
  std::size_t chosen = 0;
  double t = parts[0].at(x);
  if (combine == Combine::Max || combine == Combine::Min) {
    for (std::size_t i = 1; i < parts.size(); ++i) {
      const double ti = parts[i].at(x);
      if (combine == Combine::Max ? ti > t : ti < t) {
        t = ti;
        chosen = i;
      }
    }
  }
  const double s = combine == Combine::Scaled ? scale : 1.0;
  if (gradient) {
    gradient->assign(x.size(), 0.0);
    for (std::size_t k = 0; k < parts[chosen].per_param.size(); ++k) (*gradient)[k] = s * parts[chosen].per_param[k];
  }
  return s * t;
}

double rms_log_error(const std::vector<double>& predicted, const std::vector<double>& target) {
  if (predicted.empty() || predicted.size() != target.size())
    throw std::invalid_argument("rms error: one prediction per target");
  double sum = 0;
  for (std::size_t i = 0; i < predicted.size(); ++i) {
    if (!(predicted[i] > 0)) return std::numeric_limits<double>::infinity();
    const double r = std::log(predicted[i] / target[i]);
    sum += r * r;
  }
  return std::sqrt(sum / static_cast<double>(predicted.size()));
}

namespace {

std::vector<double> predict_all(const std::vector<FigureModel>& models, const std::vector<double>& x) {
  std::vector<double> p;
  p.reserve(models.size());
  for (const FigureModel& m : models) p.push_back(m.time(x));
  return p;
}

}  // namespace

LogFitResult fit_log_least_squares(const std::vector<FigureModel>& models, const std::vector<double>& target,
                                   const std::vector<double>& start) {
  if (models.empty() || models.size() != target.size())
    throw std::invalid_argument("fit: one target per figure, and at least one");
  for (double t : target)
    if (!(t > 0)) throw std::invalid_argument("fit: every target must be positive");
  LogFitResult r;
  r.x = start;
  for (double& v : r.x) v = std::max(v, 0.0);
  r.predicted = predict_all(models, r.x);
  double error = rms_log_error(r.predicted, target);
  if (!std::isfinite(error)) throw std::invalid_argument("fit: a figure's time at the start is not positive");

  const std::size_t n = r.x.size();
  for (r.iterations = 0; r.iterations < 100; ++r.iterations) {
    // Linearise ln(model_i) at x: ln m_i(y) ~ ln m_i(x) + g_i . (y - x) / m_i(x),
    // and solve for y >= 0 directly: rows g_i / m_i, right-hand side
    // ln(target_i / m_i(x)) + g_i . x / m_i.
    std::vector<std::vector<double>> a;
    std::vector<double> b;
    for (std::size_t i = 0; i < models.size(); ++i) {
      std::vector<double> g;
      const double m = models[i].time(r.x, &g);
      double gx = 0;
      for (std::size_t k = 0; k < n; ++k) {
        g[k] /= m;
        gx += g[k] * r.x[k];
      }
      a.push_back(std::move(g));
      b.push_back(std::log(target[i] / m) + gx);
    }
    const std::vector<double> y = nonnegative_least_squares(a, b);
    // Damped step from x towards y until the true error falls.
    bool improved = false;
    for (double step = 1; step > 1.0 / 1024; step /= 2) {
      std::vector<double> trial(n);
      for (std::size_t k = 0; k < n; ++k) trial[k] = r.x[k] + step * (y[k] - r.x[k]);
      const std::vector<double> p = predict_all(models, trial);
      const double e = rms_log_error(p, target);
      if (e < error) {
        improved = error - e > 1e-12 * error;
        r.x = trial;
        r.predicted = p;
        error = e;
        break;
      }
    }
    if (!improved) break;
  }
  r.rms_log = error;
  return r;
}

}  // namespace capsim::sim
