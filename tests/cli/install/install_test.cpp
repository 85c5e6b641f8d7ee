// cmake --install puts the program, its EXR module, its documentation, the sample scenes and
// the baselines of `bench modes` under the prefix; the installed program runs,
// and from any directory finds its models and baselines under the prefix's
// share/capsim, writing only into that directory.

#include "support/cli_run.h"

using namespace capsim::testing;

namespace {

namespace fs = std::filesystem;

// cmake --install of the build to prefix, logged in dir's install.log; its exit status.
int install(const std::string& prefix, const TempDir& dir) {
  const std::string command = std::string(CAPSIM_CMAKE_COMMAND) + " --install " + CAPSIM_BINARY_DIR + " --prefix " +
                              prefix + " >" + (dir / "install.log") + " 2>&1";
  return std::system(command.c_str());
}

TEST(Install, PutsTheProgramDocsAndScenesUnderThePrefix) {
  TempDir dir;
  const std::string prefix = dir / "prefix";
  ASSERT_EQ(install(prefix, dir), 0) << read_file(dir / "install.log");

  const fs::path root(prefix);
  EXPECT_TRUE(fs::is_regular_file(root / "share/doc/capsim/README.md"));
  EXPECT_TRUE(fs::is_regular_file(root / "share/doc/capsim/docs/scene-format.md"));
  EXPECT_TRUE(fs::is_regular_file(root / "share/capsim/scenes/balls.csg"));
  EXPECT_TRUE(fs::is_regular_file(root / "share/capsim/scenes/disb/f00000.csg"));
  EXPECT_TRUE(fs::is_regular_file(root / "share/capsim/baselines/modes.json"));
  EXPECT_TRUE(fs::is_regular_file(root / "share/capsim/baselines/modes-48x48.json"));
  const std::string capsim = (root / "bin/capsim").string();
  ASSERT_TRUE(fs::is_regular_file(capsim));

  const std::string version = capsim + " --version >" + (dir / "version.txt");
  ASSERT_EQ(std::system(version.c_str()), 0);
  EXPECT_EQ(read_file(dir / "version.txt"), "capsim 0.1.0\n");
  const std::string render = capsim + " render " + (root / "share/capsim/scenes/balls.csg").string() + " -o " +
                             (dir / "balls.png") + " --size 16x16";
  ASSERT_EQ(std::system(render.c_str()), 0);
  EXPECT_TRUE(fs::is_regular_file(dir / "balls.png"));

  // An .exr is written by the EXR module installed under the prefix (the
  // loader's log names each library it opens), not by the build's.
  const std::string exr = "LD_DEBUG=files " + capsim + " render " +
                          (root / "share/capsim/scenes/balls.csg").string() + " -o " + (dir / "balls.exr") +
                          " --size 16x16 2>" + (dir / "exr.log");
  ASSERT_EQ(std::system(exr.c_str()), 0) << read_file(dir / "exr.log");
  EXPECT_TRUE(fs::is_regular_file(dir / "balls.exr"));
  const std::string log = read_file(dir / "exr.log");
  const auto at = log.find("file=" + prefix + "/");
  ASSERT_NE(at, std::string::npos) << log;
  const std::string opened = log.substr(at + 5, log.find(' ', at) - (at + 5));
  EXPECT_TRUE(opened.ends_with("/capsim/libcapsim_exr.so")) << opened;
}

TEST(Install, TheInstalledProgramFindsItsDataFromAnyDirectoryAndWritesOnlyThere) {
  TempDir dir;
  const std::string prefix = dir / "prefix";
  ASSERT_EQ(install(prefix, dir), 0) << read_file(dir / "install.log");
  const fs::path share = fs::weakly_canonical(fs::path(prefix) / "share/capsim");
  const std::set<std::string> installed = files_under(prefix);
  const fs::path work = dir.path() / "work";
  fs::create_directories(work);
  const std::string capsim = (fs::path(prefix) / "bin/capsim").string();

  // A size without a shipped baseline: run, written and not compared.
  const RunResult small = run_program_in(work, capsim, "bench modes --size 16x16 --html modes.html", dir);
  ASSERT_EQ(small.status, 0) << small.out << small.err;
  EXPECT_TRUE(small.out.ends_with("no baseline for 16x16: not compared\n")) << small.out;
  // The default size's baseline and the one at 48x48 are found and compared.
  const RunResult compared = run_program_in(work, capsim, "bench modes --size 48x48", dir);
  ASSERT_EQ(compared.status, 0) << compared.out << compared.err;
  EXPECT_TRUE(compared.out.ends_with((share / "baselines/modes-48x48.json").string() +
                                     ": all 200 runs identical to the baseline\n"))
      << compared.out;
  // The reproduction on a small screen, from the installed models.
  const RunResult repro = run_program_in(work, capsim, "repro --size 16x16 --disb-frames 1", dir);
  ASSERT_EQ(repro.status, 0) << repro.out << repro.err;
  EXPECT_NE(read_file(work / "reproduction.md").find((share / "scenes/chess.csg").string()), std::string::npos);

  EXPECT_EQ(files_under(work), (std::set<std::string>{"images", "images/graph-4-3.svg", "images/table-4-2.svg",
                                                       "modes.html", "reproduction.md"}));
  EXPECT_EQ(files_under(prefix), installed);
}

}  // namespace
