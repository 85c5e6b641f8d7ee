// --quiet: only the summary and errors. simulate keeps the header's first line,
// Max, Min and d, the busy-only spread and the frame time (and, for a sequence,
// the Table 4-5 form); bench modes its verdict; repro the report written and
// each target; no progress on stderr, not even the percentage on a terminal.

#include "support/cli_run.h"

#include <chrono>
#include <cstdlib>
#include <sstream>

using namespace capsim::testing;

namespace {

const std::string kBalls = scene_path("balls.csg");
const std::string kScenes = std::string(CAPSIM_SOURCE_DIR) + "/scenes";

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

bool holds_line(const std::vector<std::string>& all, const std::string& line) {
  return std::find(all.begin(), all.end(), line) != all.end();
}

TEST(CliQuiet, SimulateOn32x32CellsPrintsAHandfulOfLines) {
  TempDir dir;
  const std::string args = "simulate " + kBalls + " --size 32x32 --cells 32x32 -o ";
  const RunResult full = run_capsim(args + (dir / "full.png"), dir);
  ASSERT_EQ(full.status, 0) << full.err;
  const std::vector<std::string> all = lines(full.out);
  EXPECT_GT(all.size(), 1000u);

  const RunResult quiet = run_capsim(args + (dir / "quiet.png") + " --quiet", dir);
  ASSERT_EQ(quiet.status, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "");
  const std::vector<std::string> summary = lines(quiet.out);
  ASSERT_EQ(summary.size(), 4u) << quiet.out;
  EXPECT_EQ(summary[0], "CAP simulation: 32x32 cells, dot mode, profile cap (8000000 Hz), 32x32 pixels");
  EXPECT_EQ(summary[1].rfind("Max ", 0), 0u);
  EXPECT_EQ(summary[2].rfind("busy only ", 0), 0u);
  EXPECT_EQ(summary[3].rfind("frame time ", 0), 0u);
  for (const std::string& line : summary) EXPECT_TRUE(holds_line(all, line)) << line;
  EXPECT_EQ(read_file(dir / "quiet.png"), read_file(dir / "full.png"));
}

TEST(CliQuiet, ASequenceAlsoGivesTheTable45Form) {
  TempDir dir;
  const std::string args = "simulate " + kBalls + " --size 16x16 --cells 2x2 --frames 2 -o " + (dir / "s.png");
  const RunResult full = run_capsim(args, dir);
  ASSERT_EQ(full.status, 0) << full.err;
  const RunResult quiet = run_capsim(args + " --quiet", dir);
  ASSERT_EQ(quiet.status, 0) << quiet.err;
  const std::vector<std::string> summary = lines(quiet.out);
  ASSERT_EQ(summary.size(), 7u) << quiet.out;
  EXPECT_EQ(summary[4], "Table 4-5 form, 2 frames:");
  for (const std::string& line : summary) EXPECT_TRUE(holds_line(lines(full.out), line)) << line;
}

TEST(CliQuiet, BenchModesPrintsOnlyItsVerdict) {
  TempDir dir;
  const std::string args = "bench modes --size 48x48 --scenes " + kScenes + " --baseline " +
                           std::string(CAPSIM_SOURCE_DIR) + "/bench/baselines/modes-48x48.json";
  const RunResult full = run_capsim(args, dir);
  ASSERT_EQ(full.status, 0) << full.err;
  EXPECT_NE(full.err.find("balls block 4x4 aa0"), std::string::npos) << full.err;  // a line per run
  const RunResult quiet = run_capsim(args + " --quiet", dir);
  ASSERT_EQ(quiet.status, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "");
  ASSERT_EQ(lines(quiet.out).size(), 1u) << quiet.out;
  EXPECT_NE(quiet.out.find("all 200 runs identical to the baseline"), std::string::npos) << quiet.out;
}

TEST(CliQuiet, ReproLeavesOutItsTimedProgress) {
  TempDir dir;
  const std::string args = "repro --size 16x16 --disb-frames 1 --scenes " + kScenes + " -o " + (dir / "r.md") +
                           " --images " + dir.path().string();
  const RunResult full = run_capsim(args, dir);
  ASSERT_EQ(full.status, 0) << full.err;
  EXPECT_EQ(full.err.rfind("[", 0), 0u) << full.err;
  const RunResult quiet = run_capsim(args + " --quiet", dir);
  ASSERT_EQ(quiet.status, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "");
  EXPECT_EQ(quiet.out.rfind(dir / "r.md" + ": written (", 0), 0u) << quiet.out;
  const std::vector<std::string> summary = lines(quiet.out), all = lines(full.out);
  ASSERT_EQ(summary.size(), all.size());
  for (std::size_t k = 1; k < summary.size(); ++k) EXPECT_EQ(summary[k], all[k]);  // line 0 holds the time
}

// A render of a few seconds (4096 x 4096 of chess, one thread) on a terminal:
// util-linux's script gives the run one (a pseudo-terminal). What the
// terminal showed, and the exit status.
struct TerminalRun {
  int status;
  std::string shown;
};
TerminalRun render_on_a_terminal(const TempDir& dir, const std::string& options) {
  const std::string command = std::string(CAPSIM_EXE) + " render " + scene_path("chess.csg") +
                              " --size 4096x4096 --threads 1 -o " + (dir / "c.png") + options;
  const std::string run = "script -qec '" + command + "' /dev/null >" + (dir / "tty") + " 2>&1";
  const int status = std::system(run.c_str());
  return {status, read_file(dir / "tty")};
}

// Progress shows on a terminal after the first second.
TEST(CliQuiet, RenderOnATerminalShowsNoPercentage) {
  if (std::system("command -v script >/dev/null 2>&1") != 0) GTEST_SKIP() << "no script(1) to give a terminal";
  TempDir dir;
  const auto started = std::chrono::steady_clock::now();
  const TerminalRun plain = render_on_a_terminal(dir, "");
  const bool long_enough = std::chrono::steady_clock::now() - started > std::chrono::seconds(2);
  EXPECT_EQ(plain.status, 0);
  const TerminalRun quiet = render_on_a_terminal(dir, " --quiet");
  EXPECT_EQ(quiet.status, 0);
  EXPECT_EQ(quiet.shown, "");
  if (!long_enough) GTEST_SKIP() << "the render took under 2 s, too short to show progress without --quiet";
  EXPECT_NE(plain.shown.find("rendering: "), std::string::npos) << plain.shown;
}

// --timings' line comes after the progress's last, on a line of its own.
TEST(CliQuiet, RenderOnATerminalEndsWithTheTimings) {
  if (std::system("command -v script >/dev/null 2>&1") != 0) GTEST_SKIP() << "no script(1) to give a terminal";
  TempDir dir;
  const auto started = std::chrono::steady_clock::now();
  const TerminalRun run = render_on_a_terminal(dir, " --timings");
  const bool long_enough = std::chrono::steady_clock::now() - started > std::chrono::seconds(2);
  ASSERT_EQ(run.status, 0);
  const std::string& shown = run.shown;
  const std::size_t timings = shown.rfind("timings (wall clock): read ");
  ASSERT_NE(timings, std::string::npos) << shown;
  EXPECT_TRUE(timings == 0 || shown[timings - 1] == '\n') << shown;
  EXPECT_EQ(shown.find('\n', timings), shown.size() - 1) << "ends the output, as one line";
  if (!long_enough) GTEST_SKIP() << "the render took under 2 s, too short to show progress";
  const std::size_t done = shown.find("rendering: done");
  ASSERT_NE(done, std::string::npos) << shown;
  EXPECT_LT(done, timings);
}

}  // namespace
