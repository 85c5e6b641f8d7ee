// `capsim sweep` under mpirun: three ranks share the points and rank 0 writes
// the bytes a local run writes, a resumed sweep included; a rank's failure is
// told by rank 0 and nothing is written. Skipped when capsim was built without
// MPI or mpirun is absent. Run as root on few cores, as CI does, hence
// --allow-run-as-root and --oversubscribe.

#include "support/cli_run.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <fstream>
#include <regex>
#include <string>

using namespace capsim::testing;

namespace {

#ifdef CAPSIM_MPIEXEC
const std::string kMpirun = CAPSIM_MPIEXEC;
#else
const std::string kMpirun;
#endif

#define SKIP_WITHOUT_MPI()                                                                                  \
  if (kMpirun.empty())                                                                                      \
    GTEST_SKIP() << "capsim was built without MPI (Debian package libopenmpi-dev): sweeps under mpirun are " \
                    "not checked";                                                                          \
  if (::access(kMpirun.c_str(), X_OK) != 0)                                                                 \
  GTEST_SKIP() << kMpirun << " is absent: sweeps under mpirun are not checked"

const std::string kScenes = std::string(CAPSIM_SOURCE_DIR) + "/scenes";

void write(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

// 2 scenes x 2 modes x the cell grids at 16x16: 12 points with three grids.
std::string sweep_file(const TempDir& dir, const std::string& scene2, const std::string& cells) {
  const std::string file = dir / "s.json";
  write(file, R"({"axes": {"scenes": [")" + kScenes + R"(/balls.csg", ")" + scene2 + R"("], "cells": )" + cells +
                  R"(, "modes": ["line", "dot"], "sizes": ["16x16"]}})");
  return file;
}

// capsim under `mpirun -np 3`. Open MPI's temporary files go to the test's
// directory (TMPDIR). A sanitized build checks no leaks there: Open MPI's
// plugins, unloaded at MPI_Finalize, leave allocations LeakSanitizer reports
// and cannot name a library for; the local sweeps' tests check the same code
// for leaks.
RunResult mpirun_capsim(const std::string& args, const TempDir& dir) {
  std::string setup = "export TMPDIR='" + dir.path().string() + "';";
#ifdef CAPSIM_SANITIZED
  setup += "export ASAN_OPTIONS=\"${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0\";";
#endif
  return run_capsim(args, dir, setup, kMpirun + " --allow-run-as-root --oversubscribe -np 3");
}

int count_of(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

void expect_same_outputs(const TempDir& dir, const std::string& a, const std::string& b) {
  for (const char* ext : {".csv", ".json", ".html"}) EXPECT_EQ(read_file(dir / (a + ext)), read_file(dir / (b + ext))) << ext;
}

TEST(MpiSweep, ThreeRanksWriteTheLocalRunsBytes) {
  SKIP_WITHOUT_MPI();
  TempDir dir;
  const std::string spec = sweep_file(dir, kScenes + "/chess.csg", R"(["1x1", "2x2", "4x4"])");
  const RunResult local = run_capsim("sweep " + spec + " -o " + (dir / "local") + " --quiet", dir);
  ASSERT_EQ(local.status, 0) << local.err;
  const RunResult mpi = mpirun_capsim("sweep " + spec + " -o " + (dir / "mpi"), dir);
  ASSERT_EQ(mpi.status, 0) << mpi.err;
  expect_same_outputs(dir, "local", "mpi");
  EXPECT_NE(mpi.out.find("12 points (12 run on 3 MPI ranks, 0 kept from the earlier run)"), std::string::npos)
      << mpi.out;
  // Point k of those to run goes to rank k mod 3: four each.
  for (const char* rank : {"rank 0 of 3: ran 4/4", "rank 1 of 3: ran 4/4", "rank 2 of 3: ran 4/4"})
    EXPECT_EQ(count_of(mpi.err, rank), 1) << rank << "\n" << mpi.err;
  for (int point : {2, 5, 8, 11})
    EXPECT_TRUE(std::regex_search(mpi.err, std::regex("rank 1 of 3: ran [1-4]/4: point " + std::to_string(point) + ":")))
        << point << "\n" << mpi.err;
}

TEST(MpiSweep, AResumedSweepRunsOnlyTheMissingPoints) {
  SKIP_WITHOUT_MPI();
  TempDir dir;
  const std::string scene2 = kScenes + "/chess.csg";
  ASSERT_EQ(run_capsim("sweep " + sweep_file(dir, scene2, R"(["1x1", "2x2"])") + " -o " + (dir / "fresh") + " --quiet",
                       dir)
                .status,
            0);
  ASSERT_EQ(mpirun_capsim("sweep " + sweep_file(dir, scene2, R"(["2x2"])") + " -o " + (dir / "part") + " --quiet", dir)
                .status,
            0);
  const RunResult resumed =
      mpirun_capsim("sweep " + sweep_file(dir, scene2, R"(["1x1", "2x2"])") + " -o " + (dir / "part") + " --resume", dir);
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  EXPECT_EQ(count_of(resumed.err, ": ran "), 4) << resumed.err;
  EXPECT_EQ(count_of(resumed.err, "cells=1x1"), 4) << resumed.err;
  EXPECT_NE(resumed.out.find("8 points (4 run on 3 MPI ranks, 4 kept from the earlier run)"), std::string::npos)
      << resumed.out;
  expect_same_outputs(dir, "fresh", "part");
}

TEST(MpiSweep, ARanksFailureIsToldAndNothingIsWritten) {
  SKIP_WITHOUT_MPI();
  TempDir dir;
  write(dir / "bad.csg", "sphere oops\n");
  // Points 3 and 4 of 4 (bad.csg's) fall to ranks 2 and 0; rank 1's runs.
  const RunResult r = mpirun_capsim(
      "sweep " + sweep_file(dir, dir / "bad.csg", R"(["1x1"])") + " -o " + (dir / "out") + " --quiet", dir);
  EXPECT_NE(r.status, 0);
  EXPECT_EQ(count_of(r.err, "rank 0 of 3: " + (dir / "bad.csg") + ":2:1: unexpected end of file after 'oops'\n"), 1)
      << r.err;
  EXPECT_EQ(count_of(r.err, "rank 2 of 3: " + (dir / "bad.csg") + ":2:1: unexpected end of file after 'oops'\n"), 1)
      << r.err;
  EXPECT_EQ(count_of(r.err, "rank 1 of 3: " + (dir / "bad.csg")), 0) << r.err;
  for (const char* ext : {".csv", ".json", ".html"}) EXPECT_FALSE(std::filesystem::exists(dir / (std::string("out") + ext)));
  EXPECT_EQ(r.out, "");
}

}  // namespace
