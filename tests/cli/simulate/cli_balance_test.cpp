// `capsim simulate --balance`: static is the run as before; demand[:TILE]
// and steal[:CHUNK] give render's screen, report the balancing, record the
// scheme, and refuse what they do not model before writing anything.

#include "support/cli_run.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>

using namespace capsim::testing;

namespace {

const std::string kBalls = scene_path("balls.csg");

TEST(CliBalance, DemandScreenIsRendersAndTheReportsSayHowItWasShared) {
  TempDir dir;
  ASSERT_EQ(run_capsim("render " + kBalls + " -o " + (dir / "r.png") + " --size 40x30", dir).status, 0);
  for (const std::string threads : {"1", "2"}) {
    const RunResult r = run_capsim("simulate " + kBalls + " -o " + (dir / "s.png") +
                                       " --size 40x30 --cells 2x3 --balance demand:16 --threads " + threads +
                                       " --report " + (dir / "r.json"),
                                   dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(read_file(dir / "s.png"), read_file(dir / "r.png")) << threads;
    EXPECT_NE(r.out.find("2x3 cells, balanced on demand in tiles of 16 pixels"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("balanced on demand: 80 tiles of at most 4x4 pixels"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(" tiles  requests tile waits"), std::string::npos) << r.out;
    const nlohmann::json report = nlohmann::json::parse(read_file(dir / "r.json"));
    EXPECT_EQ(report["provenance"]["options"]["balance"], "demand:16");
    const nlohmann::json& b = report["balancing"];
    EXPECT_EQ(b["tile_pixels"], 16);
    EXPECT_EQ(b["tile_side"], 4);
    ASSERT_EQ(b["tile_cells"].size(), 1u);
    EXPECT_EQ(b["tile_cells"][0].size(), 80u);
    EXPECT_EQ(b["host"]["grants"], 80);
    EXPECT_EQ(b["host"]["no_tile"], 6);
    std::uint64_t tiles = 0;
    for (const auto& c : report["cells"]) tiles += c["tiles"].get<std::uint64_t>();
    EXPECT_EQ(tiles, 80u);
  }
}

// Antialiased, tiles trace their own corners: the screen is still render's.
TEST(CliBalance, AntialiasedDemandScreenIsRenders) {
  TempDir dir;
  ASSERT_EQ(run_capsim("render " + kBalls + " -o " + (dir / "r.png") + " --size 30x20 --aa 2", dir).status, 0);
  const RunResult r = run_capsim("simulate " + kBalls + " -o " + (dir / "s.png") +
                                     " --size 30x20 --cells 2x2 --aa 2 --balance demand:9 --quiet",
                                 dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read_file(dir / "s.png"), read_file(dir / "r.png"));
}

// A static run reports as it did before --balance existed: no balancing
// section, no "balance" among the options.
TEST(CliBalance, StaticReportsHaveNoBalancing) {
  TempDir dir;
  for (const std::string balance : {"", " --balance static"}) {
    const RunResult r = run_capsim("simulate " + kBalls + " -o " + (dir / "s.png") + " --size 16x12 --cells 2x2" +
                                       balance + " --report " + (dir / "r.json"),
                                   dir);
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json report = nlohmann::json::parse(read_file(dir / "r.json"));
    EXPECT_FALSE(report.contains("balancing"));
    EXPECT_FALSE(report["provenance"]["options"].contains("balance"));
    EXPECT_FALSE(report["cells"][0].contains("tiles"));
    EXPECT_NE(r.out.find("2x2 cells, dot mode"), std::string::npos);
  }
}

TEST(CliBalance, StealScreenIsRendersInEveryModeAndTheReportsSayWhatWasStolen) {
  TempDir dir;
  for (const std::string aa : {"0", "2"}) {
    ASSERT_EQ(run_capsim("render " + kBalls + " -o " + (dir / "r.png") + " --size 40x30 --aa " + aa, dir).status, 0);
    for (const std::string mode : {"block", "line", "dot"})
      for (const std::string threads : {"1", "2"}) {
        const std::string what = "aa " + aa + " " + mode + " threads " + threads;
        const RunResult r = run_capsim("simulate " + kBalls + " -o " + (dir / "s.png") +
                                           " --size 40x30 --cells 3x2 --balance steal:5 --aa " + aa + " --mode " + mode +
                                           " --threads " + threads + " --report " + (dir / "r.json"),
                                       dir);
        ASSERT_EQ(r.status, 0) << r.err;
        EXPECT_EQ(read_file(dir / "s.png"), read_file(dir / "r.png")) << what;
        EXPECT_NE(r.out.find("3x2 cells, " + mode + " mode, stealing chunks of 5 pixels"), std::string::npos)
            << r.out;
        EXPECT_NE(r.out.find("stealing: "), std::string::npos) << r.out;
        EXPECT_NE(r.out.find("  chunks   stolen    given   asked  refused"), std::string::npos) << r.out;
        const nlohmann::json report = nlohmann::json::parse(read_file(dir / "r.json"));
        EXPECT_EQ(report["provenance"]["options"]["balance"], "steal:5");
        EXPECT_EQ(report["mode"], mode);
        const nlohmann::json& b = report["balancing"];
        EXPECT_EQ(b["scheme"], "steal");
        EXPECT_EQ(b["chunk_pixels"], 5);
        std::uint64_t chunks = 0, stolen = 0, given = 0, bytes = 0;
        for (const auto& window : b["chunk_cells"][0]) chunks += window.size();
        for (const auto& c : report["cells"]) {
          stolen += c["chunks_stolen"].get<std::uint64_t>();
          given += c["chunks_given"].get<std::uint64_t>();
          bytes += c["steal_bytes"].get<std::uint64_t>();
        }
        EXPECT_EQ(b["chunks"], chunks) << what;
        EXPECT_EQ(b["chunks_stolen"], stolen) << what;
        EXPECT_EQ(stolen, given) << what;
        EXPECT_EQ(bytes, 2 * b["links"]["bytes"].get<std::uint64_t>()) << what << ": every byte sent and taken in";
      }
  }
}

TEST(CliBalance, RefusesWhatDemandDoesNotModelBeforeWritingAnything) {
  TempDir dir;
  const std::string base = "simulate " + kBalls + " -o " + (dir / "s.png") + " --size 16x12 --report " +
                           (dir / "r.json") + " ";
  const std::pair<std::string, std::string> cases[] = {
      {"--balance demand:16 --frame-average", "--balance demand:16 hands out the tiles of one frame at a time"},
      {"--balance demand --mode line", "--balance demand hands out tiles, which the window controllers show"},
      {"--balance demand:15", "--balance demand:15 is not a balance scheme (accepted: static, demand, demand:TILE"},
      {"--balance steal:0", "--balance steal:0 is not a balance scheme"},
      {"--balance steal --frame-average", "--balance steal takes chunks of one frame at a time"},
      {"--balance dynamic", "--balance dynamic is not a balance scheme"},
  };
  for (const auto& [args, message] : cases) {
    const RunResult r = run_capsim(base + args, dir);
    EXPECT_NE(r.status, 0) << args;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "s.png")) << args;
    EXPECT_FALSE(std::filesystem::exists(dir / "r.json")) << args;
  }
}

}  // namespace
