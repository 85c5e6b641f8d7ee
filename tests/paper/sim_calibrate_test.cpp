// `capsim calibrate`'s rounds on a reduced screen: each round runs every
// experiment at the costs the previous fit chose, the best round wins, and
// the result is deterministic.

#include "paper/calibration/calibrate.h"
#include "paper/calibration/calibration.h"
#include "machine/costs/builtin_profiles.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace capsim::sim {
namespace {

CalibrationOptions reduced() {
  CalibrationOptions o;
  o.repro.width = o.repro.height = 32;
  o.repro.m380_width = o.repro.m380_height = 32;
  o.repro.scenes_dir = std::string(CAPSIM_SOURCE_DIR) + "/scenes";
  o.repro.table_4_5_frames = 1;
  o.rounds = 1;
  return o;
}

TEST(Calibrate, ARoundRunsAtTheFittedCostsAndTheBestWins) {
  std::vector<std::string> lines;
  const Calibration c = calibrate(reduced(), [&](const std::string& s) { lines.push_back(s); });
  ASSERT_EQ(c.rounds.size(), 2u);  // the start, then one fit
  EXPECT_EQ(c.rounds[0].x, parameter_values(load_cost_profile("m380"), Machine::M380));
  EXPECT_NE(c.rounds[1].x, c.rounds[0].x);
  // The fit lowers the error of its own model below the start's, and the best
  // round is the one whose runs met the paper best.
  EXPECT_LT(c.rounds[1].model_rms, c.rounds[0].simulated_rms);
  for (const CalibrationRound& r : c.rounds) EXPECT_LE(c.rounds[c.best].simulated_rms, r.simulated_rms);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].rfind("round 0: rms ln(ours / paper) ", 0), 0u) << lines[0];
  // Every table the reduced runs fit has its error.
  ASSERT_FALSE(c.best_tables.empty());
  EXPECT_EQ(c.best_tables.front().table, "4-2");
  // The profiles written from it read back as its costs.
  const nlohmann::json cap = nlohmann::json::parse(calibrated_profile_json(c.x(), Machine::Cap));
  EXPECT_EQ(cap["name"], "cap");
  const CostProfile m380 = calibrated_profile(c.x(), Machine::M380);
  const std::vector<double> back = parameter_values(m380, Machine::M380);
  for (std::size_t k = 0; k < back.size(); ++k) EXPECT_NEAR(back[k], c.x()[k], 1e-3 * c.x()[k] + 1e-9) << k;
}

// The cells' voxel costs that calibrate writes are the host's (as written)
// times 164 on the CAP, the same on the M380: the shipped profiles hold what
// it writes from their own values.
TEST(Calibrate, WritesTheCellsVoxelCostsFromTheHosts) {
  for (const Machine machine : {Machine::Cap, Machine::M380}) {
    const std::string name = machine == Machine::Cap ? "cap" : "m380";
    const nlohmann::json written = nlohmann::json::parse(
        calibrated_profile_json(parameter_values(load_cost_profile(name), machine), machine));
    std::string builtin;
    for (const BuiltinProfile& b : builtin_profiles())
      if (b.name == name) builtin = std::string(b.json);
    EXPECT_EQ(written["cell_voxel_costs_us"], nlohmann::json::parse(builtin)["cell_voxel_costs_us"]) << name;
    if (machine == Machine::Cap) {
      EXPECT_EQ(written["cell_voxel_costs_us"]["primitive"], 194800);  // 1188 x 164 = 194832, to 4 digits
      EXPECT_EQ(written["cell_voxel_costs_us"]["grid_voxel"], 11970);   // 73.01 x 164 = 11973.64
    }
  }
}

TEST(Calibrate, AlternativesVaryOneAssumptionEach) {
  const std::vector<Alternative> alternatives = calibration_alternatives(reduced());
  ASSERT_GE(alternatives.size(), 8u);
  EXPECT_EQ(alternatives[0].name.rfind("shipped", 0), 0u);
  int primary = 0, exclusions = 0, screens = 0;
  for (const Alternative& a : alternatives) {
    primary += a.options.repro.table_4_2_primary_only ? 1 : 0;
    exclusions += a.options.exclusions != Exclusions::Table44ChessCad ? 1 : 0;
    screens += a.options.repro.width != 32 || a.options.repro.m380_width != 32 ? 1 : 0;
  }
  EXPECT_EQ(primary, 1);
  EXPECT_EQ(exclusions, 2);
  EXPECT_EQ(screens, 5);
}

}  // namespace
}  // namespace capsim::sim
