// A signal that ends capsim while its outputs are pending removes their
// temporary files: the process still ends by that signal, and leaves nothing.

#include "support/cli_run.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>

#include <chrono>
#include <cstring>
#include <thread>

using namespace capsim::testing;

namespace {

const std::string kBalls = scene_path("balls.csg");

bool holds_a_temporary_file(const std::filesystem::path& dir) {
  for (const std::string& name : directory_entries(dir))
    if (name.size() > 4 && name.compare(name.size() - 4, 4, ".tmp") == 0) return true;
  return false;
}

// Runs capsim with args, with every signal at its default action and none
// blocked (whatever the test runner had), stdout and stderr discarded.
pid_t spawn_capsim(const std::vector<std::string>& args) {
  std::vector<std::string> all = {CAPSIM_EXE};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    for (int s = 1; s < NSIG; ++s) ::signal(s, SIG_DFL);
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, 1);
    ::dup2(null, 2);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  return pid;
}

// The scene is a FIFO nobody writes to: capsim, having staged its outputs
// (their temporary files exist), waits for ever to read it, until the signal.
class CliSignal : public ::testing::TestWithParam<int> {};

TEST_P(CliSignal, EndsTheProcessAndRemovesTheTemporaryFiles) {
  TempDir dir;
  const std::string fifo = dir / "scene.csg";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0) << std::strerror(errno);
  const pid_t pid = spawn_capsim({"simulate", fifo, "-o", dir / "s.png", "--report", dir / "r.json", "--heatmap",
                                  dir / "h.png"});
  ASSERT_GT(pid, 0);
  // A guard against waiting for ever, not a timing condition: capsim stages
  // its outputs within milliseconds of starting.
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (!holds_a_temporary_file(dir.path()) && std::chrono::steady_clock::now() < give_up)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  const bool staged = holds_a_temporary_file(dir.path());
  ::kill(pid, GetParam());
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  EXPECT_TRUE(staged) << "no temporary file appeared before the scene was read";
  ASSERT_TRUE(WIFSIGNALED(status)) << "exit status " << WEXITSTATUS(status);
  EXPECT_EQ(WTERMSIG(status), GetParam());
  EXPECT_EQ(directory_entries(dir.path()), std::vector<std::string>{"scene.csg"});
}

INSTANTIATE_TEST_SUITE_P(Signals, CliSignal, ::testing::Values(SIGINT, SIGTERM, SIGHUP),
                         [](const ::testing::TestParamInfo<int>& info) {
                           return std::string(sigabbrev_np(info.param));
                         });

// A file-size limit: the write that passes it raises SIGXFSZ.
TEST(CliSignal, FileSizeLimitLeavesNoTemporaryFile) {
  TempDir dir;
  const std::string limit = "ulimit -f 2;";  // 1 KiB (dash) or 2 KiB (bash)
  RunResult r = run_capsim("render " + kBalls + " -o " + (dir / "b.png") + " --size 64x64", dir, limit);
  EXPECT_EQ(r.signal, SIGXFSZ);
  EXPECT_EQ(directory_entries(dir.path()), std::vector<std::string>{});

  r = run_capsim("render " + kBalls + " -o " + (dir / "b.exr") + " --size 64x64", dir, limit);
  EXPECT_EQ(r.signal, SIGXFSZ);
  EXPECT_EQ(directory_entries(dir.path()), std::vector<std::string>{});

  r = run_capsim("simulate " + kBalls + " -o " + (dir / "s.png") + " --size 8x8 --report " + (dir / "r.json") +
                     " --trace " + (dir / "t.json"), dir, limit);
  EXPECT_EQ(r.signal, SIGXFSZ);
  EXPECT_EQ(directory_entries(dir.path()), std::vector<std::string>{});
}

TEST(CliSignal, AnIgnoredSignalStaysIgnored) {
  // Started with SIGXFSZ ignored (as by nohup or trap ''), capsim keeps it
  // ignored: the write fails with EFBIG and capsim reports it.
  TempDir dir;
  const RunResult r = run_capsim("render " + kBalls + " -o " + (dir / "b.png") + " --size 64x64", dir,
                                 "ulimit -f 2; trap '' XFSZ;");
  EXPECT_EQ(r.signal, 0);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "capsim: " + (dir / "b.png") + ": File too large\n");
  EXPECT_EQ(directory_entries(dir.path()), std::vector<std::string>{});
}

}  // namespace
