#pragma once
// The fit of the cost constants the paper does not give, by least squares of
// the relative error over measured cells (docs/calibration.md). Time is linear
// in every cost, so a cell's time for other values of the fitted costs follows
// from its simulated time and its operation counts:
//   t(x) = t_simulated + sum over fitted costs k of (x_k - profile_k) x count_k.

#include "machine/cost_profile.h"

#include "capsim/op_counts.h"

#include <string>
#include <vector>

namespace capsim::sim {

// The costs Table 4-2's fit may determine: those Table 4-1 does not give,
// in the order the reproduction prints them.
std::vector<CostTerm> all_fitted_costs();

// One measured cell: the published time and a simulation of it on one cell
// (its operations are what that cell and the host did).
struct FitCell {
  double paper_seconds = 0;
  double simulated_seconds = 0;
  OpCounts ops;              // summed over the cells
  std::uint64_t pixels = 0;  // written, summed over the cells
  VoxelGenCounts voxels;     // the host's
};

// How many operations term c is charged for in a cell.
double charged_count(CostTerm c, const FitCell& cell);
// The profile's value of term c, in microseconds (its cycles / clock).
double profile_value_us(CostTerm c, const CostProfile& profile);

struct FitResult {
  std::vector<CostTerm> fitted;
  std::vector<double> value_us;           // per fitted cost, >= 0
  std::vector<double> predicted_seconds;  // per cell, with the fitted values
  double rms_relative_error = 0;          // sqrt(mean of (predicted / paper - 1)^2)
};

// Non-negative least squares of (t / paper - 1) over the cells, the costs in
// `fitted` free and every other cost at the profile's value.
FitResult fit_costs(const std::vector<FitCell>& cells, const CostProfile& profile,
                    const std::vector<CostTerm>& fitted);

// The same quantities for the profile as it is (nothing fitted).
FitResult evaluate_costs(const std::vector<FitCell>& cells);

}  // namespace capsim::sim
