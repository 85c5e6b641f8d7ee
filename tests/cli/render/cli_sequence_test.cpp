// Sequences on the command line: several scene files are the frames of one
// run, written under OpenSCAD's numbering; simulate's frames equal render's;
// nothing is written when any frame fails; one camera frames the sequence.

#include "support/cli_run.h"
#include "support/html_page.h"

#include "capsim/scene/parser.h"
#include "capsim/trace/prepared_scene.h"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <fstream>

using namespace capsim::testing;

namespace {

// Frame k of a small animation: a sphere moving right, without a camera.
std::string frame_text(int k) {
  return "light(position = [5, -20, 20], color = [1, 1, 1]);\n"
         "union() {\n  translate([" + std::to_string(k) + ", 0, 0]) sphere(r = 1);\n"
         "  translate([0, 0, -2]) cube([6, 3, 0.5]);\n}\n";
}

std::string write_frames(const TempDir& dir, int count) {
  std::string files;
  for (int k = 0; k < count; ++k) {
    const std::string path = dir / fmt::format("f{}.csg", k);
    std::ofstream(path) << frame_text(k);
    files += fmt::format(" {}", path);
  }
  return files;
}

TEST(CliSequence, FramesAreWrittenUnderOpenScadNumbering) {
  TempDir dir;
  const std::string files = write_frames(dir, 3);
  const RunResult r = run_capsim("render" + files + " -o " + (dir / "out.png") + " --size 32x24", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* name : {"out00000.png", "out00001.png", "out00002.png"})
    EXPECT_TRUE(std::filesystem::exists(dir / name)) << name;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
  EXPECT_FALSE(std::filesystem::exists(dir / "out00003.png"));
  EXPECT_NE(read_file(dir / "out00000.png"), read_file(dir / "out00002.png"));  // the sphere moved
}

TEST(CliSequence, SimulatedFramesEqualRenderedFramesInEveryDistribution) {
  TempDir dir;
  const std::string files = write_frames(dir, 5);
  const std::string opts = " --size 40x30 --aa 1";
  ASSERT_EQ(run_capsim("render" + files + opts + " -o " + (dir / "r.png"), dir).status, 0);
  for (const std::string extra : {"", " --frame-average"}) {
    const RunResult r = run_capsim("simulate" + files + opts + " --cells 2x2 -o " + (dir / "s.png") + " --report " +
                                       (dir / "s.json") + extra,
                                   dir);
    ASSERT_EQ(r.status, 0) << r.err;
    for (int k = 0; k < 5; ++k) {
      const std::string n = "0000" + std::to_string(k) + ".png";
      EXPECT_EQ(read_file(dir / ("s" + n)), read_file(dir / ("r" + n))) << "frame " << k << extra;
    }
    const nlohmann::json report = nlohmann::json::parse(read_file(dir / "s.json"));
    EXPECT_EQ(report["frames"].size(), 5u);
    EXPECT_EQ(report["sequence"]["frame_average"], !extra.empty());
    EXPECT_EQ(report["units"].size(), extra.empty() ? 5u : 2u);  // groups of 2 x 2 frames
    EXPECT_NE(r.out.find("Table 4-5 form, 5 frames:"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(extra.empty() ? "antialiasing" : "frame-averaged antialiasing"), std::string::npos);
  }
}

TEST(CliSequence, AFrameThatFailsLeavesNoFrameWritten) {
  TempDir dir;
  std::string files = write_frames(dir, 2);
  std::ofstream(dir / "bad.csg") << "sphere(r = -1);\n";
  files += fmt::format(" {}", dir / "bad.csg");
  for (const std::string cmd : {"render", "simulate"}) {
    const RunResult r = run_capsim(cmd + files + " -o " + (dir / "out.png") + " --size 16x16", dir);
    EXPECT_EQ(r.status, 1) << cmd;
    EXPECT_NE(r.err.find("bad.csg:1:"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out00000.png")) << cmd;
  }
}

// A sequence's time is labelled as the whole run's, with its mean per frame
// (and, frame averaged, per group), in the text report, the JSON and the page,
// whose title names the sequence rather than its last file.
TEST(CliSequence, TimesAreLabelledPerFrameAndInAllAndThePageNamesTheSequence) {
  TempDir dir;
  const std::string files = write_frames(dir, 4);
  for (const std::string extra : {"", " --frame-average"}) {
    const RunResult r = run_capsim("simulate" + files + " --size 24x18 --cells 1x2 -o " + (dir / "s.png") +
                                       " --report " + (dir / "s.json") + " --html " + (dir / "s.html") + extra,
                                   dir);
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json report = nlohmann::json::parse(read_file(dir / "s.json"));
    const double total = report["total_cycles"].get<double>() / report["clock_hz"].get<double>();
    EXPECT_DOUBLE_EQ(report["sequence"]["total_seconds"].get<double>(), total);
    EXPECT_DOUBLE_EQ(report["sequence"]["mean_frame_seconds"].get<double>(), total / 4);
    const std::string label =
        extra.empty() ? fmt::format("frames: 4, time per frame (mean) {:.3f} s, total {:.3f} s", total / 4, total)
                      : fmt::format("frames: 4 in 2 groups, time per group (mean) {:.3f} s, per frame (mean) {:.3f} "
                                    "s, total {:.3f} s",
                                    total / 2, total / 4, total);
    if (extra.empty()) {
      EXPECT_FALSE(report["sequence"].contains("groups"));
    } else {
      EXPECT_EQ(report["sequence"]["groups"], 2);
      EXPECT_DOUBLE_EQ(report["sequence"]["mean_group_seconds"].get<double>(), total / 2);
    }
    EXPECT_NE(r.out.find(label + " (" + report["total_cycles"].dump() + " cycles)\n"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("frame time"), std::string::npos) << r.out;
    const std::string page = read_file(dir / "s.html");
    EXPECT_NE(page.find("<td id=\"frame-time\">" + label + " ("), std::string::npos) << extra;
    EXPECT_NE(page.find(fmt::format("{:.3f} s per frame (mean)", total / 4)), std::string::npos) << extra;
    EXPECT_NE(page.find("<title>capsim: f0.csg ... f3.csg (4 frames), 1x2 cells, dot mode</title>"),
              std::string::npos)
        << extra;
    EXPECT_NE(page.find("<span class=\"scene\">f0.csg ... f3.csg (4 frames)</span>"), std::string::npos) << extra;
  }
}

TEST(CliSequence, FrameAveragingNeedsDotMode) {
  TempDir dir;
  const std::string files = write_frames(dir, 2);
  const RunResult r =
      run_capsim("simulate" + files + " -o " + (dir / "s.png") + " --mode line --frame-average", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--frame-average turns the dot pattern from frame to frame: it needs --mode dot"),
            std::string::npos)
      << r.err;
}

TEST(FrameSequence, FramesWithoutACameraShareTheOneThatFramesThemAll) {
  std::vector<capsim::PreparedScene> frames;
  capsim::PrepareOptions o;
  o.width = 32;
  o.height = 24;
  for (int k = 0; k < 3; ++k) frames.push_back(capsim::prepare_scene(capsim::parse_scene(frame_text(4 * k), "f.csg"), o));
  // With a camera of its own, a frame keeps it.
  frames.push_back(capsim::prepare_scene(
      capsim::parse_scene("camera(eye = [0, -30, 0], center = [0, 0, 0]);\n" + frame_text(1), "g.csg"), o));
  const capsim::Camera own = frames[3].camera;
  capsim::frame_sequence(frames);
  capsim::Aabb all;
  for (int k = 0; k < 4; ++k) all.extend(capsim::framed_bounds(frames[k]));
  const capsim::Camera shared = capsim::default_camera(all, 32, 24);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(frames[k].camera.eye, shared.eye) << k;
    EXPECT_EQ(frames[k].camera.center, shared.center) << k;
  }
  EXPECT_EQ(frames[3].camera.eye, own.eye);
}

}  // namespace
