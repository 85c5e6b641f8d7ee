// What an output path leads to decides how capsim writes it: a symbolic link
// is followed and the file it leads to replaced whole (the link stays a link;
// a dangling one creates the file it names); a FIFO, a character device and
// "-" (standard output) are written through once the run has succeeded; a
// directory or a socket is refused before any work. Every case runs as the
// invoker and, when that is root (as in CI), as the user nobody too.

#include "support/as_user.h"
#include "support/cli_run.h"
#include "support/provenance.h"

#include <fcntl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>

#include <cstring>
#include <future>

using namespace capsim::testing;
namespace fs = std::filesystem;

namespace {

const std::string kBalls = scene_path("balls.csg");

enum class User { Invoker, Nobody };
void PrintTo(User u, std::ostream* os) { *os << (u == User::Invoker ? "the invoker" : "nobody"); }

// Reads a FIFO whole on a thread of its own: opening it waits for a writer.
class FifoReader {
 public:
  explicit FifoReader(std::string path)
      : path_(std::move(path)), content_(std::async(std::launch::async, [p = path_] { return read_file(p); })) {}
  // What was read. A capsim that never opened the FIFO leaves the reader
  // waiting: a writer of our own that closes at once ends its wait with nothing.
  // That writer's open fails (ENXIO) while the reader's thread has not yet
  // reached its own open, as on a loaded machine, so it is tried until the
  // reader is done.
  std::string finish() {
    while (content_.wait_for(std::chrono::milliseconds(10)) != std::future_status::ready) {
      const int fd = ::open(path_.c_str(), O_WRONLY | O_NONBLOCK);
      if (fd >= 0) ::close(fd);
    }
    return content_.get();
  }

 private:
  std::string path_;
  std::future<std::string> content_;
};

class CliOutputTargets : public ::testing::TestWithParam<User> {
 protected:
  void SetUp() override {
    if (GetParam() == User::Invoker) return;
    std::string why_not;
    launcher_ = unprivileged_launcher(why_not, {kBalls});
    if (launcher_.empty()) GTEST_SKIP() << why_not;
  }

  // Runs `simulate` of an 8x8 screen on 2x2 cells with `options` added, as
  // the user of the test; the directory is that user's first.
  RunResult simulate(const std::string& options, const std::string& scene = kBalls) {
    if (GetParam() == User::Nobody) give_to_nobody(dir_.path());
    return run_capsim("simulate " + scene + " --size 8x8 --cells 2x2 -o " + (dir_ / "s.png") + " " + options, dir_,
                      "", launcher_);
  }

  // A report as the runs compared here give it alike: without the provenance's
  // command line and --report path, which name each run's target.
  static std::string comparable(const std::string& report) { return without_argv_and(report, {"report"}); }

  // The report a run writes to a plain new file, removed after reading
  // (comparable).
  std::string reference_report() {
    const RunResult r = simulate("--report " + (dir_ / "reference.json"));
    EXPECT_EQ(r.status, 0) << r.err;
    std::string text = read_file(dir_ / "reference.json");
    fs::remove(dir_ / "reference.json");
    fs::remove(dir_ / "s.png");
    EXPECT_FALSE(text.empty());
    return comparable(text);
  }

  TempDir dir_;
  std::string launcher_;
};

TEST_P(CliOutputTargets, ARegularFileIsReplacedWhole) {
  const std::string report = reference_report();
  std::ofstream(dir_ / "r.json") << "old";
  const RunResult r = simulate("--report " + (dir_ / "r.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(comparable(read_file(dir_ / "r.json")), report);
  EXPECT_EQ(directory_entries(dir_.path()), (std::vector<std::string>{"r.json", "s.png"}));
}

TEST_P(CliOutputTargets, ASymbolicLinkIsFollowedAndStaysALink) {
  const std::string report = reference_report();
  std::ofstream(dir_ / "real.json") << "old";
  fs::create_symlink("real.json", dir_ / "link.json");
  const RunResult r = simulate("--report " + (dir_ / "link.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.json"));
  EXPECT_EQ(fs::read_symlink(dir_ / "link.json"), "real.json");
  EXPECT_EQ(comparable(read_file(dir_ / "real.json")), report);
  EXPECT_EQ(directory_entries(dir_.path()), (std::vector<std::string>{"link.json", "real.json", "s.png"}));
}

// Each relative link is read against its own directory: c.json's "real.json"
// is sub/real.json.
TEST_P(CliOutputTargets, AChainOfLinksIsResolvedFully) {
  const std::string report = reference_report();
  fs::create_directory(dir_.path() / "sub");
  std::ofstream(dir_ / "sub/real.json") << "old";
  fs::create_symlink("b.json", dir_ / "a.json");
  fs::create_symlink("sub/c.json", dir_ / "b.json");
  fs::create_symlink("real.json", dir_ / "sub/c.json");
  const RunResult r = simulate("--report " + (dir_ / "a.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(comparable(read_file(dir_ / "sub/real.json")), report);
  EXPECT_EQ(fs::read_symlink(dir_ / "a.json"), "b.json");
  EXPECT_EQ(fs::read_symlink(dir_ / "b.json"), "sub/c.json");
  EXPECT_EQ(fs::read_symlink(dir_ / "sub/c.json"), "real.json");
  EXPECT_EQ(directory_entries(dir_.path() / "sub"), (std::vector<std::string>{"c.json", "real.json"}));
}

TEST_P(CliOutputTargets, ADanglingLinkCreatesTheFileItNames) {
  const std::string report = reference_report();
  fs::create_directory(dir_.path() / "sub");
  fs::create_symlink("sub/new.json", dir_ / "link.json");
  RunResult r = simulate("--report " + (dir_ / "link.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(comparable(read_file(dir_ / "sub/new.json")), report);
  EXPECT_EQ(fs::read_symlink(dir_ / "link.json"), "sub/new.json");

  // One whose directory does not exist is refused, naming that directory.
  fs::create_symlink("missing/new.json", dir_ / "nowhere.json");
  r = simulate("--report " + (dir_ / "nowhere.json"));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "capsim simulate: --report " + (dir_ / "nowhere.json") + ": directory " + (dir_ / "missing") +
                       " does not exist\n");
}

TEST_P(CliOutputTargets, AFifoIsWrittenThrough) {
  const std::string report = reference_report();
  const std::string fifo = dir_ / "fifo.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0666), 0) << std::strerror(errno);
  if (GetParam() == User::Nobody) give_to_nobody(dir_.path());
  FifoReader reader(fifo);
  const RunResult r = simulate("--report " + fifo);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(comparable(reader.finish()), report);
  struct stat st {};
  ASSERT_EQ(::lstat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
  EXPECT_EQ(directory_entries(dir_.path()), (std::vector<std::string>{"fifo.json", "s.png"}));
}

// The command's own lines move to stderr, so stdout carries the report alone.
TEST_P(CliOutputTargets, DashIsStandardOutput) {
  const std::string report = reference_report();
  const RunResult r = simulate("--report -");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(comparable(r.out), report);
  EXPECT_EQ(r.err.rfind("CAP simulation: 2x2 cells", 0), 0u) << r.err;
  EXPECT_EQ(directory_entries(dir_.path()), std::vector<std::string>{"s.png"});

  // lattice writes its scene there too.
  if (GetParam() == User::Nobody) give_to_nobody(dir_.path());
  const RunResult l = run_capsim("lattice 16 -o -", dir_, "", launcher_);
  ASSERT_EQ(l.status, 0) << l.err;
  EXPECT_NE(l.out.find("sphere("), std::string::npos) << l.out;
  EXPECT_EQ(l.err, "-: 16 spheres, 2 x 2 x 4\n");
}

TEST_P(CliOutputTargets, ACharacterDeviceIsWrittenThroughAndStaysADevice) {
  fs::create_symlink("/dev/null", dir_ / "null.json");
  const RunResult r = simulate("--report " + (dir_ / "null.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  struct stat st {};
  ASSERT_EQ(::stat("/dev/null", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
  EXPECT_EQ(fs::read_symlink(dir_ / "null.json"), "/dev/null");
  EXPECT_EQ(directory_entries(dir_.path()), (std::vector<std::string>{"null.json", "s.png"}));
}

TEST_P(CliOutputTargets, ADirectoryOrASocketIsRefusedBeforeAnyWork) {
  fs::create_directory(dir_.path() / "folder");
  const std::string socket_path = dir_ / "sock";
  const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
  ASSERT_GE(fd, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  ASSERT_LT(socket_path.size(), sizeof(address.sun_path));
  std::strcpy(address.sun_path, socket_path.c_str());
  ASSERT_EQ(::bind(fd, reinterpret_cast<const sockaddr*>(&address), sizeof(address)), 0) << std::strerror(errno);
  fs::create_symlink("folder", dir_ / "folder-link");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {dir_ / "folder", "is a directory"}, {dir_ / "folder-link", "is a directory"}, {socket_path, "is a socket"}};
  for (const auto& [path, reason] : cases) {
    const RunResult r = simulate("--report " + path);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "capsim simulate: --report " + path + ": " + reason + "\n");
  }
  ::close(fd);
  EXPECT_EQ(directory_entries(dir_.path()), (std::vector<std::string>{"folder", "folder-link", "sock"}));
}

TEST_P(CliOutputTargets, AtMostOneOutputGoesToStandardOutput) {
  const RunResult r = simulate("--report - --trace -");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "capsim simulate: --trace - is standard output, which --report - already takes: at most one "
                   "output can go to standard output\n");
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(directory_entries(dir_.path()), std::vector<std::string>{});
}

// The scene is broken: the run fails after its outputs were staged, and
// nothing reaches any of them, whatever kind.
TEST_P(CliOutputTargets, AFailedRunWritesNothing) {
  std::ofstream(dir_ / "broken.csg") << "sphere(;\n";
  std::ofstream(dir_ / "real.json") << "old";
  fs::create_symlink("real.json", dir_ / "link.json");
  const std::string fifo = dir_ / "fifo.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0666), 0) << std::strerror(errno);
  if (GetParam() == User::Nobody) give_to_nobody(dir_.path());
  FifoReader reader(fifo);
  const RunResult r = simulate("--report " + (dir_ / "link.json") + " --trace " + fifo + " --html -",
                               dir_ / "broken.csg");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err.rfind(dir_ / "broken.csg:1:", 0), 0u) << r.err;
  EXPECT_EQ(reader.finish(), "");
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(read_file(dir_ / "real.json"), "old");
  EXPECT_EQ(directory_entries(dir_.path()), (std::vector<std::string>{"broken.csg", "fifo.json", "link.json", "real.json"}));
}

// Only an ordinary user meets permissions: root may write any file.
TEST_P(CliOutputTargets, AFifoThatCannotBeWrittenIsRefusedBeforeAnyWork) {
  if (GetParam() == User::Invoker && ::geteuid() == 0) GTEST_SKIP() << "root may write any FIFO";
  const std::string fifo = dir_ / "fifo.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0666), 0) << std::strerror(errno);
  if (GetParam() == User::Nobody) give_to_nobody(dir_.path());
  ASSERT_EQ(::chmod(fifo.c_str(), 0444), 0);
  const RunResult r = simulate("--report " + fifo);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "capsim simulate: --report " + fifo + ": cannot write to it: Permission denied\n");
  EXPECT_EQ(directory_entries(dir_.path()), std::vector<std::string>{"fifo.json"});
}

INSTANTIATE_TEST_SUITE_P(Users, CliOutputTargets, ::testing::Values(User::Invoker, User::Nobody),
                         [](const ::testing::TestParamInfo<User>& info) {
                           return info.param == User::Invoker ? std::string("Invoker") : std::string("Nobody");
                         });

// bench modes reads its baseline before it may rewrite it: that cannot be a stream.
TEST(CliOutputTargetsBench, TheBaselineCannotBeStandardOutput) {
  TempDir dir;
  const RunResult r = run_capsim(
      "bench modes --size 48x48 --update --baseline - --scenes " + std::string(CAPSIM_SOURCE_DIR) + "/scenes", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "capsim bench modes: --baseline -: the baseline is read as well as written, so it cannot be "
                   "standard output\n");
  EXPECT_EQ(r.out, "");
}

}  // namespace
