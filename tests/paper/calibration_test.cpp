// What the calibration fits and how a run's time depends on it.

#include "paper/calibration/calibration.h"
#include "paper/repro/paper_figures.h"

#include <gtest/gtest.h>

#include <cmath>

namespace capsim::sim {
namespace {

std::size_t index_of(CostTerm t) {
  const std::vector<FitParameter> params = fit_parameters();
  for (std::size_t k = 0; k < params.size(); ++k)
    if (params[k].term == t) return k;
  ADD_FAILURE() << profile_key(t) << " is not fitted";
  return 0;
}

TEST(Calibration, FitsOnlyWhatTable41DoesNotGive) {
  for (const FitParameter& p : fit_parameters()) EXPECT_NE(info(p.term).source, CostSource::Table41) << profile_key(p.term);
  EXPECT_EQ(FitParameter{CostTerm::RayOther}.cap_multiplier(), paper::kCapOverM380);
  EXPECT_EQ(FitParameter{CostTerm::HostGridVoxel}.cap_multiplier(), 1.0);
}

TEST(Calibration, ATimeIsLinearInTheFittedCosts) {
  CostProfile profile = load_cost_profile("m380");
  WorkCounts counts;
  counts.ops.rays = 1000;
  counts.ops.voxel_passes = 300;
  counts.pixels = 50;
  counts.voxels.grid_voxels = 8;
  const double simulated = 2.5;
  const LinearTime t = linear_time(simulated, counts, profile, Machine::M380);
  // At the profile's own values the time is the simulated one.
  EXPECT_NEAR(t.at(parameter_values(profile, Machine::M380)), simulated, 1e-12);
  // Each parameter moves it by its count: 1000 rays x 1 us = 1 ms.
  EXPECT_NEAR(t.per_param[index_of(CostTerm::RayOther)], 1000e-6, 1e-15);
  EXPECT_NEAR(t.per_param[index_of(CostTerm::VoxelPass)], 300e-6, 1e-15);
  EXPECT_NEAR(t.per_param[index_of(CostTerm::PixelWrite)], 50e-6, 1e-15);
  EXPECT_NEAR(t.per_param[index_of(CostTerm::HostGridVoxel)], 8e-6, 1e-15);
  EXPECT_EQ(t.per_param[index_of(CostTerm::TreeVisit)], 0);
  // On the CAP a cell's microsecond of M380 work is 164 of its own; the
  // host's is the same.
  const LinearTime cap = linear_time(simulated, counts, load_cost_profile("cap"), Machine::Cap);
  EXPECT_NEAR(cap.per_param[index_of(CostTerm::RayOther)], 1000e-6 * paper::kCapOverM380, 1e-12);
  EXPECT_NEAR(cap.per_param[index_of(CostTerm::HostGridVoxel)], 8e-6, 1e-15);
}

TEST(Calibration, ACategorysTimeMovesOnlyWithItsOwnCosts) {
  WorkCounts counts;
  counts.ops.rays = 1000;
  counts.ops.voxel_passes = 300;
  const LinearTime csg = linear_time(1.0, counts, load_cost_profile("m380"), Machine::M380, CostCategory::Csg);
  EXPECT_EQ(csg.per_param[index_of(CostTerm::RayOther)], 0);
  EXPECT_NEAR(csg.per_param[index_of(CostTerm::VoxelPass)], 300e-6, 1e-15);
}

TEST(Calibration, ProfilesTakeTheFittedValues) {
  std::vector<double> x(fit_parameters().size(), 0.0);
  x[index_of(CostTerm::RayOther)] = 1.23456;
  x[index_of(CostTerm::HostPrimitive)] = 100;
  const CostProfile m380 = calibrated_profile(x, Machine::M380);
  const CostProfile cap = calibrated_profile(x, Machine::Cap);
  EXPECT_NEAR(profile_value_us(CostTerm::RayOther, m380), 1.235, 1e-9);  // 4 significant digits
  EXPECT_NEAR(profile_value_us(CostTerm::RayOther, cap), 202.5, 1e-9);  // 164 x 1.23456, 4 digits
  EXPECT_NEAR(profile_value_us(CostTerm::HostPrimitive, cap), 100, 1e-9);
  // Table 4-1's costs stay.
  EXPECT_NEAR(profile_value_us(CostTerm::SphereTest, m380), 18.2, 1e-9);
  EXPECT_NEAR(profile_value_us(CostTerm::SphereTest, cap), 2980, 1e-9);
  // And the values read back as the parameters (to the rounding).
  EXPECT_NEAR(parameter_values(m380, Machine::M380)[index_of(CostTerm::RayOther)], 1.235, 1e-9);
}

}  // namespace
}  // namespace capsim::sim
