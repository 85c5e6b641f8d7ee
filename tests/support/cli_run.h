#pragma once
// Runs the capsim binary from tests and captures what it printed.

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace capsim::testing {

struct RunResult {
  int status = -1;  // exit status; -1 if a signal ended the process
  int signal = 0;   // the signal that ended it, if one did
  std::string out;  // stdout
  std::string err;  // stderr
};

inline std::string read_file(const std::filesystem::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

// The names in dir, sorted.
inline std::vector<std::string> directory_entries(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// A fresh directory for one test's files, removed when the test ends.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string("capsim-") + info->test_suite_name() + "-" + info->name() + "-" +
                       std::to_string(::getpid());
    std::replace(name.begin(), name.end(), '/', '_');  // parameterised tests' names hold '/'
    path_ = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() { std::filesystem::remove_all(path_); }
  const std::filesystem::path& path() const { return path_; }
  std::string operator/(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

// Runs program (a capsim binary) with args, its output captured in dir's
// .stdout and .stderr, which are removed again. args are passed through the
// shell as written; quote paths with spaces. shell_setup, if given, runs in
// that shell first (e.g. "ulimit -f 2;"), and the program then replaces the
// shell, so a signal that ends it is reported. launcher, if given, is a
// command that runs the program (e.g. one that drops privileges, as_user.h).
inline RunResult run_program(const std::string& program, const std::string& args, const TempDir& dir,
                             const std::string& shell_setup = "", const std::string& launcher = "") {
  const std::string out = dir / ".stdout", err = dir / ".stderr";
  const std::string cmd =
      shell_setup + " exec " + launcher + " " + program + " " + args + " >" + out + " 2>" + err;
  const int raw = std::system(cmd.c_str());
  RunResult r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.signal = WIFSIGNALED(raw) ? WTERMSIG(raw) : 0;
  r.out = read_file(out);
  r.err = read_file(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

// The build's capsim, as run_program runs it.
inline RunResult run_capsim(const std::string& args, const TempDir& dir, const std::string& shell_setup = "",
                            const std::string& launcher = "") {
  return run_program(CAPSIM_EXE, args, dir, shell_setup, launcher);
}

// The same, with `cwd` as its current directory.
inline RunResult run_program_in(const std::filesystem::path& cwd, const std::string& program,
                                const std::string& args, const TempDir& dir) {
  return run_program(program, args, dir, "cd '" + cwd.string() + "' &&");
}

// Every file and directory under dir, as paths relative to it, in order.
inline std::set<std::string> files_under(const std::filesystem::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir))
    names.insert(entry.path().lexically_relative(dir).generic_string());
  return names;
}

inline std::string scene_path(const std::string& name) {
  return std::string(CAPSIM_SOURCE_DIR) + "/scenes/" + name;
}

}  // namespace capsim::testing
