// The joint fit: least squares of ln(ours / paper) over costs >= 0.

#include "paper/calibration/joint_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace capsim::sim {
namespace {

FigureModel linear(double fixed, std::vector<double> per_param) {
  FigureModel m;
  m.parts.push_back({fixed, std::move(per_param)});
  return m;
}

TEST(JointFit, RecoversCostsThatMeetEveryFigure) {
  // Times 1 + 2 a + b, 3 a, 5 + b, 4 b at a = 2, b = 0.5: 5.5, 6, 5.5, 2.
  const std::vector<FigureModel> models = {linear(1, {2, 1}), linear(0, {3, 0}), linear(5, {0, 1}),
                                           linear(0, {0, 4})};
  const LogFitResult r = fit_log_least_squares(models, {5.5, 6, 5.5, 2}, {1, 1});
  EXPECT_NEAR(r.x[0], 2, 1e-9);
  EXPECT_NEAR(r.x[1], 0.5, 1e-9);
  EXPECT_LT(r.rms_log, 1e-9);
}

TEST(JointFit, MinimisesTheLogarithmicErrorNotTheRelativeOne) {
  // One cost c against targets 1 and 4 for the same time c: the log error is
  // least at the geometric mean, 2 (the relative error would give 17/5).
  const LogFitResult r = fit_log_least_squares({linear(0, {1}), linear(0, {1})}, {1, 4}, {1});
  EXPECT_NEAR(r.x[0], 2, 1e-6);
  EXPECT_NEAR(r.rms_log, std::log(2.0), 1e-6);
}

TEST(JointFit, KeepsCostsNonNegative) {
  // The second figure alone would want b < 0 (its fixed part already exceeds
  // the target): b stays 0 and a meets the first figure.
  const LogFitResult r = fit_log_least_squares({linear(0, {1, 1}), linear(10, {0, 1})}, {3, 5}, {1, 1});
  EXPECT_EQ(r.x[1], 0);
  EXPECT_NEAR(r.x[0], 3, 1e-6);
}

TEST(JointFit, MaxAndMinFollowTheLargestAndSmallestPart) {
  FigureModel max;
  max.combine = Combine::Max;
  max.parts = {{0, {1, 0}}, {0, {0, 2}}};
  std::vector<double> g;
  EXPECT_EQ(max.time({3, 1}, &g), 3);
  EXPECT_EQ(g, (std::vector<double>{1, 0}));
  EXPECT_EQ(max.time({1, 1}, &g), 2);
  EXPECT_EQ(g, (std::vector<double>{0, 2}));
  FigureModel min = max;
  min.combine = Combine::Min;
  EXPECT_EQ(min.time({3, 1}, &g), 2);
  EXPECT_EQ(g, (std::vector<double>{0, 2}));
  FigureModel scaled;
  scaled.combine = Combine::Scaled;
  scaled.scale = 10;
  scaled.parts = {{1, {1, 0}}};
  EXPECT_EQ(scaled.time({2, 0}, &g), 30);
  EXPECT_EQ(g, (std::vector<double>{10, 0}));
}

TEST(JointFit, FitsThroughAMaximum) {
  // Max over two cells, a figure of 6 for it and 2 for the first cell alone:
  // x = (2, 1.5): the cells take 2 and 6.
  FigureModel max;
  max.combine = Combine::Max;
  max.parts = {{0, {1, 0}}, {0, {0, 4}}};
  const LogFitResult r = fit_log_least_squares({max, linear(0, {1, 0})}, {6, 2}, {1, 1});
  EXPECT_NEAR(r.x[0], 2, 1e-6);
  EXPECT_NEAR(r.x[1], 1.5, 1e-6);
}

TEST(JointFit, RefusesBadInput) {
  EXPECT_THROW(fit_log_least_squares({}, {}, {1}), std::invalid_argument);
  EXPECT_THROW(fit_log_least_squares({linear(0, {1})}, {0}, {1}), std::invalid_argument);
  EXPECT_THROW(fit_log_least_squares({linear(0, {1})}, {1}, {0}), std::invalid_argument);
}

}  // namespace
}  // namespace capsim::sim
