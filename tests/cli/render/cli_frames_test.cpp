// --frames K: one scene file with $t, animated as `openscad --animate K`
// animates it. Its frames match the frames of OpenSCAD's own exports of the
// same animation, go through the sequence pipeline (numbered outputs, one
// camera, simulate equal to render), and one frame is numbered too.

#include "support/cli_run.h"

#include <OpenImageIO/imageio.h>

#include <nlohmann/json.hpp>

#include <fmt/format.h>

#include <cstdlib>
#include <vector>

using namespace capsim::testing;

namespace {

const std::string kAnim = std::string(CAPSIM_SOURCE_DIR) + "/tests/data/anim";

// model.scad as a file capsim reads itself, evaluating $t at each frame.
std::string own_copy(const TempDir& dir) {
  std::filesystem::copy_file(kAnim + "/model.scad", dir / "model.csg");
  return dir / "model.csg";
}

std::vector<unsigned char> read_rgb8(const std::string& path, int& width, int& height) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) return {};
  const OIIO::ImageSpec& spec = in->spec();
  width = spec.width;
  height = spec.height;
  std::vector<unsigned char> px(static_cast<std::size_t>(width) * height * 3);
  in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, px.data());
  return px;
}

// Pixels that differ in any channel by any amount; -1 when the images cannot
// be compared.
int differing_pixels(const std::string& a, const std::string& b) {
  int wa = 0, ha = 0, wb = 0, hb = 0;
  const std::vector<unsigned char> pa = read_rgb8(a, wa, ha), pb = read_rgb8(b, wb, hb);
  if (pa.empty() || wa != wb || ha != hb) return -1;
  int n = 0;
  for (std::size_t i = 0; i < pa.size(); i += 3) {
    if (pa[i] != pb[i] || pa[i + 1] != pb[i + 1] || pa[i + 2] != pb[i + 2]) ++n;
  }
  return n;
}

// tests/data/anim/model.scad moves, turns and resizes a cube, a sphere and a
// cone with $t (lookup, sin, cos, `? :`); f00000.csg ... f00003.csg are what
// `openscad --animate 4 -o f.csg model.scad` (OpenSCAD 2021.01) exported from
// it, every value evaluated and printed to 6 significant digits. capsim reads
// the text of model.scad itself with --frames 4, as a copy named model.csg (a
// .scad file would go through OpenSCAD: cli_scad_test.cpp). Rounding to 6 digits moves an edge by up
// to 5e-6 of its size, which at 200x150 changed 0, 2, 0 and 0 pixels of the
// four frames, by 1/255 in one channel (`idiff -fail 0` of the two renders);
// the tolerance, 4 pixels of the 30,000 in any frame, is twice the most
// measured. A wrong $t, operator or function moves whole objects: hundreds of
// pixels.
TEST(CliFrames, FramesMatchOpenScadsAnimateExports) {
  TempDir dir;
  const std::string size = " --size 200x150";
  RunResult r = run_capsim("render --frames 4 " + own_copy(dir) + " -o " + (dir / "t.png") + size, dir);
  ASSERT_EQ(r.status, 0) << r.err;
  std::string exports;
  for (int k = 0; k < 4; ++k) exports += fmt::format(" {}/f{:05d}.csg", kAnim, k);
  r = run_capsim("render" + exports + " -o " + (dir / "o.png") + size, dir);
  ASSERT_EQ(r.status, 0) << r.err;
  constexpr int kTolerance = 4;
  for (int k = 0; k < 4; ++k) {
    const std::string ours = dir / fmt::format("t{:05d}.png", k);
    const int n = differing_pixels(ours, dir / fmt::format("o{:05d}.png", k));
    EXPECT_GE(n, 0) << "frame " << k;
    EXPECT_LE(n, kTolerance) << "frame " << k;
    // The animation does move: consecutive frames differ widely.
    if (k > 0) {
      EXPECT_GT(differing_pixels(ours, dir / fmt::format("t{:05d}.png", k - 1)), 500) << k;
    }
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "t00004.png"));
}

// simulate --frames runs the same frames as render --frames, one per $t, and
// reports them as a sequence.
TEST(CliFrames, SimulateRunsTheFramesRenderDoes) {
  TempDir dir;
  const std::string scene = dir / "s.csg";
  std::ofstream(scene) << "translate([4 * $t, 0, 0]) sphere(r = 1);\ncube([6, 3, 0.5], center = true);\n";
  const std::string opts = " --frames 3 --size 40x30";
  ASSERT_EQ(run_capsim("render " + scene + opts + " -o " + (dir / "r.png"), dir).status, 0);
  const RunResult r = run_capsim(
      "simulate " + scene + opts + " --cells 2x2 -o " + (dir / "s.png") + " --report " + (dir / "s.json"), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  for (int k = 0; k < 3; ++k) {
    const std::string n = fmt::format("{:05d}.png", k);
    EXPECT_EQ(read_file(dir / ("s" + n)), read_file(dir / ("r" + n))) << "frame " << k;
  }
  EXPECT_NE(read_file(dir / "r00000.png"), read_file(dir / "r00002.png"));  // the sphere moved
  const nlohmann::json report = nlohmann::json::parse(read_file(dir / "s.json"));
  EXPECT_EQ(report["frames"].size(), 3u);
  EXPECT_NE(r.out.find("Table 4-5 form, 3 frames:"), std::string::npos) << r.out;
}

// The reports and traces of an animation are the same bytes on 1 and 2 host
// threads, but for the provenance's record of the command line (its outputs'
// names and --threads): every frame's scene is parsed from the same text at
// its own $t.
TEST(CliFrames, ReportsAndTracesDoNotDependOnHostThreads) {
  TempDir dir;
  const std::string run = "simulate " + own_copy(dir) + " --frames 3 --size 32x24 --cells 2x2 --aa 1";
  std::string report[2], trace[2];
  for (int threads = 1; threads <= 2; ++threads) {
    const std::string tag = std::to_string(threads);
    const RunResult r = run_capsim(run + " --threads " + tag + " -o " + (dir / ("s" + tag + ".png")) + " --report " +
                                       (dir / ("r" + tag + ".json")) + " --trace " + (dir / ("t" + tag + ".json")),
                                   dir);
    ASSERT_EQ(r.status, 0) << r.err;
    nlohmann::json j = nlohmann::json::parse(read_file(dir / ("r" + tag + ".json")));
    EXPECT_EQ(j["provenance"]["options"]["threads"], threads);
    EXPECT_EQ(j["provenance"]["options"]["frames"], 3);
    j["provenance"].erase("argv");
    j["provenance"]["options"] = nullptr;
    report[threads - 1] = j.dump(2);
    trace[threads - 1] = read_file(dir / ("t" + tag + ".json"));
  }
  EXPECT_FALSE(report[0].empty());
  EXPECT_EQ(report[0], report[1]);
  EXPECT_EQ(trace[0], trace[1]);
}

// The page of an animation names the one file and the frame count; the text
// report labels the time per frame and in all.
TEST(CliFrames, PageOfAnAnimationNamesTheFileAndItsFrames) {
  TempDir dir;
  const RunResult r = run_capsim("simulate " + kAnim + "/model.scad --frames 3 --size 16x12 --cells 1x2 -o " +
                                     (dir / "s.png") + " --html " + (dir / "s.html"),
                                 dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string page = read_file(dir / "s.html");
  EXPECT_NE(page.find("<title>capsim: model.scad (3 frames), 1x2 cells, dot mode</title>"), std::string::npos);
  EXPECT_NE(r.out.find("frames: 3, time per frame (mean) "), std::string::npos) << r.out;
}

// As with `openscad --animate 1`, one frame is still numbered.
TEST(CliFrames, OneFrameIsNumbered) {
  TempDir dir;
  const RunResult r =
      run_capsim("render --frames 1 " + own_copy(dir) + " -o " + (dir / "one.png") + " --size 20x15", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "one00000.png"));
  EXPECT_FALSE(std::filesystem::exists(dir / "one.png"));
}

// An error in an expression names its place and leaves nothing written,
// whichever frame's $t it shows up at (here the third: sqrt(-0.1)).
TEST(CliFrames, AnErrorAtOneFrameLeavesNothingWritten) {
  TempDir dir;
  const std::string scene = dir / "bad.csg";
  std::ofstream(scene) << "sphere(r = $t < 0.5 ? 1 : sqrt(0.4 - $t));\n";
  const RunResult r = run_capsim("render " + scene + " --frames 4 -o " + (dir / "b.png") + " --size 8x8", dir);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, scene + ":1:12: the expression gives nan, not a finite number; every number must be finite\n");
  EXPECT_FALSE(std::filesystem::exists(dir / "b00000.png"));
}

}  // namespace
