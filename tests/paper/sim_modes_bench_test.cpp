// `capsim bench modes` at a reduced screen against its stored baseline
// (bench/baselines/modes-48x48.json): identical figures pass; any moved figure
// fails with a table of old, new and their ratio; --update rewrites the
// baseline and says what moved.

#include "paper/modes/modes_bench.h"
#include "support/cli_run.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace capsim::sim {
namespace {

using capsim::testing::read_file;
using capsim::testing::run_capsim;
using capsim::testing::TempDir;

const std::string kBaseline = std::string(CAPSIM_SOURCE_DIR) + "/bench/baselines/modes-48x48.json";
const std::string kArgs = " --size 48x48 --scenes " + std::string(CAPSIM_SOURCE_DIR) + "/scenes";

TEST(CliBenchModes, MatchesItsStoredBaseline) {
  TempDir dir;
  const auto r = run_capsim("bench modes" + kArgs + " --baseline " + kBaseline + " --json " + (dir / "now.json") +
                                " --plot " + (dir / "modes.svg"),
                            dir);
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("all 200 runs identical to the baseline"), std::string::npos) << r.out;
  // The table: a header and one row per run.
  EXPECT_NE(r.out.find("model        scheme    cells  aa    frame s"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("disb/f00000  dot       16x16   2"), std::string::npos) << r.out;
  // The same figures as the baseline; the file names the version that wrote
  // it, which a baseline from an earlier version may not share.
  nlohmann::json now = nlohmann::json::parse(read_file(dir / "now.json"));
  nlohmann::json base = nlohmann::json::parse(read_file(kBaseline));
  const std::string version = run_capsim("--version", dir).out;
  EXPECT_EQ("capsim " + now["capsim_version"].get<std::string>() + "\n", version);
  now.erase("capsim_version");
  base.erase("capsim_version");
  EXPECT_EQ(now, base);
  EXPECT_EQ(read_file(dir / "modes.svg").find("<svg"), 0u);
}

TEST(CliBenchModes, DemandRunsFollowTheStaticOnesWithTheirBalancingFigures) {
  const nlohmann::json base = nlohmann::json::parse(read_file(kBaseline));
  // Per model and antialiasing: block, line, dot, demand, then steal, on 4 grids each.
  const nlohmann::json& demand = base["runs"][14];  // balls, plain, demand:64, 8x8 cells
  EXPECT_EQ(demand["model"], "balls");
  EXPECT_EQ(demand["balance"], "demand:64");
  EXPECT_FALSE(demand.contains("mode"));
  EXPECT_EQ(demand["cells"], "8x8");
  EXPECT_GT(demand["balance_bus_percent"].get<double>(), 0);
  EXPECT_TRUE(demand["tile_wait_cycles"].is_number_unsigned());
  // A static run has neither.
  EXPECT_EQ(base["runs"][10]["mode"], "dot");
  EXPECT_FALSE(base["runs"][10].contains("balance"));
  EXPECT_FALSE(base["runs"][10].contains("balance_bus_percent"));
  // Then steal, from dot mode, with what it stole.
  const nlohmann::json& steal = base["runs"][18];  // balls, plain, steal:16, 8x8 cells
  EXPECT_EQ(steal["balance"], "steal:16");
  EXPECT_FALSE(steal.contains("mode"));
  EXPECT_TRUE(steal["chunks_stolen"].is_number_unsigned());
  EXPECT_GT(steal["steal_link_bytes"].get<std::uint64_t>(), 0u);
  // Tiles trace their own corners: an antialiased demand run sends nothing over the links.
  const nlohmann::json& aa = base["runs"][34];  // balls, --aa 2, demand:64, 8x8 cells
  EXPECT_EQ(aa["balance"], "demand:64");
  EXPECT_EQ(aa["aa"], 2);
  EXPECT_EQ(aa["link_messages"], 0);
  EXPECT_GT(base["runs"][30]["link_messages"].get<std::uint64_t>(), 0u);  // balls, --aa 2, dot, 8x8
}

TEST(CliBenchModes, AMovedFigureFailsWithOldNewAndRatio) {
  TempDir dir;
  nlohmann::json base = nlohmann::json::parse(read_file(kBaseline));
  nlohmann::json& run = base["runs"][10];  // balls, plain, dot mode, 8x8 cells
  ASSERT_EQ(run["model"], "balls");
  ASSERT_EQ(run["mode"], "dot");
  ASSERT_EQ(run["cells"], "8x8");
  const std::uint64_t frame = run["frame_cycles"].get<std::uint64_t>();
  run["frame_cycles"] = frame * 2;
  {
    std::ofstream out(dir / "old.json");
    out << base.dump(2);
  }
  const auto r = run_capsim("bench modes" + kArgs + " --baseline " + (dir / "old.json"), dir);
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("1 figures differ from the baseline"), std::string::npos) << r.out;
  const std::string row = r.out.substr(r.out.find("balls dot 8x8 aa0"));
  EXPECT_NE(row.find("frame_cycles"), std::string::npos) << row;
  EXPECT_NE(row.find(std::to_string(frame * 2)), std::string::npos) << row;
  EXPECT_NE(row.find(std::to_string(frame)), std::string::npos) << row;
  EXPECT_NE(row.find("0.500000"), std::string::npos) << row;  // new / old

  // --update rewrites it as the run found it and summarises what moved.
  const auto u = run_capsim("bench modes" + kArgs + " --baseline " + (dir / "old.json") + " --update", dir);
  EXPECT_EQ(u.status, 0) << u.err;
  EXPECT_NE(u.out.find("rewritten; 1 figures moved"), std::string::npos) << u.out;
  EXPECT_EQ(nlohmann::json::parse(read_file(dir / "old.json")), nlohmann::json::parse(read_file(kBaseline)));
}

TEST(CliBenchModes, RefusesAMissingBaselineWithoutUpdate) {
  TempDir dir;
  const auto r = run_capsim("bench modes" + kArgs + " --baseline " + (dir / "none.json"), dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("none.json: no such file (write one with --update)"), std::string::npos) << r.err;
}

TEST(ModesBench, ComparisonNamesRunsOnlyOneSideHasAndRefusesAnotherScreen) {
  const nlohmann::json run = {{"model", "balls"}, {"mode", "dot"}, {"cells", "4x4"}, {"aa", 0}, {"frame_cycles", 10}};
  nlohmann::json a = {{"size", "48x48"}, {"profile", "cap"}, {"runs", {run}}};
  nlohmann::json b = a;
  b["runs"][0]["cells"] = "8x8";
  const std::vector<MovedFigure> moved = compare_modes_bench(a, b);
  ASSERT_EQ(moved.size(), 2u);
  EXPECT_EQ(moved[0].run, "balls dot 4x4 aa0");
  EXPECT_EQ(moved[0].new_value, "absent");
  EXPECT_EQ(moved[1].run, "balls dot 8x8 aa0");
  EXPECT_EQ(moved[1].old_value, "absent");
  EXPECT_TRUE(compare_modes_bench(a, a).empty());
  b = a;
  b["size"] = "64x64";
  EXPECT_THROW(compare_modes_bench(a, b), std::runtime_error);
}

}  // namespace
}  // namespace capsim::sim
