// Non-negative least squares and the calibration fit built on it.

#include "paper/calibration_fit.h"
#include "paper/least_squares.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace capsim::sim {
namespace {

TEST(LeastSquares, SolvesAConsistentSystemExactly) {
  // x = 2, y = 3 satisfy every row.
  const std::vector<std::vector<double>> a = {{1, 0}, {0, 1}, {1, 1}, {2, -1}};
  const std::vector<double> b = {2, 3, 5, 1};
  const std::vector<double> x = nonnegative_least_squares(a, b);
  EXPECT_NEAR(x[0], 2, 1e-12);
  EXPECT_NEAR(x[1], 3, 1e-12);
}

TEST(LeastSquares, MinimisesTheSquaredResidual) {
  // Fitting a constant to 1, 2, 6: the mean.
  const std::vector<double> x = nonnegative_least_squares({{1}, {1}, {1}}, {1, 2, 6});
  EXPECT_NEAR(x[0], 3, 1e-12);
}

TEST(LeastSquares, KeepsEveryUnknownNonNegative) {
  // Unconstrained: x = 4, y = -1. With y >= 0 the best is y = 0 and x the least
  // squares of x alone: rows (x = 3), (x = 4), (x = 5): x = 4.
  const std::vector<std::vector<double>> a = {{1, 1}, {1, 0}, {1, -1}};
  const std::vector<double> b = {3, 4, 5};
  const std::vector<double> x = nonnegative_least_squares(a, b);
  EXPECT_NEAR(x[0], 4, 1e-12);
  EXPECT_EQ(x[1], 0);
}

TEST(LeastSquares, AColumnOfZerosGivesZero) {
  const std::vector<double> x = nonnegative_least_squares({{1, 0}, {2, 0}}, {1, 2});
  EXPECT_NEAR(x[0], 1, 1e-12);
  EXPECT_EQ(x[1], 0);
}

TEST(LeastSquares, RefusesRaggedOrEmptyInput) {
  EXPECT_THROW(nonnegative_least_squares({}, {}), std::invalid_argument);
  EXPECT_THROW(nonnegative_least_squares({{1, 2}, {1}}, {1, 2}), std::invalid_argument);
  EXPECT_THROW(nonnegative_least_squares({{1}}, {1, 2}), std::invalid_argument);
}

// Cells whose "paper" times come from known costs: the fit finds them.
TEST(CalibrationFit, RecoversTheCostsThePublishedTimesWereMadeWith) {
  CostProfile profile;
  profile.clock_hz = 1'000'000;  // 1 cycle = 1 us
  profile.costs[CostTerm::RayOther] = Cycles(10);
  profile.costs[CostTerm::VoxelVisit] = Cycles(1);
  const double true_ray = 25, true_voxel = 4;  // us
  std::vector<FitCell> cells;
  for (int i = 1; i <= 6; ++i) {
    FitCell c;
    c.ops.rays = 1000u * i;
    c.ops.dda_setups = 900u * i;
    c.ops.dda_steps = 5000u * static_cast<std::uint64_t>(i * i);
    const double fixed = 0.5 * i;  // seconds of work not fitted
    const double voxels = static_cast<double>(c.ops.dda_setups + c.ops.dda_steps);
    c.simulated_seconds = fixed + 1e-6 * (10 * static_cast<double>(c.ops.rays) + 1 * voxels);
    c.paper_seconds = fixed + 1e-6 * (true_ray * static_cast<double>(c.ops.rays) + true_voxel * voxels);
    cells.push_back(c);
  }
  const FitResult fit = fit_costs(cells, profile, {CostTerm::RayOther, CostTerm::VoxelVisit});
  EXPECT_NEAR(fit.value_us[0], true_ray, 1e-6);
  EXPECT_NEAR(fit.value_us[1], true_voxel, 1e-6);
  EXPECT_NEAR(fit.rms_relative_error, 0, 1e-9);
  for (std::size_t i = 0; i < cells.size(); ++i) EXPECT_NEAR(fit.predicted_seconds[i], cells[i].paper_seconds, 1e-9);
  // As the profile stands, every cell is below the paper.
  const FitResult now = evaluate_costs(cells);
  EXPECT_GT(now.rms_relative_error, 0.1);
  EXPECT_EQ(now.predicted_seconds[2], cells[2].simulated_seconds);
}

TEST(CalibrationFit, CountsAndProfileValuesPerCost) {
  FitCell c;
  c.ops.rays = 7;
  c.ops.dda_setups = 2;
  c.ops.dda_steps = 9;
  c.ops.tree_visits = 4;
  c.ops.hits_sorted = 5;
  c.voxels.primitives = 3;
  c.voxels.columns = 6;
  c.voxels.voxel_entries = 8;
  const double want[] = {7, 11, 4, 5, 3, 6, 8};
  ASSERT_EQ(all_fitted_costs().size(), std::size(want));
  for (std::size_t k = 0; k < std::size(want); ++k) EXPECT_EQ(charged_count(all_fitted_costs()[k], c), want[k]) << k;
  const CostProfile m380 = load_cost_profile("m380");
  EXPECT_DOUBLE_EQ(profile_value_us(CostTerm::HostColumn, m380), 10.8);
  EXPECT_EQ(profile_key(CostTerm::VoxelVisit), "cell_costs_us.voxel_visit");
}

}  // namespace
}  // namespace capsim::sim
