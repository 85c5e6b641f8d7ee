// Non-negative least squares, the calibration fit's step.

#include "paper/calibration/least_squares.h"

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

}  // namespace
}  // namespace capsim::sim
