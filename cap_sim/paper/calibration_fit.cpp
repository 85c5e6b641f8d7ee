#include "paper/calibration_fit.h"

#include "paper/least_squares.h"

#include <cmath>
#include <stdexcept>

namespace capsim::sim {

std::vector<CostTerm> all_fitted_costs() {
  return {CostTerm::RayOther,      CostTerm::VoxelVisit, CostTerm::TreeVisit, CostTerm::HitSort,
          CostTerm::HostPrimitive, CostTerm::HostColumn, CostTerm::HostEntry};
}

double charged_count(CostTerm c, const FitCell& cell) {
  const CostTermInfo& t = info(c);
  return static_cast<double>(t.payer == CostPayer::Cell ? t.cell_count(cell.ops, cell.pixels)
                                                        : t.host_count(cell.voxels));
}

double profile_value_us(CostTerm c, const CostProfile& p) {
  return static_cast<double>(p.costs[c].count()) * 1e6 / static_cast<double>(p.clock_hz);
}

namespace {

double rms_relative(const std::vector<FitCell>& cells, const std::vector<double>& predicted) {
  double sum = 0;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const double r = predicted[i] / cells[i].paper_seconds - 1;
    sum += r * r;
  }
  return std::sqrt(sum / static_cast<double>(cells.size()));
}

}  // namespace

FitResult fit_costs(const std::vector<FitCell>& cells, const CostProfile& profile,
                    const std::vector<CostTerm>& fitted) {
  if (cells.empty() || fitted.empty()) throw std::invalid_argument("a fit needs cells and costs to fit");
  // Row i: sum_k x_k count_ik / paper_i = 1 - (t_i - sum_k profile_k count_ik) / paper_i,
  // x in microseconds.
  std::vector<std::vector<double>> a;
  std::vector<double> b;
  for (const FitCell& cell : cells) {
    std::vector<double> row;
    double rest = cell.simulated_seconds;
    for (CostTerm c : fitted) {
      const double n = charged_count(c, cell);
      row.push_back(n * 1e-6 / cell.paper_seconds);
      rest -= profile_value_us(c, profile) * n * 1e-6;
    }
    a.push_back(std::move(row));
    b.push_back(1 - rest / cell.paper_seconds);
  }
  FitResult r;
  r.fitted = fitted;
  r.value_us = nonnegative_least_squares(a, b);
  for (std::size_t i = 0; i < cells.size(); ++i) {
    double t = cells[i].paper_seconds * (1 - b[i]);
    for (std::size_t k = 0; k < fitted.size(); ++k) t += r.value_us[k] * a[i][k] * cells[i].paper_seconds;
    r.predicted_seconds.push_back(t);
  }
  r.rms_relative_error = rms_relative(cells, r.predicted_seconds);
  return r;
}

FitResult evaluate_costs(const std::vector<FitCell>& cells) {
  FitResult r;
  for (const FitCell& c : cells) r.predicted_seconds.push_back(c.simulated_seconds);
  r.rms_relative_error = rms_relative(cells, r.predicted_seconds);
  return r;
}

}  // namespace capsim::sim
