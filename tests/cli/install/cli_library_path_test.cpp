// capsim loads its libraries from where the system (or its RUNPATH) keeps
// them, never from the directory it is run in: a file there named like one of
// them is not opened. An empty RUNPATH entry, which CMake's padding once left,
// makes the loader search the current directory first.

#include "support/cli_run.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace capsim::testing;

namespace {

// The sonames the loader resolves for capsim ("libtbb.so.12 => /usr/lib/..."),
// as it lists them without running the program.
std::vector<std::string> loaded_sonames(const TempDir& dir) {
  const RunResult listed = run_capsim("", dir, "export LD_TRACE_LOADED_OBJECTS=1;");
  EXPECT_EQ(listed.status, 0) << listed.err;
  std::vector<std::string> names;
  std::istringstream lines(listed.out);
  for (std::string line; std::getline(lines, line);) {
    const auto arrow = line.find(" => ");
    if (arrow == std::string::npos) continue;
    const auto first = line.find_first_not_of(" \t");
    names.push_back(line.substr(first, arrow - first));
  }
  return names;
}

TEST(CliLibraryPath, FilesNamedLikeItsLibrariesInTheCurrentDirectoryAreNotLoaded) {
  const TempDir dir;
  const std::vector<std::string> names = loaded_sonames(dir);
  // capsim links TBB, libpng, libdeflate, fmt and the C++ runtime at least.
  ASSERT_GE(names.size(), 5u);
  const std::filesystem::path here = dir.path() / "here";
  std::filesystem::create_directories(here);
  for (const std::string& name : names) std::ofstream(here / name) << "not a library\n";
  const RunResult r = run_program_in(here, CAPSIM_EXE, "--version", dir);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("capsim"), std::string::npos) << r.out;
  EXPECT_EQ(r.err, "");
}

}  // namespace
