// Every declared statistic of a cell and of a link reaches the text report,
// the JSON report and the HTML page, from its one declaration.

#include "machine/machine.h"
#include "machine/statistics.h"
#include "report/html_report.h"
#include "report/sim_report.h"

#include "capsim/scene/parser.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>

namespace capsim::sim {
namespace {

const RunFacts kFacts{{"balls.csg"}, "capsim simulate balls.csg", 0.5, "0", std::nullopt};

SimulationResult run(int depth, bool on_demand = false, bool cells_generate_voxels = false) {
  PrepareOptions prep;
  prep.width = 48;
  prep.height = 40;
  static const PreparedScene scene =
      prepare_scene(parse_scene_file(std::string(CAPSIM_SOURCE_DIR) + "/scenes/balls.csg"), prep);
  const Tracer tracer(scene, TraceOptions{});
  MachineConfig config;
  config.cells = {2, 3};
  config.profile = load_cost_profile("cap");
  config.aa = {depth, 0.3};
  if (on_demand) config.balance = {BalanceScheme::Demand, 16};
  if (cells_generate_voxels) config.voxel_generation = VoxelGeneration::Cells;
  config.completion_cycles = true;  // the page needs them
  return simulate_frame(tracer, config, 2, false);
}

TEST(Statistics, EveryCellStatisticIsInTheJsonTextAndPage) {
  struct Case {
    int depth;
    bool on_demand, cells_generate_voxels;
  };
  for (const auto& [depth, on_demand, cells_voxels] :
       {Case{0, false, false}, Case{1, false, false}, Case{0, true, false}, Case{0, false, true}}) {
    const SimulationResult r = run(depth, on_demand, cells_voxels);
    const nlohmann::json json = report_json(r);
    const std::string text = format_report(r);
    const std::string page = html_report(r, kFacts);
    for (const auto& s : kCellStatistics) {
      const bool kept =
          statistic_kept(s.scope, depth > 0, on_demand ? BalanceScheme::Demand : BalanceScheme::Static, cells_voxels);
      for (std::size_t c = 0; c < r.cells.size(); ++c) {
        ASSERT_EQ(json["cells"][c].contains(s.json_key()), kept) << s.name << " depth " << depth << " " << on_demand;
        if (kept) {
          EXPECT_EQ(json["cells"][c][s.json_key()], s.value(r.cells[c])) << s.name;
        }
      }
      EXPECT_EQ(text.find(s.heading) != std::string::npos, kept) << s.name << " depth " << depth;
      EXPECT_EQ(page.find("data-key=\"" + s.json_key() + "\"") != std::string::npos, kept) << s.name;
    }
  }
}

TEST(Statistics, EveryLinkStatisticIsInTheJsonAndPage) {
  const SimulationResult r = run(1);
  ASSERT_FALSE(r.links.empty());
  const nlohmann::json json = report_json(r);
  const std::string page = html_report(r, kFacts);
  for (const auto& s : kLinkStatistics) {
    for (std::size_t l = 0; l < r.links.size(); ++l) EXPECT_EQ(json["links"][l][s.json_key()], s.value(r.links[l]));
    EXPECT_NE(page.find(std::string("<th>") + s.title + "</th>"), std::string::npos) << s.name;
  }
}

TEST(Statistics, CyclesAreNamedSoInTheJson) {
  EXPECT_EQ(kCellStatistics[2].json_key(), "busy_cycles");
  EXPECT_EQ(kCellStatistics[0].json_key(), "pixels");
  EXPECT_EQ(kLinkStatistics[3].json_key(), "max_wait_cycles");
}

}  // namespace
}  // namespace capsim::sim
