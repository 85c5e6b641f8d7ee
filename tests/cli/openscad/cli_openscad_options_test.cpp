// OpenSCAD's view options on `capsim render` and `capsim simulate`: what they
// accept, --imgsize beside --size, the options over the scene's camera
// statement, --verbose's camera pasted back, and the orthographic view on the
// simulated machine.

#include "support/cli_run.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

using namespace capsim::testing;

namespace {

const std::string kSphere = "difference() { sphere(r = 2); translate([0, -3, 0]) cube(3); }\n";

std::string write_scene(const TempDir& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir / name) << text;
  return dir / name;
}

TEST(CliOpenScadOptions, RefusesBadValues) {
  TempDir dir;
  const std::string scene = write_scene(dir, "s.csg", kSphere);
  const std::string base = "render " + scene + " -o " + (dir / "o.png") + " ";
  RunResult r = run_capsim(base + "--camera=1,2,3,4,5", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--camera 1,2,3,4,5 does not have 6 or 7 numbers"), std::string::npos) << r.err;
  r = run_capsim(base + "--camera=1,2,3,1,2,3", dir);
  EXPECT_NE(r.err.find("has the eye at the centre"), std::string::npos) << r.err;
  r = run_capsim(base + "--camera=0,0,0,55,0,25,0", dir);
  EXPECT_NE(r.err.find("has a distance that is not above 0"), std::string::npos) << r.err;
  r = run_capsim(base + "--camera=0,0,0,55,0,nan,10", dir);
  EXPECT_NE(r.err.find("is not a list of numbers"), std::string::npos) << r.err;
  r = run_capsim(base + "--projection=fisheye", dir);
  EXPECT_NE(r.err.find("--projection fisheye is not a projection (accepted: perspective, p, ortho, o or "
                       "orthogonal)"),
            std::string::npos)
      << r.err;
  r = run_capsim(base + "--imgsize=64x48", dir);
  EXPECT_NE(r.err.find("--imgsize 64x48 is not W,H"), std::string::npos) << r.err;
  r = run_capsim(base + "--imgsize=64,48 --size 32x24", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--size 32x24 and --imgsize 64,48 give different image sizes"), std::string::npos) << r.err;
}

// --imgsize is --size; both at once agree.
TEST(CliOpenScadOptions, ImgsizeIsSize) {
  TempDir dir;
  const std::string scene = write_scene(dir, "s.csg", kSphere);
  ASSERT_EQ(run_capsim("render " + scene + " -o " + (dir / "a.png") + " --imgsize=40,30", dir).status, 0);
  ASSERT_EQ(run_capsim("render " + scene + " -o " + (dir / "b.png") + " --size 40x30 --imgsize=40,30", dir).status,
            0);
  ASSERT_EQ(run_capsim("render " + scene + " -o " + (dir / "c.png") + " --size 40x30", dir).status, 0);
  EXPECT_TRUE(read_file(dir / "a.png") == read_file(dir / "c.png"));
  EXPECT_TRUE(read_file(dir / "b.png") == read_file(dir / "c.png"));
}

// The options win over the scene's camera statement; without them the
// statement holds.
TEST(CliOpenScadOptions, OptionsOverrideTheCameraStatement) {
  TempDir dir;
  const std::string plain = write_scene(dir, "plain.csg", kSphere);
  const std::string with_camera =
      write_scene(dir, "cam.csg", "camera(eye = [0, 0, 30], center = [0, 0, 0], up = [0, 1, 0]);\n" + kSphere);
  const std::string opts = " --size 48x32 --camera=3,-9,4,0,0,0";
  ASSERT_EQ(run_capsim("render " + plain + " -o " + (dir / "a.png") + opts, dir).status, 0);
  ASSERT_EQ(run_capsim("render " + with_camera + " -o " + (dir / "b.png") + opts, dir).status, 0);
  ASSERT_EQ(run_capsim("render " + with_camera + " -o " + (dir / "c.png") + " --size 48x32", dir).status, 0);
  EXPECT_TRUE(read_file(dir / "a.png") == read_file(dir / "b.png"));
  EXPECT_FALSE(read_file(dir / "b.png") == read_file(dir / "c.png"));
}

// --verbose prints the camera as options; pasted, they give the same image.
TEST(CliOpenScadOptions, VerboseCameraPastesBack) {
  TempDir dir;
  const std::string scene = write_scene(dir, "s.csg", kSphere);
  RunResult r = run_capsim("render " + scene + " -o " + (dir / "a.png") + " --size 48x32 --projection=o --verbose", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string prefix = "camera: ";
  ASSERT_EQ(r.err.rfind(prefix, 0), 0u) << r.err;
  const std::string args = r.err.substr(prefix.size(), r.err.find('\n') - prefix.size());
  EXPECT_NE(args.find("--projection=ortho"), std::string::npos) << args;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;  // one line: OpenSCAD's camera is expressible
  r = run_capsim("render " + scene + " -o " + (dir / "b.png") + " --size 48x32 " + args, dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(read_file(dir / "a.png") == read_file(dir / "b.png"));
  // capsim's default camera (a 40 degree field) says that OpenSCAD's differs.
  r = run_capsim("simulate " + scene + " -o " + (dir / "c.png") + " --size 16x16 --cells 2x2 --verbose", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("camera: a 40 degree field with up [0, 0, 1]; OpenSCAD's --camera sees from the same eye "
                       "and centre with a 22.5 degree field and z up"),
            std::string::npos)
      << r.err;
  // ... and gives the statement that sees exactly as it does.
  const std::string marker = "in the scene file: ";
  const auto at = r.err.find(marker);
  ASSERT_NE(at, std::string::npos) << r.err;
  const std::string statement = r.err.substr(at + marker.size(), r.err.find('\n', at) - at - marker.size());
  const std::string pinned = dir / "pinned.csg";
  std::ofstream(pinned) << statement << "\n" << read_file(scene);
  r = run_capsim("simulate " + pinned + " -o " + (dir / "d.png") + " --size 16x16 --cells 2x2", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(read_file(dir / "c.png") == read_file(dir / "d.png")) << statement;
}

// The machine traces the tracer's primary rays: orthographic too, and
// orthographic differs from perspective.
TEST(CliOpenScadOptions, SimulatedScreenIsTheOrthographicRender) {
  TempDir dir;
  const std::string scene = write_scene(dir, "s.csg", kSphere);
  const std::string opts = " --size 40x30 --camera=0,0,0,60,0,30,12 --projection=o";
  ASSERT_EQ(run_capsim("render " + scene + " -o " + (dir / "r.png") + opts, dir).status, 0);
  const RunResult r = run_capsim("simulate " + scene + " -o " + (dir / "s.png") + opts + " --cells 2x2", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(read_file(dir / "r.png") == read_file(dir / "s.png"));
  ASSERT_EQ(run_capsim("render " + scene + " -o " + (dir / "p.png") + " --size 40x30 --camera=0,0,0,60,0,30,12", dir)
                .status,
            0);
  EXPECT_FALSE(read_file(dir / "r.png") == read_file(dir / "p.png"));
}

}  // namespace
