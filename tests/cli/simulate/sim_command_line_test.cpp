// The command line an HTML page gives for its run (sim::simulate_command,
// every option) repeats the run: run again, it writes the same report, byte
// for byte, and so does the short form with only the changed options (but for
// the provenance's record of how each was typed and of its output files:
// every option's effective value is the same).

#include "paper/simulate_command.h"
#include "support/cli_run.h"
#include "support/provenance.h"

#include <gtest/gtest.h>

namespace {

using namespace capsim::testing;
using capsim::sim::CommandForm;
using capsim::sim::simulate_command;
using capsim::sim::SimulateSettings;

// The command the page gives (these tests' paths hold nothing that HTML
// escapes).
std::string page_command(const std::string& page) {
  const std::string open = "<code>capsim simulate ";
  const std::size_t at = page.find(open);
  if (at == std::string::npos) return "";
  const std::size_t start = at + std::string("<code>").size();
  return page.substr(start, page.find("</code>", start) - start);
}

std::string runnable(const std::string& command) {
  EXPECT_EQ(command.rfind("capsim ", 0), 0u) << command;
  return command.substr(std::string("capsim ").size());
}

struct Case {
  std::string name;
  SimulateSettings settings;  // the scenes and the output are the test's
};

class SimulateCommandLine : public ::testing::TestWithParam<Case> {};

TEST_P(SimulateCommandLine, RepeatsTheRunToTheByte) {
  TempDir dir;
  SimulateSettings s = GetParam().settings;
  s.output = dir / "s.png";
  // Run as the page's own command gives it, with a report and the page.
  const std::string args = runnable(simulate_command(s, CommandForm::EveryOption));
  RunResult r = run_capsim(args + " --report " + (dir / "first.json") + " --html " + (dir / "p.html"), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string first = without_argv_and(read_file(dir / "first.json"), {"report", "html"});
  // The page gives the same command: the builder's, every option.
  EXPECT_EQ(page_command(read_file(dir / "p.html")), simulate_command(s, CommandForm::EveryOption));
  for (const CommandForm form : {CommandForm::EveryOption, CommandForm::NonDefaults}) {
    r = run_capsim(runnable(simulate_command(s, form)) + " --report " + (dir / "again.json"), dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(without_argv_and(read_file(dir / "again.json"), {"report", "html"}), first)
        << simulate_command(s, form);
  }
}

SimulateSettings settings(std::vector<std::string> scenes, int width, int height) {
  SimulateSettings s;
  s.scenes = std::move(scenes);
  s.width = width;
  s.height = height;
  return s;
}

std::vector<Case> cases() {
  std::vector<Case> all;
  all.push_back({"Defaults", settings({scene_path("balls.csg")}, 32, 24)});
  SimulateSettings changed = settings({scene_path("chess.csg")}, 40, 30);
  changed.grid = 6;
  changed.cells = {2, 3};
  changed.mode = capsim::sim::PixelMode::Line;
  changed.primary_only = true;
  changed.aa = {1, 0.5};
  changed.threads = 2;
  all.push_back({"EverySingleFrameSetting", changed});
  SimulateSettings animated = settings({std::string(CAPSIM_SOURCE_DIR) + "/tests/data/anim/model.scad"}, 24, 24);
  animated.frames = 3;
  animated.cells = {2, 2};
  animated.aa.depth = 1;
  animated.frame_average = true;
  all.push_back({"AnimatedFrameAveraged", animated});
  SimulateSettings m380 = settings({scene_path("piston.csg")}, 32, 32);
  m380.cells = {1, 1};
  m380.profile = "m380";
  m380.grid = 16;
  all.push_back({"Mainframe", m380});
  return all;
}

INSTANTIATE_TEST_SUITE_P(Runs, SimulateCommandLine, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& info) { return info.param.name; });

}  // namespace
