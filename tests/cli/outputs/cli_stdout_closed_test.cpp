// A reader of stdout that goes away early (`capsim ... | head -1`): capsim
// stops printing, writes its outputs and exits 0; but an output that is
// standard output itself and cannot be written fails the run (status 1), and
// the other outputs are not put in place.

#include "support/cli_run.h"

#include <fcntl.h>
#include <signal.h>

#include <cstdlib>

using namespace capsim::testing;

namespace {

const std::string kBalls = scene_path("balls.csg");

struct Child {
  pid_t pid = -1;
  int out = -1;  // the read end of its stdout
};

// Runs capsim with args, its stdout a pipe, its stderr the file err, its
// temporary directory tmp, and every signal at its default action.
Child spawn(const std::vector<std::string>& args, const std::string& err, const std::string& tmp) {
  std::vector<std::string> all = {CAPSIM_EXE};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  int fds[2];
  if (::pipe(fds) != 0) return {};
  const pid_t pid = ::fork();
  if (pid == 0) {
    for (int s = 1; s < NSIG; ++s) ::signal(s, SIG_DFL);
    ::setenv("TMPDIR", tmp.c_str(), 1);
    const int e = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fds[1], 1);
    ::dup2(e, 2);
    ::close(fds[0]);
    ::close(fds[1]);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  ::close(fds[1]);
  return {pid, fds[0]};
}

int exit_status(pid_t pid) {
  int status = 0;
  if (::waitpid(pid, &status, 0) != pid) return -2;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -100 - WTERMSIG(status);
}

// 1,024 cells print over 100 KiB, more than a pipe holds: capsim is still
// writing when the reader leaves.
TEST(CliStdoutClosed, AReaderThatLeavesAfterOneLineLeavesExitStatusZero) {
  TempDir dir;
  std::filesystem::create_directory(dir.path() / "tmp");
  const Child c = spawn({"simulate", kBalls, "--size", "32x32", "--cells", "32x32", "-o", dir / "s.png", "--report",
                         dir / "r.json"},
                        dir / "err", dir / "tmp");
  ASSERT_GT(c.pid, 0);
  std::string first;
  for (char ch; first.empty() || first.back() != '\n';) {
    if (::read(c.out, &ch, 1) != 1) break;
    first += ch;
  }
  ::close(c.out);
  EXPECT_EQ(exit_status(c.pid), 0);  // not ended by SIGPIPE (-113)
  EXPECT_EQ(first, "CAP simulation: 32x32 cells, dot mode, profile cap (8000000 Hz), 32x32 pixels\n");
  EXPECT_EQ(read_file(dir / "err"), "");
  EXPECT_EQ(directory_entries(dir.path()), (std::vector<std::string>{"err", "r.json", "s.png", "tmp"}));
}

TEST(CliStdoutClosed, AnOutputToStandardOutputWithNoReaderFailsTheRun) {
  TempDir dir;
  std::filesystem::create_directory(dir.path() / "tmp");
  const Child c = spawn({"simulate", kBalls, "--size", "8x8", "-o", dir / "s.png", "--report", "-", "--trace",
                         dir / "t.json"},
                        dir / "err", dir / "tmp");
  ASSERT_GT(c.pid, 0);
  ::close(c.out);  // before capsim can write anything
  EXPECT_EQ(exit_status(c.pid), 1);
  EXPECT_EQ(read_file(dir / "err"), "capsim: -: cannot write to it: Broken pipe\n");
  EXPECT_EQ(directory_entries(dir.path()), (std::vector<std::string>{"err", "tmp"}));
  EXPECT_TRUE(std::filesystem::is_empty(dir.path() / "tmp"));  // the report's staging file went too
}

}  // namespace
