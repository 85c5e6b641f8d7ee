#pragma once
// The joint fit of the calibration (docs/calibration.md): the unknown costs
// chosen so that the published times, all tables at once, are met as closely
// as possible in ratio: minimise sum over figures of ln(ours / paper)^2 over
// costs >= 0.
//
// Each figure's time is a model of the costs x (microseconds): a part is
// linear, fixed + sum_k per_param[k] x_k (seconds); a figure is one part, the
// largest or smallest of several (Max and Min over a run's cells), or one
// part scaled (a run whose time the model follows only in proportion, such
// as a frame-averaged sequence). Runs measured at one set of costs give these
// models exactly for linear figures and to first order for the others; the
// calibration re-runs the machine at the fitted costs and fits again.

#include <string>
#include <vector>

namespace capsim::sim {

struct LinearTime {
  double fixed = 0;                // seconds that do not depend on the fitted costs
  std::vector<double> per_param;   // seconds per microsecond of each fitted cost
  double at(const std::vector<double>& x) const;
};

enum class Combine { One, Max, Min, Scaled };

struct FigureModel {
  Combine combine = Combine::One;
  std::vector<LinearTime> parts;  // One, Scaled: exactly one
  double scale = 1;               // Scaled: time = scale x parts[0]
  // The model's time at x; gradient (if given) receives d time / d x.
  double time(const std::vector<double>& x, std::vector<double>* gradient = nullptr) const;
};

struct LogFitResult {
  std::vector<double> x;          // the fitted costs, each >= 0
  std::vector<double> predicted;  // each figure's model time at x
  double rms_log = 0;             // sqrt(mean of ln(predicted / paper)^2)
  int iterations = 0;
};

// rms of ln(predicted / target) over the figures.
double rms_log_error(const std::vector<double>& predicted, const std::vector<double>& target);

// Minimises sum_i ln(model_i(x) / target_i)^2 over x >= 0 by Gauss-Newton
// steps, each the non-negative least-squares solution of the linearised
// problem, damped (halved) until the error falls. start: where to begin (one
// value per cost, > 0 where the cost may be used). Throws
// std::invalid_argument when the sizes disagree, a target is not positive or
// a model's time at start is not positive.
LogFitResult fit_log_least_squares(const std::vector<FigureModel>& models, const std::vector<double>& target,
                                   const std::vector<double>& start);

}  // namespace capsim::sim
