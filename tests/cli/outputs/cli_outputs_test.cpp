// The outputs of `render` and `simulate`: every path is checked before any work
// (a different file each, not an input, not a directory, in a directory that
// exists and can be written), all are written under temporary names and put in
// place only once all are complete, and a write error names the real reason.

#include "support/cli_run.h"

#include <sys/stat.h>

using namespace capsim::testing;

namespace {

const std::string kBalls = scene_path("balls.csg");

struct OutputCase {
  std::string name;
  std::string options;  // D stands for the test's directory
  std::string message;  // the whole line printed after "capsim simulate: ", D as above
};
void PrintTo(const OutputCase& c, std::ostream* os) { *os << c.options; }

std::string in_dir(std::string text, const std::string& dir) {
  for (auto at = text.find("D/"); at != std::string::npos; at = text.find("D/", at + dir.size()))
    text.replace(at, 1, dir);
  return text;
}

class CliOutputRefused : public ::testing::TestWithParam<OutputCase> {};

// The scene file is broken too: refusing with the output's message (status
// 2) rather than the scene's (status 1) shows the outputs were checked before
// the scene was read.
TEST_P(CliOutputRefused, BeforeAnyWorkWithNothingWritten) {
  TempDir dir;
  std::filesystem::create_directory(dir / "folder");
  std::filesystem::create_directory(dir / "folder.png");
  std::ofstream(dir / "plain") << "a file\n";
  std::ofstream(dir / "broken.csg") << "sphere(;\n";
  const std::vector<std::string> before = directory_entries(dir.path());
  const RunResult r = run_capsim("simulate " + (dir / "broken.csg") + " --size 8x8 " + in_dir(GetParam().options, dir.path().string()), dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "capsim simulate: " + in_dir(GetParam().message, dir.path().string()) + "\n");
  EXPECT_EQ(directory_entries(dir.path()), before);
  EXPECT_EQ(read_file(dir / "plain"), "a file\n");
}

INSTANTIATE_TEST_SUITE_P(
    Simulate, CliOutputRefused,
    ::testing::Values(
        OutputCase{"ReportIsADirectory", "-o D/s.png --report D/folder", "--report D/folder: is a directory"},
        OutputCase{"HeatmapIsADirectory", "-o D/s.png --heatmap D/folder.png", "--heatmap D/folder.png: is a directory"},
        OutputCase{"TraceEndsInASlash", "-o D/s.png --trace D/folder/", "--trace D/folder/: names a directory, not a file"},
        OutputCase{"ScreenAndHeatmapAreOneFile", "-o D/out.png --heatmap D/out.png",
                   "--heatmap D/out.png is the same file as --output: every output needs a file of its own"},
        OutputCase{"ReportAndTraceAreOneFileByAnotherName", "-o D/s.png --report D/r.json --trace D/folder/../r.json",
                   "--trace D/folder/../r.json is the same file as --report: every output needs a file of its own"},
        OutputCase{"ReportIsTheScene", "-o D/s.png --report D/broken.csg",
                   "--report D/broken.csg is an input of the command; writing it would replace it"},
        OutputCase{"DirectoryMissing", "-o D/s.png --report D/missing/r.json",
                   "--report D/missing/r.json: directory D/missing does not exist"},
        OutputCase{"DirectoryIsAFile", "-o D/plain/s.png", "--output D/plain/s.png: D/plain is not a directory"}),
    [](const ::testing::TestParamInfo<OutputCase>& info) { return info.param.name; });

TEST(CliOutputs, AnOutputInADirectoryThatCannotBeWrittenIsRefusedWithTheReason) {
  // No one may create files in /proc, root included.
  TempDir dir;
  const RunResult r = run_capsim("render " + kBalls + " -o /proc/capsim-out.png --size 8x8", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.rfind("capsim render: --output /proc/capsim-out.png: cannot create a file in /proc: ", 0), 0u) << r.err;
  EXPECT_FALSE(std::filesystem::exists("/proc/capsim-out.png"));
}

TEST(CliOutputs, ASuccessfulRunLeavesItsOutputsAndNothingElse) {
  TempDir dir;
  const RunResult r = run_capsim("simulate " + kBalls + " -o " + (dir / "s.png") + " --size 8x8 --report " + (dir / "r.json") +
                                     " --trace " + (dir / "t.json") + " --heatmap " + (dir / "h.png"), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(directory_entries(dir.path()), (std::vector<std::string>{"h.png", "r.json", "s.png", "t.json"}));
}

TEST(CliOutputs, ExistingOutputsAreReplacedOnlyWhenAllAreComplete) {
  TempDir dir;
  std::ofstream(dir / "s.png") << "old screen";
  std::ofstream(dir / "r.json") << "old report";
  // The screen fits under the file-size limit; the report does not.
  const RunResult r = run_capsim("simulate " + kBalls + " -o " + (dir / "s.png") + " --size 8x8 --report " + (dir / "r.json"),
                                 dir, "ulimit -f 2; trap '' XFSZ;");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(read_file(dir / "s.png"), "old screen");
  EXPECT_EQ(read_file(dir / "r.json"), "old report");
  EXPECT_EQ(directory_entries(dir.path()), (std::vector<std::string>{"r.json", "s.png"}));
}

// A write that fails (here a file-size limit, with SIGXFSZ ignored so that the
// write returns EFBIG) names the output and the system's reason, and leaves
// none of the outputs, not even those written before it.
TEST(CliOutputs, AWriteErrorNamesTheReasonAndLeavesNoOutput) {
  TempDir dir;
  const std::string limit = "ulimit -f 2; trap '' XFSZ;";  // 1 KiB (dash) or 2 KiB (bash)
  // The 8x8 screen fits under the limit; the report, written next, does not.
  RunResult r = run_capsim("simulate " + kBalls + " -o " + (dir / "s.png") + " --size 8x8 --report " + (dir / "r.json") +
                               " --heatmap " + (dir / "h.png"), dir, limit);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "capsim: " + (dir / "r.json") + ": File too large\n");
  EXPECT_EQ(directory_entries(dir.path()), std::vector<std::string>{});

  r = run_capsim("simulate " + kBalls + " -o " + (dir / "s.png") + " --size 8x8 --heatmap " + (dir / "h.png"), dir, limit);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "capsim: " + (dir / "h.png") + ": File too large\n");
  EXPECT_EQ(directory_entries(dir.path()), std::vector<std::string>{});

  r = run_capsim("render " + kBalls + " -o " + (dir / "b.png") + " --size 64x64", dir, limit);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "capsim: " + (dir / "b.png") + ": File too large\n");
  EXPECT_EQ(directory_entries(dir.path()), std::vector<std::string>{});

  // OpenEXR's message names the file it wrote: the output, not its temporary name.
  r = run_capsim("render " + kBalls + " -o " + (dir / "b.exr") + " --size 64x64", dir, limit);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err.rfind("capsim: " + (dir / "b.exr") + ": ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("File too large"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find(".tmp"), std::string::npos) << r.err;
  EXPECT_EQ(directory_entries(dir.path()), std::vector<std::string>{});
}

}  // namespace
