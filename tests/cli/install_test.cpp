// cmake --install puts the program, its documentation and the sample scenes
// under the prefix, and the installed program runs.

#include "support/cli_run.h"

using namespace capsim::testing;

namespace {

TEST(Install, PutsTheProgramDocsAndScenesUnderThePrefix) {
  TempDir dir;
  const std::string prefix = dir / "prefix";
  const std::string install = std::string(CAPSIM_CMAKE_COMMAND) + " --install " + CAPSIM_BINARY_DIR + " --prefix " +
                              prefix + " >" + (dir / "install.log") + " 2>&1";
  ASSERT_EQ(std::system(install.c_str()), 0) << read_file(dir / "install.log");

  const std::filesystem::path root(prefix);
  EXPECT_TRUE(std::filesystem::is_regular_file(root / "share/doc/capsim/README.md"));
  EXPECT_TRUE(std::filesystem::is_regular_file(root / "share/doc/capsim/docs/scene-format.md"));
  EXPECT_TRUE(std::filesystem::is_regular_file(root / "share/capsim/scenes/balls.csg"));
  const std::string capsim = (root / "bin/capsim").string();
  ASSERT_TRUE(std::filesystem::is_regular_file(capsim));

  const std::string version = capsim + " --version >" + (dir / "version.txt");
  ASSERT_EQ(std::system(version.c_str()), 0);
  EXPECT_EQ(read_file(dir / "version.txt"), "capsim 0.1.0\n");
  const std::string render = capsim + " render " + (root / "share/capsim/scenes/balls.csg").string() + " -o " +
                             (dir / "balls.png") + " --size 16x16";
  ASSERT_EQ(std::system(render.c_str()), 0);
  EXPECT_TRUE(std::filesystem::is_regular_file(dir / "balls.png"));
}

}  // namespace
