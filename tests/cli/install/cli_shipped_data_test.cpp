// `bench modes`, `repro` and `calibrate` run from any directory: the build's
// capsim finds the source tree's models and baselines by itself
// (src/cli/shipped_data.h), writes only into the current directory or where
// its options say, and never into the source tree unless told to. A capsim
// away from both its build directory and a share/capsim finds no models and
// says where it looked.

#include "support/cli_run.h"

#include <nlohmann/json.hpp>

using namespace capsim::testing;

namespace {

namespace fs = std::filesystem;

const fs::path kSource = fs::weakly_canonical(CAPSIM_SOURCE_DIR);

// capsim run with dir as its current directory.
RunResult run_in(const TempDir& dir, const std::string& args) {
  return run_program_in(dir.path(), CAPSIM_EXE, args, dir);
}

// Run as run_in does, it is refused with this usage error and writes nothing.
void expect_refused(const TempDir& dir, const std::string& args, const std::string& message) {
  const RunResult r = run_in(dir, args);
  EXPECT_EQ(r.status, 2) << args;
  EXPECT_EQ(r.err, message + "\n");
  EXPECT_TRUE(files_under(dir.path()).empty()) << args;
}

TEST(ShippedData, BenchModesFindsTheModelsAndTheBaselineFromAnyDirectory) {
  TempDir dir;
  const RunResult r = run_in(dir, "bench modes --size 48x48");
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_TRUE(r.out.ends_with((kSource / "bench/baselines/modes-48x48.json").string() +
                              ": all 200 runs identical to the baseline\n"))
      << r.out;
  EXPECT_TRUE(files_under(dir.path()).empty());
}

TEST(ShippedData, BenchModesAtASizeWithoutABaselineRunsWritesAndSaysSo) {
  TempDir dir;
  const RunResult r = run_in(dir, "bench modes --size 16x16 --json now.json --html modes.html");
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_TRUE(r.out.ends_with("no baseline for 16x16: not compared\n")) << r.out;
  EXPECT_NE(r.out.find("disb/f00000  dot       16x16   2"), std::string::npos) << r.out;
  EXPECT_EQ(files_under(dir.path()), (std::set<std::string>{"modes.html", "now.json"}));
  EXPECT_EQ(nlohmann::json::parse(read_file(dir / "now.json"))["size"], "16x16");
  EXPECT_NE(read_file(dir / "modes.html")
                .find("<p id=\"baseline\" class=\"baseline none\">No baseline for 16x16: not compared.</p>"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(kSource / "bench/baselines/modes-16x16.json"));
}

TEST(ShippedData, UpdateWritesOnlyTheBaselineItIsGiven) {
  TempDir dir;
  expect_refused(dir, "bench modes --size 16x16 --update",
                 "capsim bench modes: --update needs --baseline FILE, the baseline to write");

  const RunResult written = run_in(dir, "bench modes --size 16x16 --update --baseline mine.json");
  ASSERT_EQ(written.status, 0) << written.out << written.err;
  EXPECT_TRUE(written.out.ends_with("mine.json: written (200 runs)\n")) << written.out;
  EXPECT_EQ(files_under(dir.path()), (std::set<std::string>{"mine.json"}));
  EXPECT_FALSE(fs::exists(kSource / "bench/baselines/modes-16x16.json"));

  const RunResult compared = run_in(dir, "bench modes --size 16x16 --baseline mine.json");
  EXPECT_EQ(compared.status, 0) << compared.err;
  EXPECT_TRUE(compared.out.ends_with("mine.json: all 200 runs identical to the baseline\n")) << compared.out;
}

TEST(ShippedData, ReproWritesItsReportAndPlotsInTheCurrentDirectory) {
  TempDir dir;
  const fs::path project_report = kSource / "docs/reproduction.md";
  const fs::file_time_type before = fs::last_write_time(project_report);
  const RunResult r = run_in(dir, "repro --size 24x24 --disb-frames 1");
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_EQ(fs::last_write_time(project_report), before);
  EXPECT_TRUE(r.out.starts_with("reproduction.md: written")) << r.out;
  EXPECT_EQ(files_under(dir.path()), (std::set<std::string>{"images", "images/graph-4-3.svg",
                                                            "images/table-4-2.svg", "reproduction.md"}));
  const std::string md = read_file(dir / "reproduction.md");
  EXPECT_NE(md.find("](images/table-4-2.svg)"), std::string::npos);
  // Its commands name the models it found.
  EXPECT_NE(md.find((kSource / "scenes/chess.csg").string()), std::string::npos);
}

TEST(ShippedData, ARefusedReproLeavesNoImagesDirectoryBehind) {
  TempDir dir;
  expect_refused(dir, "repro --size 24x24 --json none/r.json",
                 "capsim repro: --json none/r.json: directory none does not exist");
}

TEST(ShippedData, CalibrateFindsTheModelsFromAnyDirectory) {
  TempDir dir;
  // Its scenes are looked for before its threads are checked.
  const RunResult r = run_in(dir, "calibrate --threads 2000");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.err.starts_with("capsim calibrate: --threads 2000 is out of range")) << r.err;
  EXPECT_TRUE(files_under(dir.path()).empty());
}

TEST(ShippedData, AProgramAwayFromItsBuildAndAShareDirectoryFindsNoModels) {
  TempDir dir;
  fs::create_directories(dir.path() / "bin");
  fs::copy_file(CAPSIM_EXE, dir.path() / "bin/capsim");
  const std::string copy = (dir.path() / "bin/capsim").string();
  const RunResult r = run_program_in(dir.path(), copy, "bench modes --size 16x16", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "capsim bench modes: --scenes is needed: the shipped models are not in " +
                       (fs::weakly_canonical(dir.path()) / "share/capsim/scenes").string() +
                       " (accepted: a directory holding the shipped models (balls.csg, chess.csg, ..., disb/))\n");
  // An explicit --scenes still runs it.
  const RunResult given =
      run_program_in(dir.path(), copy, "bench modes --size 4x4 --scenes " + (kSource / "scenes").string(), dir);
  EXPECT_EQ(given.status, 0) << given.err;
  EXPECT_TRUE(given.out.ends_with("no baseline for 4x4: not compared\n")) << given.out;
}

}  // namespace
