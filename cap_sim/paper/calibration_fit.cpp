#include "paper/calibration_fit.h"

#include "paper/least_squares.h"

#include <cmath>
#include <stdexcept>

namespace capsim::sim {

std::vector<FittedCost> all_fitted_costs() {
  return {FittedCost::RayOther,      FittedCost::VoxelVisit, FittedCost::TreeVisit, FittedCost::HitSort,
          FittedCost::HostPrimitive, FittedCost::HostColumn, FittedCost::HostEntry};
}

const char* profile_key(FittedCost c) {
  switch (c) {
    case FittedCost::RayOther: return "cell_costs_us.ray_other";
    case FittedCost::VoxelVisit: return "cell_costs_us.voxel_visit";
    case FittedCost::TreeVisit: return "cell_costs_us.tree_visit";
    case FittedCost::HitSort: return "cell_costs_us.hit_sort";
    case FittedCost::HostPrimitive: return "host_costs_us.primitive";
    case FittedCost::HostColumn: return "host_costs_us.voxel_column";
    case FittedCost::HostEntry: return "host_costs_us.voxel_entry";
  }
  return "?";
}

double charged_count(FittedCost c, const FitCell& cell) {
  const OpCounts& o = cell.ops;
  switch (c) {
    case FittedCost::RayOther: return static_cast<double>(o.rays);
    case FittedCost::VoxelVisit: return static_cast<double>(o.dda_setups) + static_cast<double>(o.dda_steps);
    case FittedCost::TreeVisit: return static_cast<double>(o.tree_visits);
    case FittedCost::HitSort: return static_cast<double>(o.hits_sorted);
    case FittedCost::HostPrimitive: return static_cast<double>(cell.voxels.primitives);
    case FittedCost::HostColumn: return static_cast<double>(cell.voxels.columns);
    case FittedCost::HostEntry: return static_cast<double>(cell.voxels.voxel_entries);
  }
  return 0;
}

double profile_value_us(FittedCost c, const CostProfile& p) {
  Cycles cycles;
  switch (c) {
    case FittedCost::RayOther: cycles = p.cell.ray_other; break;
    case FittedCost::VoxelVisit: cycles = p.cell.voxel_visit; break;
    case FittedCost::TreeVisit: cycles = p.cell.tree_visit; break;
    case FittedCost::HitSort: cycles = p.cell.hit_sort; break;
    case FittedCost::HostPrimitive: cycles = p.host.primitive; break;
    case FittedCost::HostColumn: cycles = p.host.column; break;
    case FittedCost::HostEntry: cycles = p.host.voxel_entry; break;
  }
  return static_cast<double>(cycles.count()) * 1e6 / static_cast<double>(p.clock_hz);
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
                    const std::vector<FittedCost>& fitted) {
  if (cells.empty() || fitted.empty()) throw std::invalid_argument("a fit needs cells and costs to fit");
  // Row i: sum_k x_k count_ik / paper_i = 1 - (t_i - sum_k profile_k count_ik) / paper_i,
  // x in microseconds.
  std::vector<std::vector<double>> a;
  std::vector<double> b;
  for (const FitCell& cell : cells) {
    std::vector<double> row;
    double rest = cell.simulated_seconds;
    for (FittedCost c : fitted) {
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
