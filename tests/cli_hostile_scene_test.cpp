// `capsim render` on hostile scene files: each is refused with one located
// message (exit 1, nothing written) or rendered, never a crash, a cut message
// or a blank image with exit 0. Large inputs are generated here, not stored.

#include "cli_run.h"

#include <fstream>
#include <string>

using namespace capsim::testing;

namespace {

// Writes `text` as dir/name and returns its path.
std::string write_scene(const TempDir& dir, const std::string& name, const std::string& text) {
  const std::string path = dir / name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// Renders `scene` to a small PNG; the run must fail with exactly one line,
// `SCENE:LINE:COL: ...` (`SCENE: ...` where `where` is empty: the file as a
// whole) holding `fragment`, and leave no image.
::testing::AssertionResult RefusedAt(const TempDir& dir, const std::string& scene,
                                     const std::string& where, const std::string& fragment) {
  const std::string out = dir / "out.png";
  const RunResult r = run_capsim("render " + scene + " -o " + out + " --size 16x16", dir);
  const std::string prefix = scene + (where.empty() ? "" : ":" + where) + ": ";
  if (r.status != 1 || r.err.rfind(prefix, 0) != 0 || r.err.find(fragment) == std::string::npos ||
      r.err.find('\n') != r.err.size() - 1 || std::filesystem::exists(out)) {
    return ::testing::AssertionFailure() << "status " << r.status << ", stderr: " << r.err;
  }
  return ::testing::AssertionSuccess();
}

}  // namespace

TEST(CliHostileScene, QuotedStringsArePrintedWhole) {
  TempDir dir;
  using namespace std::string_literals;
  const std::string scene = write_scene(dir, "nul.csg", "cube();\ncolor(\"re\0d\xFF\") cube();"s);
  EXPECT_TRUE(RefusedAt(dir, scene, "2:7",
                        R"(unknown colour "re\0d\xFF"; use a CSS/SVG colour )"
                        R"(name (e.g. "red", "steelblue"), "#rgb", "#rgba", "#rrggbb", "#rrggbbaa" or )"
                        R"(a vector [r, g, b] / [r, g, b, a] of numbers in [0, 1])"));
}

namespace {

std::string repeated(const std::string& text, int times) {
  std::string out;
  for (int i = 0; i < times; ++i) out += text;
  return out;
}

}  // namespace

// Nesting past the documented 1000 levels is refused where it passes the
// limit (it overflowed the stack: exit 139, no message); 1000 levels render.
TEST(CliHostileScene, DeepNestingIsRefusedOrRendered) {
  TempDir dir;
  const std::string deep =
      write_scene(dir, "deep.csg", repeated("union() {", 5000) + "sphere(1);" + repeated("}", 5000));
  EXPECT_TRUE(RefusedAt(dir, deep, "1:9009", "nesting deeper than 1000 levels is not supported"));
  const std::string blocks = write_scene(dir, "blocks.csg", repeated("{", 3000));
  EXPECT_TRUE(RefusedAt(dir, blocks, "1:1001", "nesting deeper than 1000 levels is not supported"));

  const std::string limit = write_scene(
      dir, "limit.csg",
      repeated("difference() {\n sphere(1);\n", 1000) + "sphere(1);\n" + repeated("}", 1000));
  const RunResult r = run_capsim("render " + limit + " -o " + (dir / "limit.png") + " --size 16x16", dir);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "limit.png"));
}

// 10,000 copies of one sphere (100 KB) took 87 s and 4.2 GB at 64x64: every
// copy filled a 43^3 grid, and each ray sorted 20,000 crossings by insertion.
TEST(CliHostileScene, TenThousandCoincidentSpheresRender) {
  TempDir dir;
  const std::string scene = write_scene(dir, "copies.csg", repeated("sphere(1);", 10000));
  const RunResult r = run_capsim("render " + scene + " -o " + (dir / "copies.png") + " --size 16x16", dir);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "copies.png"));
}

// Four million copies (40 MB) ran out of memory at 7.8 GB; a file past the
// size limit is refused before it is read.
TEST(CliHostileScene, FilePastTheSizeLimitIsRefused) {
  TempDir dir;
  const std::string large = write_scene(dir, "large.csg", "sphere();" + std::string(32 << 20, ' '));
  EXPECT_TRUE(RefusedAt(dir, large, "",
                        "the file is larger than 33554432 bytes (32 MiB), the most capsim reads "
                        "(reading takes up to about 100 bytes of memory per byte)"));
}
