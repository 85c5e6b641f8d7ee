// `capsim sweep`: every point run as `capsim simulate` runs it (the figures
// equal its --report's), the outputs (CSV, JSON and the HTML page) byte-identical for any --threads, a
// resumed sweep the same bytes as a fresh one with only the missing points
// run, and a bad sweep file named with the JSON path of its bad value.

#include "support/cli_run.h"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <regex>

using namespace capsim::testing;
using nlohmann::json;

namespace {

const std::string kScenes = std::string(CAPSIM_SOURCE_DIR) + "/scenes";

void write(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

// A sweep file in dir naming the shipped scenes by absolute path: 2 scenes x 2
// cell grids x 2 modes at 16x16.
std::string small_sweep(const TempDir& dir, const std::string& cells = R"(["4x4", "2x2"])") {
  const std::string file = dir / "small.json";
  write(file, R"({"axes": {"scenes": [")" + kScenes + R"(/balls.csg", ")" + kScenes +
                  R"(/chess.csg"], "cells": )" + cells + R"(, "modes": ["line", "dot"], "sizes": ["16x16"]}})");
  return file;
}

int count_of(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(CliSweep, WritesACsvAndJsonRecordPerPointInOrder) {
  TempDir dir;
  const RunResult r = run_capsim("sweep " + small_sweep(dir) + " -o " + (dir / "out"), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(count_of(r.err, "ran "), 8);
  EXPECT_NE(r.out.find("8 points (8 run, 0 kept from the earlier run)"), std::string::npos) << r.out;
  const std::string csv = read_file(dir / "out.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "scene,cells,mode,balance,aa,profile,size,grid,primary_only,frame_average,voxel_generation,frames,width,"
            "height,"
            "clock_hz,frame_cycles,frame_seconds,max_cycles,min_cycles,max_seconds,min_seconds,"
            "deviation_percent,busy_deviation_percent,speedup,bus_transfers,bus_bytes,bus_cycles,bus_seconds,"
            "link_messages,link_bytes,balance_bus_percent,tile_wait_cycles,chunks_stolen,steal_link_bytes,"
            "voxel_generation_cycles,voxel_bus_bytes,capsim_version");
  EXPECT_EQ(count_of(csv, "\n"), 9);
  const json doc = json::parse(read_file(dir / "out.json"));
  ASSERT_EQ(doc["points"].size(), 8u);
  const std::string version = run_capsim("--version", dir).out;  // "capsim VERSION\n"
  EXPECT_EQ("capsim " + doc["capsim_version"].get<std::string>() + "\n", version);
  EXPECT_EQ(doc["points"][0]["capsim_version"], doc["capsim_version"]);
  EXPECT_EQ(doc["points"][0]["cells"], "4x4");
  EXPECT_EQ(doc["points"][1]["cells"], "2x2");
  EXPECT_EQ(doc["points"][1]["mode"], "line");
  EXPECT_EQ(doc["points"][2]["mode"], "dot");
  EXPECT_EQ(doc["points"][4]["scene"], kScenes + "/chess.csg");
  // 2x2 is the fewest cells: its speed-up is 1, and 4x4's is against it.
  EXPECT_EQ(doc["points"][1]["speedup"], 1.0);
  EXPECT_DOUBLE_EQ(doc["points"][0]["speedup"].get<double>(),
                   doc["points"][1]["frame_cycles"].get<double>() / doc["points"][0]["frame_cycles"].get<double>());
}

TEST(CliSweep, WritesTheHtmlPageOfPlotsFromTheRecords) {
  TempDir dir;
  ASSERT_EQ(run_capsim("sweep " + small_sweep(dir) + " -o " + (dir / "out") + " --quiet", dir).status, 0);
  const std::string page = read_file(dir / "out.html");
  EXPECT_EQ(page.rfind("<!DOCTYPE html>", 0), 0u) << page.substr(0, 80);
  EXPECT_NE(page.find("<title>capsim sweep: small.json</title>"), std::string::npos);
  EXPECT_EQ(count_of(page, "<figure class=\"scene-plot\""), 2);
  EXPECT_NE(page.find("data-scene=\"chess.csg\" data-series=\"2\""), std::string::npos);
  const json points = json::parse(read_file(dir / "out.json"))["points"];
  const std::uint64_t cycles = points[7]["frame_cycles"];
  EXPECT_NE(page.find(fmt::format("<td data-value=\"{}\" title=", cycles)), std::string::npos);
}

TEST(CliSweep, FiguresEqualSimulatesReportOfTheSamePoint) {
  TempDir dir;
  ASSERT_EQ(run_capsim("sweep " + small_sweep(dir) + " -o " + (dir / "out") + " --quiet", dir).status, 0);
  const json points = json::parse(read_file(dir / "out.json"))["points"];
  struct Point {
    int index;
    std::string scene, cells, mode;
  };
  for (const Point& p : {Point{6, "chess", "4x4", "dot"}, Point{1, "balls", "2x2", "line"}}) {
    const json& point = points[p.index];
    ASSERT_EQ(point["cells"], p.cells);
    ASSERT_EQ(point["mode"], p.mode);
    const RunResult sim = run_capsim("simulate " + kScenes + "/" + p.scene + ".csg --size 16x16 --cells " + p.cells +
                                         " --mode " + p.mode + " -o " + (dir / "s.png") + " --report " +
                                         (dir / "r.json"),
                                     dir);
    ASSERT_EQ(sim.status, 0) << sim.err;
    const json report = json::parse(read_file(dir / "r.json"));
    EXPECT_EQ(point["frame_cycles"], report["total_cycles"]) << p.scene;
    EXPECT_EQ(point["max_seconds"], report["max_seconds"]);
    EXPECT_EQ(point["min_seconds"], report["min_seconds"]);
    EXPECT_EQ(point["deviation_percent"], report["deviation_percent"]);
    EXPECT_EQ(point["busy_deviation_percent"], report["busy_deviation_percent"]);
    EXPECT_EQ(point["clock_hz"], report["clock_hz"]);
  }
}

TEST(CliSweep, ADemandPointIsSimulatesBalanceDemandRun) {
  TempDir dir;
  const std::string file = dir / "balance.json";
  write(file, R"({"axes": {"scenes": [")" + kScenes + R"(/balls.csg"], "cells": ["2x2"], "modes": ["line", "dot"],)" +
                  R"( "balance": ["static", "demand:16"], "sizes": ["32x24"]}})");
  const RunResult r = run_capsim("sweep " + file + " -o " + (dir / "out") + " --quiet", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("3 points (3 run, 0 kept from the earlier run); 1 left out: 1 demand points repeated per mode"),
            std::string::npos)
      << r.out;
  const json points = json::parse(read_file(dir / "out.json"))["points"];
  ASSERT_EQ(points.size(), 3u);
  EXPECT_EQ(points[0]["balance"], "static");
  EXPECT_EQ(points[0]["balance_bus_percent"], 0.0);
  EXPECT_EQ(points[0]["tile_wait_cycles"], 0);
  const json& demand = points[2];
  EXPECT_EQ(demand["balance"], "demand:16");
  EXPECT_EQ(demand["mode"], "tiles");
  const RunResult sim = run_capsim("simulate " + kScenes + "/balls.csg --size 32x24 --cells 2x2 --balance demand:16 -o " +
                                       (dir / "s.png") + " --report " + (dir / "r.json"),
                                   dir);
  ASSERT_EQ(sim.status, 0) << sim.err;
  const json report = json::parse(read_file(dir / "r.json"));
  EXPECT_EQ(demand["frame_cycles"], report["total_cycles"]);
  EXPECT_EQ(demand["deviation_percent"], report["deviation_percent"]);
  EXPECT_EQ(demand["balance_bus_percent"], report["balancing"]["bus"]["occupancy_percent"]);
  std::uint64_t waits = 0;
  for (const json& cell : report["cells"]) waits += cell["tile_wait_cycles"].get<std::uint64_t>();
  EXPECT_EQ(demand["tile_wait_cycles"], waits);
  EXPECT_GT(demand["balance_bus_percent"].get<double>(), 0);
}

TEST(CliSweep, AStealPointIsSimulatesBalanceStealRunInItsMode) {
  TempDir dir;
  const std::string file = dir / "steal.json";
  write(file, R"({"axes": {"scenes": [")" + kScenes + R"(/balls.csg"], "cells": ["2x2"], "modes": ["block", "dot"],)" +
                  R"( "balance": ["steal:4"], "frame_average": [false, true], "sizes": ["32x24"]}})");
  const RunResult r = run_capsim("sweep " + file + " -o " + (dir / "out") + " --quiet", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("2 points (2 run, 0 kept from the earlier run); 2 left out: 2 frame_average with demand or "
                       "steal"),
            std::string::npos)
      << r.out;
  const json points = json::parse(read_file(dir / "out.json"))["points"];
  ASSERT_EQ(points.size(), 2u);
  const json& block = points[0];
  EXPECT_EQ(block["mode"], "block");
  EXPECT_EQ(block["balance"], "steal:4");
  const RunResult sim = run_capsim("simulate " + kScenes +
                                       "/balls.csg --size 32x24 --cells 2x2 --mode block --balance steal:4 -o " +
                                       (dir / "s.png") + " --report " + (dir / "r.json"),
                                   dir);
  ASSERT_EQ(sim.status, 0) << sim.err;
  const json report = json::parse(read_file(dir / "r.json"));
  EXPECT_EQ(block["frame_cycles"], report["total_cycles"]);
  EXPECT_EQ(block["chunks_stolen"], report["balancing"]["chunks_stolen"]);
  EXPECT_EQ(block["steal_link_bytes"], report["balancing"]["links"]["bytes"]);
  EXPECT_GT(block["chunks_stolen"].get<std::uint64_t>(), 0u);
}

TEST(CliSweep, OutputsDoNotDependOnTheThreads) {
  TempDir dir;
  const std::string spec = small_sweep(dir);
  ASSERT_EQ(run_capsim("sweep " + spec + " -o " + (dir / "one") + " --threads 1 --quiet", dir).status, 0);
  ASSERT_EQ(run_capsim("sweep " + spec + " -o " + (dir / "two") + " --threads 2 --quiet", dir).status, 0);
  EXPECT_EQ(read_file(dir / "one.csv"), read_file(dir / "two.csv"));
  EXPECT_EQ(read_file(dir / "one.json"), read_file(dir / "two.json"));
  EXPECT_EQ(read_file(dir / "one.html"), read_file(dir / "two.html"));
}

TEST(CliSweep, ResumeRunsOnlyTheMissingPointsAndWritesTheSameBytes) {
  TempDir dir;
  ASSERT_EQ(run_capsim("sweep " + small_sweep(dir) + " -o " + (dir / "fresh") + " --quiet", dir).status, 0);
  // A sweep of one cell grid first, then resumed with both.
  ASSERT_EQ(run_capsim("sweep " + small_sweep(dir, R"(["4x4"])") + " -o " + (dir / "part") + " --quiet", dir).status, 0);
  const RunResult resumed = run_capsim("sweep " + small_sweep(dir) + " -o " + (dir / "part") + " --resume", dir);
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  EXPECT_EQ(count_of(resumed.err, "ran "), 4);
  EXPECT_EQ(count_of(resumed.err, "cells=2x2"), 4);
  EXPECT_NE(resumed.out.find("8 points (4 run, 4 kept from the earlier run)"), std::string::npos) << resumed.out;
  EXPECT_EQ(read_file(dir / "part.csv"), read_file(dir / "fresh.csv"));
  EXPECT_EQ(read_file(dir / "part.json"), read_file(dir / "fresh.json"));
  EXPECT_EQ(read_file(dir / "part.html"), read_file(dir / "fresh.html"));
  // Nothing is left to run.
  const RunResult again = run_capsim("sweep " + small_sweep(dir) + " -o " + (dir / "part") + " --resume", dir);
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_EQ(count_of(again.err, "ran "), 0);
  EXPECT_EQ(read_file(dir / "part.json"), read_file(dir / "fresh.json"));
}

// Not the stem alone: run from the sweep file's directory, STEM.json would be
// the sweep file itself.
TEST(CliSweep, DefaultPrefixIsTheSweepFilesStemWithResultsInTheCurrentDirectory) {
  TempDir dir;
  const std::string spec = small_sweep(dir, R"(["1x1"])");
  const RunResult r = run_program_in(dir.path(), CAPSIM_EXE, "sweep small.json --quiet", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_EQ(r.out,
            "small-results.csv, small-results.json, small-results.html: 4 points (4 run, 0 kept from the earlier "
            "run)\n");
  EXPECT_TRUE(std::filesystem::exists(dir / "small-results.csv"));
  EXPECT_TRUE(std::filesystem::exists(dir / "small-results.json"));
  EXPECT_TRUE(std::filesystem::exists(dir / "small-results.html"));
}

TEST(CliSweep, FrameAverageOutsideDotModeIsLeftOutAndSaid) {
  TempDir dir;
  write(dir / "fa-spec.json", R"({"axes": {"scenes": [{"scene": ")" + kScenes +
                             R"(/balls.csg", "frames": 2}], "cells": ["1x2"], "modes": ["block", "dot"], )"
                             R"("sizes": ["16x16"], "frame_average": [false, true]}})");
  const RunResult r = run_capsim("sweep " + (dir / "fa-spec.json") + " -o " + (dir / "fa") + " --quiet", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("3 points (3 run, 0 kept from the earlier run); 1 left out: 1 frame_average outside dot mode"),
            std::string::npos)
      << r.out;
  const json doc = json::parse(read_file(dir / "fa.json"));
  EXPECT_EQ(doc["points"][2]["frame_average"], true);
  EXPECT_EQ(doc["points"][2]["frames"], 2);
}

TEST(CliSweep, ABadSweepFileNamesTheValueAndWritesNothing) {
  TempDir dir;
  write(dir / "bad.json", R"({"axes": {"scenes": [")" + kScenes + R"(/balls.csg"], "cells": ["4x4", "8x8", "9x99"]}})");
  const RunResult r = run_capsim("sweep " + (dir / "bad.json") + " -o " + (dir / "bad"), dir);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, (dir / "bad.json") + ": axes.cells[2]: \"9x99\" is out of range (accepted: 1x1 to 32x32)\n");
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.csv"));
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.json.csv"));
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.html"));
}

TEST(CliSweep, UsageErrorsExitWithTwo) {
  TempDir dir;
  const RunResult none = run_capsim("sweep", dir);
  EXPECT_EQ(none.status, 2);
  EXPECT_EQ(none.err.rfind("capsim sweep: ", 0), 0u) << none.err;
  const RunResult threads = run_capsim("sweep " + small_sweep(dir) + " --threads -1", dir);
  EXPECT_EQ(threads.status, 2) << threads.err;
}

TEST(CliSweep, AResumeFromAFileThatIsNotASweepFails) {
  TempDir dir;
  write(dir / "out.json", "[1, 2]");
  const RunResult r = run_capsim("sweep " + small_sweep(dir, R"(["1x1"])") + " -o " + (dir / "out") + " --resume", dir);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("cannot resume from it: not a sweep's JSON"), std::string::npos) << r.err;
  EXPECT_EQ(read_file(dir / "out.json"), "[1, 2]");
  EXPECT_FALSE(std::filesystem::exists(dir / "out.csv"));
  EXPECT_FALSE(std::filesystem::exists(dir / "out.html"));
}

}  // namespace
