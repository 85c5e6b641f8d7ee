// `capsim simulate --html`: the page holds the same run's --report and --trace
// JSON and its screen byte for byte, whatever the screen's format; only the
// host's wall time changes from run to run; a missing directory fails before
// any work.

#include "support/cli_run.h"
#include "support/html_page.h"

#include <gtest/gtest.h>

using namespace capsim::testing;

namespace {

const std::string kBalls = scene_path("balls.csg");

// The page without its one varying figure, the host's wall time.
std::string without_wall_time(const std::string& page) {
  const std::string open = "<td id=\"host-time\">";
  const std::size_t at = page.find(open);
  if (at == std::string::npos) return page;
  return page.substr(0, at + open.size()) + page.substr(page.find("</td>", at));
}

TEST(CliSimulateHtml, PageHoldsTheRunsReportTraceAndScreenByteForByte) {
  TempDir dir;
  for (const std::string args : {" --cells 3x4 --mode line", " --cells 2x2 --mode dot --aa 1"}) {
    for (const std::string screen : {"s.png", "s.exr"}) {
      const RunResult r = run_capsim("simulate " + kBalls + " -o " + (dir / screen) + " --size 48x36" + args +
                                         " --report " + (dir / "r.json") + " --trace " + (dir / "t.json") +
                                         " --html " + (dir / "r.html"),
                                     dir);
      ASSERT_EQ(r.status, 0) << r.err;
      const std::string page = read_file(dir / "r.html");
      EXPECT_EQ(unescape_block(data_block_text(page, "report-data")), read_file(dir / "r.json")) << args << screen;
      EXPECT_EQ(unescape_block(data_block_text(page, "trace-data")), read_file(dir / "t.json")) << args << screen;
      if (screen == "s.png") {
        const std::vector<unsigned char> png = from_base64(image_data_uri(page, "screen-0"));
        EXPECT_EQ(std::string(png.begin(), png.end()), read_file(dir / "s.png")) << args;
      }
    }
  }
}

TEST(CliSimulateHtml, OnlyTheHostWallTimeChangesFromRunToRun) {
  TempDir dir;
  std::string first;
  for (int run = 0; run < 2; ++run) {
    const RunResult r = run_capsim("simulate " + kBalls + " -o " + (dir / "s.png") +
                                       " --size 40x30 --cells 2x3 --html " + (dir / "r.html"),
                                   dir);
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string page = read_file(dir / "r.html");
    EXPECT_NE(page.find("<td id=\"host-time\">"), std::string::npos);
    EXPECT_NE(page.find("--cells 2x3 --mode dot --profile cap"), std::string::npos);  // the command
    if (run == 0) {
      first = without_wall_time(page);
    } else {
      EXPECT_TRUE(without_wall_time(page) == first);
    }
  }
}

TEST(CliSimulateHtml, MissingDirectoryFailsBeforeAnyOutput) {
  TempDir dir;
  const RunResult r = run_capsim("simulate " + kBalls + " -o " + (dir / "s.png") + " --size 8x8 --html " +
                                     (dir / "no-such-dir/r.html"),
                                 dir);
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "s.png"));
}

}  // namespace
