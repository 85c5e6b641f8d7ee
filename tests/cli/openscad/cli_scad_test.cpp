// .scad input: OpenSCAD exports the program to CSG and capsim renders the
// export, with -D passed through, --frames as OpenSCAD's --animate and several
// files as a sequence; its failures and capsim's errors in the export name the
// .scad; the temporary exports are gone after the run and after a signal; and
// without openscad on PATH the error says how to get it.

#include "support/cli_run.h"

#include <signal.h>

#include <fmt/format.h>

#include <chrono>
#include <cstdlib>
#include <thread>

using namespace capsim::testing;

namespace {

// A program only OpenSCAD reads: a module, a variable, a loop.
constexpr const char* kProgram =
    "size = 2;\n"
    "module post(h) cylinder(h = h, r = 0.5);\n"
    "for (i = [0:2]) translate([3 * i, 0, 0]) post(size * (i + 1));\n"
    "translate([0, 4, 0]) cube(size + 3 * $t);\n";

bool has_openscad() { return std::system("command -v openscad >/dev/null 2>&1") == 0; }

#define SKIP_WITHOUT_OPENSCAD() \
  if (!has_openscad()) GTEST_SKIP() << "openscad is not on PATH (the openscad package installs it)"

// Runs openscad itself in `dir` (the test's reference export).
void openscad(const TempDir& dir, const std::string& args) {
  const std::string cmd = "cd " + dir.path().string() + " && openscad " + args + " >/dev/null 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
}

std::string write(const TempDir& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir / name) << text;
  return dir / name;
}

// capsim's temporary directories in `tmp` (its TMPDIR in these runs).
int scad_dirs(const std::filesystem::path& tmp) {
  int n = 0;
  for (const auto& e : std::filesystem::directory_iterator(tmp))
    if (e.path().filename().string().rfind("capsim-scad.", 0) == 0) ++n;
  return n;
}

// Runs capsim with TMPDIR inside the test's directory.
RunResult run_with_tmp(const std::string& args, const TempDir& dir) {
  std::filesystem::create_directories(dir / "tmp");
  return run_capsim(args, dir, "export TMPDIR=" + (dir / "tmp") + ";");
}

const std::string kSize = " --size 48x36";

TEST(CliScad, RendersWhatOpenScadExports) {
  SKIP_WITHOUT_OPENSCAD();
  TempDir dir;
  const std::string scad = write(dir, "m.scad", kProgram);
  openscad(dir, "-o " + (dir / "ref.csg") + " m.scad");
  RunResult r = run_with_tmp("render " + scad + " -o " + (dir / "s.png") + kSize, dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");  // OpenSCAD's progress notes are not passed on
  ASSERT_EQ(run_capsim("render " + (dir / "ref.csg") + " -o " + (dir / "ref.png") + kSize, dir).status, 0);
  EXPECT_EQ(read_file(dir / "s.png"), read_file(dir / "ref.png"));
  EXPECT_EQ(scad_dirs(dir / "tmp"), 0);
  // simulate reads it the same way.
  r = run_with_tmp("simulate " + scad + " -o " + (dir / "sim.png") + kSize + " --cells 2x2", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read_file(dir / "sim.png"), read_file(dir / "ref.png"));
  EXPECT_EQ(scad_dirs(dir / "tmp"), 0);
}

TEST(CliScad, DefinesArePassedToOpenScad) {
  SKIP_WITHOUT_OPENSCAD();
  TempDir dir;
  const std::string scad = write(dir, "m.scad", kProgram);
  openscad(dir, "-o " + (dir / "ref.csg") + " -D size=1 -D '$t=0.5' m.scad");
  const RunResult r =
      run_with_tmp("render " + scad + " -D size=1 -D '$t=0.5' -o " + (dir / "d.png") + kSize, dir);
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_EQ(run_capsim("render " + (dir / "ref.csg") + " -o " + (dir / "ref.png") + kSize, dir).status, 0);
  ASSERT_EQ(run_capsim("render " + scad + " -o " + (dir / "plain.png") + kSize, dir).status, 0);
  EXPECT_EQ(read_file(dir / "d.png"), read_file(dir / "ref.png"));
  EXPECT_NE(read_file(dir / "d.png"), read_file(dir / "plain.png"));
}

TEST(CliScad, DefinesAreRefusedForCsgInput) {
  TempDir dir;
  const RunResult r = run_capsim("render " + scene_path("balls.csg") + " -D size=1 -o " + (dir / "b.png"), dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("-D sets a variable of an OpenSCAD program and applies only to .scad input"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "b.png"));
}

TEST(CliScad, FramesAreOpenScadsAnimation) {
  SKIP_WITHOUT_OPENSCAD();
  TempDir dir;
  const std::string scad = write(dir, "m.scad", kProgram);
  openscad(dir, "--animate 3 -o " + (dir / "f.csg") + " m.scad");
  const RunResult r = run_with_tmp("render --frames 3 " + scad + " -o " + (dir / "a.png") + kSize, dir);
  ASSERT_EQ(r.status, 0) << r.err;
  std::string exports;
  for (int k = 0; k < 3; ++k) exports += fmt::format(" {}", dir / fmt::format("f{:05d}.csg", k));
  ASSERT_EQ(run_capsim("render" + exports + " -o " + (dir / "ref.png") + kSize, dir).status, 0);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(read_file(dir / fmt::format("a{:05d}.png", k)), read_file(dir / fmt::format("ref{:05d}.png", k))) << k;
  }
  EXPECT_NE(read_file(dir / "a00000.png"), read_file(dir / "a00002.png"));  // the cube grows
  EXPECT_EQ(scad_dirs(dir / "tmp"), 0);
}

TEST(CliScad, SeveralFilesAreASequence) {
  SKIP_WITHOUT_OPENSCAD();
  TempDir dir;
  std::filesystem::create_directories(dir / "b");
  const std::string one = write(dir, "m.scad", kProgram);
  const std::string two = write(dir, "b/m.scad", "sphere(2);\n");  // the same name in another directory
  const RunResult r = run_with_tmp("render " + one + " " + scene_path("balls.csg") + " " + two + " -o " +
                                       (dir / "q.png") + kSize,
                                   dir);
  ASSERT_EQ(r.status, 0) << r.err;
  openscad(dir, "-o " + (dir / "r0.csg") + " m.scad");
  openscad(dir, "-o " + (dir / "r2.csg") + " b/m.scad");
  ASSERT_EQ(run_capsim("render " + (dir / "r0.csg") + " " + scene_path("balls.csg") + " " + (dir / "r2.csg") +
                           " -o " + (dir / "ref.png") + kSize,
                       dir)
                .status,
            0);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(read_file(dir / fmt::format("q{:05d}.png", k)), read_file(dir / fmt::format("ref{:05d}.png", k))) << k;
  }
  EXPECT_EQ(scad_dirs(dir / "tmp"), 0);
}

// Renders the program `text` as `name`, which must fail with status 1,
// leaving no image and no export behind; returns what capsim printed.
std::string refusal(const TempDir& dir, const std::string& name, const std::string& text) {
  const std::string scad = write(dir, name, text);
  const RunResult r = run_with_tmp("render " + scad + " -o " + (dir / "out.png"), dir);
  EXPECT_EQ(r.status, 1);
  EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
  EXPECT_EQ(scad_dirs(dir / "tmp"), 0);
  return r.err;
}

TEST(CliScad, OpenScadsFailureIsShownWithItsStatus) {
  SKIP_WITHOUT_OPENSCAD();
  TempDir dir;
  const std::string scad = dir / "bad.scad";
  const std::string err = refusal(dir, "bad.scad", "cube(;\n");
  EXPECT_EQ(err.rfind(scad + ": OpenSCAD could not export it to CSG (openscad exited with status 1); it printed:\n",
                        0),
            0u)
      << err;
  EXPECT_NE(err.find("Parser error"), std::string::npos) << err;
}

TEST(CliScad, WarningsAndEchoesArePassedOn) {
  SKIP_WITHOUT_OPENSCAD();
  TempDir dir;
  const std::string scad = write(dir, "w.scad", "echo(\"hello\");\ncube(missing_size);\nsphere(1);\n");
  const RunResult r = run_with_tmp("render " + scad + " -o " + (dir / "w.png") + kSize, dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("openscad: ECHO: \"hello\"\n"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("openscad: WARNING: Ignoring unknown variable 'missing_size'"), std::string::npos) << r.err;
}

// capsim's errors in the export are the export's, and name the .scad it came
// from.
TEST(CliScad, ErrorsInTheExportNameTheScad) {
  SKIP_WITHOUT_OPENSCAD();
  TempDir dir;
  const std::string scad = dir / "e.scad";
  const std::string err =
      refusal(dir, "e.scad", "sphere(1);\ncube(1e31);\n");
  EXPECT_EQ(err.rfind((dir / "tmp") + "/capsim-scad.", 0), 0u) << err;
  EXPECT_NE(err.find("/e.csg:2:13: cube size must be at most 1e30"), std::string::npos) << err;
  EXPECT_NE(err.find("\n" + scad + ": the errors above are in OpenSCAD's CSG export of it"), std::string::npos)
      << err;
}

TEST(CliScad, WithoutOpenScadTheErrorNamesThePackage) {
  TempDir dir;
  std::filesystem::create_directories(dir / "empty");
  const std::string scad = write(dir, "m.scad", kProgram);
  const RunResult r = run_capsim("render " + scad + " -o " + (dir / "m.png"), dir, "export PATH=" + (dir / "empty") + ";");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, scad + ": a .scad file needs OpenSCAD to read it, and 'openscad' is not on PATH: install the "
                          "openscad package, e.g. apt-get install openscad, or export the model to .csg yourself "
                          "(openscad -o model.csg model.scad)\n");
  EXPECT_FALSE(std::filesystem::exists(dir / "m.png"));
}

// A signal while openscad runs removes the export directory. The openscad on
// PATH is a script that records its process and waits.
TEST(CliScad, ASignalRemovesTheExports) {
  TempDir dir;
  std::filesystem::create_directories(dir / "bin");
  std::filesystem::create_directories(dir / "tmp");
  const std::string fake = write(dir, "bin/openscad", "#!/bin/sh\necho $$ > " + (dir / "pid") + "\nexec /bin/sleep 60\n");
  std::filesystem::permissions(fake, std::filesystem::perms::owner_all);
  const std::string scad = write(dir, "m.scad", kProgram);
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::setenv("PATH", (dir / "bin").c_str(), 1);
    ::setenv("TMPDIR", (dir / "tmp").c_str(), 1);
    ::signal(SIGTERM, SIG_DFL);
    const std::string out = dir / "m.png";
    ::execl(CAPSIM_EXE, CAPSIM_EXE, "render", scad.c_str(), "-o", out.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ASSERT_GT(pid, 0);
  // A guard against waiting for ever: the script starts within milliseconds.
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (read_file(dir / "pid").empty() && std::chrono::steady_clock::now() < give_up)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  const std::string script_pid = read_file(dir / "pid");
  const int dirs_while_running = scad_dirs(dir / "tmp");
  ::kill(pid, SIGTERM);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  if (!script_pid.empty()) ::kill(std::stoi(script_pid), SIGKILL);
  EXPECT_EQ(dirs_while_running, 1);
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(WTERMSIG(status), SIGTERM);
  EXPECT_EQ(scad_dirs(dir / "tmp"), 0);
}

}  // namespace
