// Usage errors of the command line: every one exits with status 2 and prints one
// line that names the option (or command) at fault and what it accepts; nothing
// is written. Scene errors keep status 1 (cli_render_test.cpp).

#include "support/cli_run.h"

using namespace capsim::testing;

namespace {

const std::string kBalls = scene_path("balls.csg");
const std::string kScenes = std::filesystem::path(kBalls).parent_path().string();

struct UsageCase {
  // OUT stands for a path in the test's directory, BALLS for scenes/balls.csg
  // and SCENES for the scenes/ directory.
  std::string args;     // after "capsim"
  std::string message;  // the whole line printed, without its newline
};
void PrintTo(const UsageCase& c, std::ostream* os) { *os << c.args; }

std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

class CliUsageError : public ::testing::TestWithParam<UsageCase> {};

TEST_P(CliUsageError, ExitsTwoWithOneLineNamingTheOptionAndItsRange) {
  TempDir dir;
  const auto in_test = [&](const std::string& text) {
    return replace_all(replace_all(replace_all(text, "OUT", dir / "out"), "BALLS", kBalls), "SCENES", kScenes);
  };
  const RunResult r = run_capsim(in_test(GetParam().args), dir);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.err, in_test(GetParam().message) + "\n");
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 0) << "something was written";
}

const char* const kSizeRange = "(accepted: WxH, W and H whole numbers from 1 to 16384, e.g. 640x480)";
const char* const kGridRange = "(accepted: 1 to 256, or auto)";
const char* const kThreadsRange = "(accepted: 0 to 1024; 0 = all hardware threads)";
const char* const kFramesRange = "(accepted: 1 to 99999, with one scene file)";
const char* const kCellsRange = "(accepted: RxC, R and C whole numbers from 1 to 32, e.g. 8x8)";

std::string with(const std::string& a, const std::string& b) { return a + " " + b; }

std::string case_name(const ::testing::TestParamInfo<UsageCase>& info) {
  std::string name;
  for (char c : info.param.args) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return name.empty() ? "no_arguments" : name;
}

INSTANTIATE_TEST_SUITE_P(
    Commands, CliUsageError,
    ::testing::Values(
        UsageCase{"", "capsim: a command is required (accepted: render, simulate, lattice, repro, bench, calibrate, sweep; capsim --help describes them)"},
        UsageCase{"rendr BALLS -o OUT.png",
                  "capsim: unknown command rendr; did you mean render? (accepted: render, simulate, lattice, repro, bench, calibrate, sweep)"},
        UsageCase{"sim BALLS -o OUT.png",
                  "capsim: unknown command sim; did you mean simulate? (accepted: render, simulate, lattice, repro, bench, calibrate, sweep)"},
        UsageCase{"draw BALLS", "capsim: unknown command draw (accepted: render, simulate, lattice, repro, bench, calibrate, sweep)"},
        UsageCase{"--threads 2 render BALLS -o OUT.png",
                  "capsim render: --threads is an option of render: give it after the command's name"},
        UsageCase{"--fast", "capsim: unknown option --fast (capsim itself takes only --help and --version; give "
                            "options after the command: render, simulate, lattice, repro, bench, calibrate, sweep)"}),
    case_name);

INSTANTIATE_TEST_SUITE_P(
    Render, CliUsageError,
    ::testing::Values(
        UsageCase{"render", "capsim render: SCENE is required (accepted: one or more scene files in the CSG "
                            "grammar of docs/scene-format.md (several are the frames of a sequence))"},
        UsageCase{"render BALLS", "capsim render: -o/--output is required (accepted: a path ending in .png or .exr)"},
        UsageCase{"render BALLS -o OUT.jpg",
                  "capsim render: --output OUT.jpg has an unsupported image type (accepted: a path ending in "
                  ".png or .exr)"},
        UsageCase{"render BALLS -o OUT.png --size", with("capsim render: --size needs a value", kSizeRange)},
        UsageCase{"render BALLS -o OUT.png --size 100", with("capsim render: --size 100 is not WxH", kSizeRange)},
        UsageCase{"render BALLS -o OUT.png --size 64x", with("capsim render: --size 64x is not WxH", kSizeRange)},
        UsageCase{"render BALLS -o OUT.png --size 0x10", with("capsim render: --size 0x10 is out of range", kSizeRange)},
        UsageCase{"render BALLS -o OUT.png --size 16385x16",
                  with("capsim render: --size 16385x16 is out of range", kSizeRange)},
        UsageCase{"render BALLS -o OUT.png --size 16x99999999999",
                  with("capsim render: --size 16x99999999999 is out of range", kSizeRange)},
        UsageCase{"render BALLS -o OUT.png --size 8x8 --size 9x9",
                  with("capsim render: --size is given more than once", kSizeRange)},
        UsageCase{"render BALLS -o OUT.png --grid many", with("capsim render: --grid many is not a whole number", kGridRange)},
        UsageCase{"render BALLS -o OUT.png --grid 0", with("capsim render: --grid 0 is out of range", kGridRange)},
        UsageCase{"render BALLS -o OUT.png --grid 257", with("capsim render: --grid 257 is out of range", kGridRange)},
        UsageCase{"render BALLS -o OUT.png --threads -1", with("capsim render: --threads -1 is out of range", kThreadsRange)},
        UsageCase{"render BALLS -o OUT.png --threads 1.5",
                  with("capsim render: --threads 1.5 is not a whole number", kThreadsRange)},
        UsageCase{"render BALLS -o OUT.png --threads 100000",
                  with("capsim render: --threads 100000 is out of range", kThreadsRange)},
        UsageCase{"render BALLS -o OUT.png --threads 99999999999999999999",
                  with("capsim render: --threads 99999999999999999999 is out of range", kThreadsRange)},
        UsageCase{"render BALLS -o OUT.png --primary-only=abc",
                  "capsim render: --primary-only abc is not a valid value (accepted: no value, or true or false)"},
        UsageCase{"render BALLS -o OUT.png --treads 2",
                  "capsim render: unknown option --treads; did you mean --threads? (capsim render --help lists "
                  "every option)"},
        UsageCase{"render BALLS -o OUT.png --cells 2x2",
                  "capsim render: unknown option --cells (capsim render --help lists every option)"},
        UsageCase{"render BALLS -o OUT.png --aa 9",
                  "capsim render: --aa 9 is out of range (accepted: 0 to 8; 0 = one sample at each pixel centre)"},
        UsageCase{"render BALLS -o OUT.png --frames", with("capsim render: --frames needs a value", kFramesRange)},
        UsageCase{"render BALLS -o OUT.png --frames 0", with("capsim render: --frames 0 is out of range", kFramesRange)},
        UsageCase{"render BALLS -o OUT.png --frames 100000",
                  with("capsim render: --frames 100000 is out of range", kFramesRange)},
        UsageCase{"render BALLS -o OUT.png --frames 2.5",
                  with("capsim render: --frames 2.5 is not a whole number", kFramesRange)},
        UsageCase{"render BALLS BALLS -o OUT.png --frames 4",
                  "capsim render: --frames animates one scene file, not a sequence of 2 (the files of a sequence "
                  "already are its frames)"}),
    case_name);

INSTANTIATE_TEST_SUITE_P(
    Simulate, CliUsageError,
    ::testing::Values(
        UsageCase{"simulate", "capsim simulate: SCENE is required (accepted: one or more scene files in the CSG "
                              "grammar of docs/scene-format.md (several are the frames of a sequence))"},
        UsageCase{"simulate BALLS --size 8x8",
                  "capsim simulate: -o/--output is required (accepted: a path ending in .png or .exr)"},
        UsageCase{"simulate BALLS -o OUT.png --size x8", with("capsim simulate: --size x8 is not WxH", kSizeRange)},
        UsageCase{"simulate BALLS -o OUT.png --grid -3", with("capsim simulate: --grid -3 is out of range", kGridRange)},
        UsageCase{"simulate BALLS -o OUT.png --threads ''",
                  with("capsim simulate: --threads '' is not a whole number", kThreadsRange)},
        UsageCase{"simulate BALLS -o OUT.png --cells 0x8", with("capsim simulate: --cells 0x8 is out of range", kCellsRange)},
        UsageCase{"simulate BALLS -o OUT.png --cells 33x1", with("capsim simulate: --cells 33x1 is out of range", kCellsRange)},
        UsageCase{"simulate BALLS -o OUT.png --cells 8by8", with("capsim simulate: --cells 8by8 is not RxC", kCellsRange)},
        UsageCase{"simulate BALLS -o OUT.png --cells", with("capsim simulate: --cells needs a value", kCellsRange)},
        UsageCase{"simulate BALLS BALLS BALLS -o OUT.png --frames 2",
                  "capsim simulate: --frames animates one scene file, not a sequence of 3 (the files of a sequence "
                  "already are its frames)"},
        UsageCase{"simulate BALLS -o OUT.png --frames -1", with("capsim simulate: --frames -1 is out of range", kFramesRange)},
        UsageCase{"simulate BALLS -o OUT.png --mode diagonal",
                  "capsim simulate: --mode diagonal is not a pixel mode (accepted: block, line or dot)"},
        UsageCase{"simulate BALLS -o OUT.png --profile no-such-profile",
                  "capsim simulate: --profile no-such-profile is neither a built-in profile nor a readable file "
                  "(accepted: cap, m380 or a profile JSON file as docs/simulation.md describes)"},
        UsageCase{"simulate BALLS -o OUT.png --heatmap OUT.jpg",
                  "capsim simulate: --heatmap OUT.jpg is not a .png path (accepted: a path ending in .png)"},
        UsageCase{"simulate BALLS -o OUT.png --report", "capsim simulate: --report needs a value (accepted: a file path)"},
        UsageCase{"simulate BALLS -o OUT.png --trace", "capsim simulate: --trace needs a value (accepted: a file path)"},
        UsageCase{"simulate BALLS -o OUT.png --cell 2x2",
                  "capsim simulate: unknown option --cell; did you mean --cells? (capsim simulate --help lists "
                  "every option)"}),
    case_name);

// The paper's tools: `lattice`, `repro`, `calibrate` and `bench modes` check their options
// and outputs the same way, before any run.
INSTANTIATE_TEST_SUITE_P(
    Tools, CliUsageError,
    ::testing::Values(
        UsageCase{"lattice 0 -o OUT.csg",
                  "capsim lattice: spheres 0 is out of range (accepted: a whole number from 1 to 1000000)"},
        UsageCase{"lattice 16 -o OUT.csg --size 0x9", with("capsim lattice: --size 0x9 is out of range", kSizeRange)},
        UsageCase{"lattice 16 -o OUT/none/x.csg",
                  "capsim lattice: --output OUT/none/x.csg: directory OUT/none does not exist"},
        UsageCase{"lattice 16 -o OUT.csg extra",
                  "capsim lattice: unexpected argument extra (capsim lattice --help lists what it takes)"},
        UsageCase{"repro --scenes SCENES --disb-frames 65",
                  "capsim repro: --disb-frames 65 is out of range (accepted: 0 to 64; 0 = leave Table 4-5 not run)"},
        UsageCase{"repro --scenes SCENES --threads 2000",
                  with("capsim repro: --threads 2000 is out of range", kThreadsRange)},
        UsageCase{"repro --scenes OUT", "capsim repro: --scenes OUT is not a directory (accepted: a directory holding "
                                        "the shipped models (balls.csg, chess.csg, ..., disb/))"},
        UsageCase{"repro --scenes SCENES -o OUT/none/r.md",
                  "capsim repro: --output OUT/none/r.md: directory OUT/none does not exist"},
        UsageCase{"repro --scenes SCENES --cap-size 384", with("capsim repro: --cap-size 384 is not WxH", kSizeRange)},
        UsageCase{"repro --scenes SCENES -o r.md --images . --json OUT/none/r.json",
                  "capsim repro: --json OUT/none/r.json: directory OUT/none does not exist"},
        UsageCase{"calibrate --scenes SCENES --rounds 0",
                  "capsim calibrate: --rounds 0 is out of range (accepted: 1 to 20)"},
        UsageCase{"calibrate --scenes SCENES --profiles OUT/none",
                  "capsim calibrate: --profiles (cap.json) OUT/none/cap.json: directory OUT/none does not exist"},
        UsageCase{"bench", "capsim bench: a benchmark is required (accepted: modes)"},
        UsageCase{"bench mods", "capsim bench: unknown command mods; did you mean modes? (accepted: modes)"},
        UsageCase{"bench modes --bogus",
                  "capsim bench modes: unknown option --bogus (capsim bench modes --help lists every option)"},
        UsageCase{"bench modes --scenes SCENES --size 3", with("capsim bench modes: --size 3 is not WxH", kSizeRange)},
        UsageCase{"bench modes --scenes SCENES --threads -1",
                  with("capsim bench modes: --threads -1 is out of range", kThreadsRange)},
        UsageCase{"bench modes --scenes SCENES --plot OUT.png",
                  "capsim bench modes: --plot OUT.png does not end in .svg (accepted: a path ending in .svg)"},
        UsageCase{"bench modes --scenes SCENES --baseline OUT.json",
                  "capsim bench modes: --baseline OUT.json: no such file (write one with --update)"},
        UsageCase{"bench modes --scenes SCENES --update",
                  "capsim bench modes: --update needs --baseline FILE, the baseline to write"},
        UsageCase{"bench modes --scenes SCENES --update --baseline OUT.json --json OUT/none/a.json",
                  "capsim bench modes: --json OUT/none/a.json: directory OUT/none does not exist"}),
    case_name);

// Values at the edge of what each check takes: plain decimals only (010 is
// ten, not eight), no NaN, the exact names of modes, a regular file for a
// profile.
INSTANTIATE_TEST_SUITE_P(
    Values, CliUsageError,
    ::testing::Values(
        UsageCase{"render BALLS -o OUT.png --aa 010",
                  "capsim render: --aa 010 is out of range (accepted: 0 to 8; 0 = one sample at each pixel centre)"},
        UsageCase{"render BALLS -o OUT.png --aa +1",
                  "capsim render: --aa +1 is not a whole number (accepted: 0 to 8; 0 = one sample at each pixel "
                  "centre)"},
        UsageCase{"render BALLS -o OUT.png --threads 0x10",
                  with("capsim render: --threads 0x10 is not a whole number", kThreadsRange)},
        UsageCase{"render BALLS -o OUT.png --grid AUTO", with("capsim render: --grid AUTO is not a whole number", kGridRange)},
        UsageCase{"render BALLS -o OUT.png --aa-threshold nan",
                  "capsim render: --aa-threshold nan is out of range (accepted: a number from 0 to 3)"},
        UsageCase{"render BALLS -o OUT.png --aa-threshold 0x1p0",
                  "capsim render: --aa-threshold 0x1p0 is not a number (accepted: a number from 0 to 3)"},
        UsageCase{"render BALLS -o OUT.png --size 8X0", with("capsim render: --size 8X0 is out of range", kSizeRange)},
        UsageCase{"simulate BALLS -o OUT.png --mode DOT",
                  "capsim simulate: --mode DOT is not a pixel mode (accepted: block, line or dot)"},
        UsageCase{"simulate BALLS -o OUT.png --profile /dev/null",
                  "capsim simulate: --profile /dev/null is neither a built-in profile nor a readable file "
                  "(accepted: cap, m380 or a profile JSON file as docs/simulation.md describes)"},
        UsageCase{"repro --scenes BALLS", "capsim repro: --scenes BALLS is not a directory (accepted: a directory "
                                          "holding the shipped models (balls.csg, chess.csg, ..., disb/))"}),
    case_name);

// Several faults: the words first (an unknown option, one without its value,
// one given twice), then each command's values in the order it reads them,
// whatever the order they were typed in.
INSTANTIATE_TEST_SUITE_P(
    Order, CliUsageError,
    ::testing::Values(
        UsageCase{"render BALLS -o OUT.png --threads abc --treads 2",
                  "capsim render: unknown option --treads; did you mean --threads? (capsim render --help lists "
                  "every option)"},
        UsageCase{"render BALLS -o OUT.png --size 0x1 --grid 3 --grid 4",
                  with("capsim render: --grid is given more than once", kGridRange)},
        UsageCase{"render BALLS -o OUT.png --size 0x1 --size 2x2", with("capsim render: --size is given more than once", kSizeRange)},
        UsageCase{"render BALLS -o OUT.png --threads abc --aa", "capsim render: --aa needs a value (accepted: 0 to 8; "
                                                                "0 = one sample at each pixel centre)"},
        UsageCase{"render --threads abc", "capsim render: SCENE is required (accepted: one or more scene files in the "
                                          "CSG grammar of docs/scene-format.md (several are the frames of a sequence))"},
        UsageCase{"render BALLS BALLS --frames 0", "capsim render: --frames animates one scene file, not a sequence of 2 "
                                                   "(the files of a sequence already are its frames)"},
        UsageCase{"render BALLS --frames 0 --size 0x1", with("capsim render: --frames 0 is out of range", kFramesRange)},
        UsageCase{"render BALLS --threads abc", "capsim render: -o/--output is required (accepted: a path ending in .png "
                                                "or .exr)"},
        UsageCase{"render BALLS -o OUT.jpg --size 0x1",
                  "capsim render: --output OUT.jpg has an unsupported image type (accepted: a path ending in "
                  ".png or .exr)"},
        UsageCase{"render BALLS -o OUT.png --aa-threshold 4 --aa 9 --max-memory 0 --threads x --grid 0",
                  with("capsim render: --grid 0 is out of range", kGridRange)},
        UsageCase{"simulate BALLS -o OUT.png --frame-average --mode block --heatmap OUT.jpg",
                  "capsim simulate: --heatmap OUT.jpg is not a .png path (accepted: a path ending in .png)"},
        UsageCase{"simulate BALLS -o OUT.png --heatmap OUT.jpg --profile nope --mode bad --cells 0x8 --aa 9",
                  "capsim simulate: --aa 9 is out of range (accepted: 0 to 8; 0 = one sample at each pixel centre)"},
        UsageCase{"simulate BALLS -o OUT.png --heatmap OUT.jpg --profile nope --mode bad --cells 0x8",
                  with("capsim simulate: --cells 0x8 is out of range", kCellsRange)},
        UsageCase{"lattice 0", "capsim lattice: --output is required"},
        UsageCase{"repro --scenes OUT --disb-frames 99 --threads x --size 0x1",
                  with("capsim repro: --size 0x1 is out of range", kSizeRange)},
        UsageCase{"repro --scenes OUT --disb-frames 99 --threads x", with("capsim repro: --threads x is not a whole number", kThreadsRange)},
        UsageCase{"repro --scenes OUT --disb-frames 99",
                  "capsim repro: --disb-frames 99 is out of range (accepted: 0 to 64; 0 = leave Table 4-5 not run)"},
        UsageCase{"bench modes --plot OUT.png --scenes OUT --threads x",
                  with("capsim bench modes: --threads x is not a whole number", kThreadsRange)},
        UsageCase{"bench modes --plot OUT.png --scenes OUT",
                  "capsim bench modes: --scenes OUT is not a directory (accepted: a directory holding the shipped "
                  "models (balls.csg, chess.csg, ..., disb/))"}),
    case_name);

}  // namespace

TEST(CliUsage, HelpComesBeforeAnyValueIsChecked) {
  TempDir dir;
  const RunResult r = run_capsim("render " + kBalls + " --threads abc --aa 99 --help", dir);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("--threads TEXT=0 "), std::string::npos) << r.out;
  EXPECT_EQ(r.err, "");
}

TEST(CliUsage, HelpStatesRangesInWordsNotTheChecksDescriptions) {
  // What each option accepts is attached to it for the messages; the help
  // keeps its own sentences and CLI11's TEXT.
  TempDir dir;
  for (const std::string command : {"render", "simulate", "lattice", "repro", "bench modes"}) {
    const RunResult r = run_capsim(command + " --help", dir);
    EXPECT_EQ(r.status, 0) << command;
    EXPECT_EQ(r.out.find("accepted"), std::string::npos) << command;
    EXPECT_EQ(r.out.find("TEXT:"), std::string::npos) << command;
  }
}

TEST(CliUsage, ProfileThatIsADirectoryIsAUsageError) {
  TempDir dir;
  const RunResult r = run_capsim("simulate " + kBalls + " -o " + (dir / "s.png") + " --profile " + dir.path().string(), dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "capsim simulate: --profile " + dir.path().string() +
                       " is neither a built-in profile nor a readable file (accepted: cap, m380 or a profile JSON "
                       "file as docs/simulation.md describes)\n");
}

TEST(CliUsage, TheLargestThreadCountRunsWithoutAWarning) {
  // More threads than the host has run as many as it has: TBB is never asked
  // for more workers than it can give, so it prints nothing.
  TempDir dir;
  for (const std::string command : {"render", "simulate"}) {
    const RunResult r = run_capsim(command + " " + kBalls + " -o " + (dir / "out.png") + " --size 16x16 --threads 1024", dir);
    EXPECT_EQ(r.status, 0) << command;
    EXPECT_EQ(r.err, "") << command;
  }
}

TEST(CliUsage, HelpAndVersionStillExitZero) {
  TempDir dir;
  for (const std::string args : {"--help", "render --help", "simulate --help", "--version"}) {
    const RunResult r = run_capsim(args, dir);
    EXPECT_EQ(r.status, 0) << args;
    EXPECT_NE(r.out, "") << args;
    EXPECT_EQ(r.err, "") << args;
  }
}
