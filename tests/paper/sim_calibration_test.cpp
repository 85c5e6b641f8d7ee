// The shipped profiles against the paper's Table 4-2: the 35 runs (five
// sphere lattices, 1 to 48 divisions, one M380) take their exact cycles, here
// on a 128 x 128 screen to keep the test short, and the profiles hold what
// the calibration fitted as docs/calibration.md states it.

#include "machine/costs/cost_profile.h"
#include "paper/calibration/calibration.h"
#include "paper/lattice_scene.h"
#include "paper/repro/paper_figures.h"
#include "paper/repro/repro.h"

#include <gtest/gtest.h>

#include <cmath>

namespace capsim::sim {
namespace {

const Table42& table_4_2() {
  static const Table42 t = [] {
    ReproOptions o;
    o.m380_width = o.m380_height = 128;
    return run_table_4_2(o);
  }();
  return t;
}

TEST(Calibration, Table42RunsTakeTheirExactCycles) {
  // Rows: 16, 512, 1000, 4096, 6859 spheres; columns: 1, 2, 4, 8, 16, 32, 48 divisions.
  const std::uint64_t expected[5][7] = {
      {6833441994, 2308884544, 1623460504, 1736888344, 1974098424, 4471772524, 10545243764},
      {183318345530, 34857584272, 10240382064, 5586831608, 4122682288, 5965333308, 11969410648},
      {360027091014, 67300621972, 19117775684, 9956688620, 7228416256, 7430373836, 12917684276},
      {1591912680602, 281538539064, 68308637520, 22782898208, 14049174920, 12717077560, 17926123690},
      {2682627381862, 524649200812, 126487324868, 39419416300, 22044712124, 18447133540, 22668280110},
  };
  for (int row = 0; row < 5; ++row)
    for (int col = 0; col < 7; ++col)
      EXPECT_EQ(table_4_2().cells[row][col].frame.count(), expected[row][col])
          << paper::kTable42Objects[row] << " spheres, " << paper::kTable42Divisions[col] << " divisions";
}

TEST(Calibration, EveryLatticeRayMeetsItsUniverseAt128x128) {
  // At 128 x 128 each ray stands for 16 of the paper's: the 1-division times
  // say every ray met every lattice. Every primary ray starts a 3DDDA, and
  // so do the shadow rays of those that hit a sphere.
  for (int row = 0; row < 5; ++row) {
    const OpCounts& ops = table_4_2().cells[row][0].ops;
    EXPECT_EQ(ops.dda_setups, ops.rays) << paper::kTable42Objects[row];
    EXPECT_GT(ops.rays, ops.primary_rays) << paper::kTable42Objects[row];
  }
}

TEST(Calibration, CapCellCostsAreTheM380sTimesTheTable41Ratio) {
  const CostProfile cap = load_cost_profile("cap"), m380 = load_cost_profile("m380");
  const std::vector<double> on_cap = parameter_values(cap, Machine::Cap);
  const std::vector<double> on_m380 = parameter_values(m380, Machine::M380);
  const std::vector<FitParameter> params = fit_parameters();
  for (std::size_t k = 0; k < params.size(); ++k)
    // Each profile stores 4 significant digits and rounds to whole cycles.
    EXPECT_NEAR(on_cap[k], on_m380[k], 1e-3 * on_m380[k] + 1e-6) << profile_key(params[k].term);
  // The host's Table 4-1 operations are the M380's: one host.
  EXPECT_EQ(profile_value_us(CostTerm::HostMatmat, cap), 18.5);
  EXPECT_NEAR(profile_value_us(CostTerm::HostMatvec, cap), 3.625, 1e-9);  // 29 cycles at 8 MHz
}

}  // namespace
}  // namespace capsim::sim
