#include "cli/scad_export.h"

#include "capsim/scene/scene.h"
#include "capsim/system/temp_file_registry.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string_view>

extern char** environ;

namespace capsim::cli {
namespace {

constexpr std::string_view kInstall =
    "install the openscad package, e.g. apt-get install openscad, or export the model to .csg yourself "
    "(openscad -o model.csg model.scad)";

[[noreturn]] void refuse(const std::string& scad, const std::string& message) {
  throw SceneError(SourceLoc{std::make_shared<const std::string>(scad), 0, 0}, message);
}

// The executable `openscad` in the first directory of PATH that holds one, as
// execvp would find it (an empty entry is the current directory); "" if none.
std::string find_openscad() {
  const char* path = std::getenv("PATH");
  const std::string dirs = path ? path : "/usr/bin:/bin";
  std::size_t start = 0;
  for (;;) {
    const std::size_t end = std::min(dirs.find(':', start), dirs.size());
    const std::string dir = dirs.substr(start, end - start);
    const std::string candidate = (dir.empty() ? std::string(".") : dir) + "/openscad";
    struct stat info {};
    if (::stat(candidate.c_str(), &info) == 0 && S_ISREG(info.st_mode) && ::access(candidate.c_str(), X_OK) == 0)
      return candidate;
    if (end == dirs.size()) return "";
    start = end + 1;
  }
}

// Runs `argv` (argv[0] the program's path) with stdin from /dev/null and
// stdout and stderr into `log`; returns its wait status.
int run(const std::vector<std::string>& args, const std::string& log, const std::string& scad) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int error = posix_spawn(&pid, args[0].c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (error != 0) refuse(scad, fmt::format("cannot run {}: {}", args[0], std::strerror(error)));
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) refuse(scad, fmt::format("cannot wait for {}: {}", args[0], std::strerror(errno)));
  }
  return status;
}

std::string read_all(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

bool starts_with_any(std::string_view line, std::initializer_list<std::string_view> prefixes) {
  return std::any_of(prefixes.begin(), prefixes.end(), [&](std::string_view p) { return line.starts_with(p); });
}

// OpenSCAD's warnings and echo() output, passed on; its progress notes dropped.
void pass_on_messages(const std::string& output) {
  std::istringstream lines(output);
  for (std::string line; std::getline(lines, line);) {
    if (starts_with_any(line, {"WARNING:", "DEPRECATED:", "ECHO:"})) fmt::print(stderr, "openscad: {}\n", line);
  }
}

std::string how_it_ended(int status) {
  if (WIFSIGNALED(status)) return fmt::format("openscad was ended by signal {}", WTERMSIG(status));
  return fmt::format("openscad exited with status {}", WEXITSTATUS(status));
}

std::string trimmed(std::string s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
  return s;
}

}  // namespace

bool is_scad_file(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".scad";
}

ScadExports::ScadExports(std::vector<std::string> defines) : defines_(std::move(defines)) {}

ScadExports::~ScadExports() {
  std::error_code ignored;
  if (!dir_.empty()) std::filesystem::remove_all(dir_, ignored);
  for (const File& f : files_) unregister_temp_file(f.slot);
  unregister_temp_file(dir_slot_);
}

void ScadExports::add_file(const std::string& path) { files_.push_back(File{path, register_temp_file(path)}); }

std::vector<std::string> ScadExports::export_csg(const std::string& scad, const std::string& name,
                                                 int animate_frames) {
  const std::string openscad = find_openscad();
  if (openscad.empty()) refuse(scad, fmt::format("a .scad file needs OpenSCAD to read it, and 'openscad' is not "
                                                 "on PATH: {}",
                                                 kInstall));
  if (dir_.empty()) {
    // Absolute: OpenSCAD 2021.01 writes a relative -o path beside its input.
    std::string pattern = (std::filesystem::absolute(std::filesystem::temp_directory_path()) / "capsim-scad.XXXXXX");
    if (::mkdtemp(pattern.data()) == nullptr)
      refuse(scad, fmt::format("cannot make a temporary directory for OpenSCAD's export ({}): {}", pattern,
                               std::strerror(errno)));
    dir_ = pattern;
    dir_slot_ = register_temp_file(dir_);
  }
  const std::string log = dir_ + "/" + name + ".log";
  const std::string output = dir_ + "/" + name + ".csg";
  std::vector<std::string> exports;
  if (animate_frames > 0) {
    // --animate K writes NAME00000.csg ... beside -o's path, at $t = k / K.
    for (int k = 0; k < animate_frames; ++k) exports.push_back(fmt::format("{}/{}{:05d}.csg", dir_, name, k));
  } else {
    exports.push_back(output);
  }
  add_file(log);
  for (const std::string& e : exports) add_file(e);

  std::vector<std::string> args = {openscad, "-o", output};
  if (animate_frames > 0) {
    args.push_back("--animate");
    args.push_back(std::to_string(animate_frames));
  }
  for (const std::string& d : defines_) {
    args.push_back("-D");
    args.push_back(d);
  }
  // A name starting with '-' would read as an option.
  args.push_back(scad.starts_with("-") ? "./" + scad : scad);
  const int status = run(args, log, scad);
  const std::string printed = trimmed(read_all(log));
  const bool exported = std::all_of(exports.begin(), exports.end(),
                                    [](const std::string& e) { return std::filesystem::exists(e); });
  const bool succeeded = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  if (!succeeded || !exported) {
    refuse(scad, fmt::format("OpenSCAD could not export it to CSG ({}{}); it printed:{}", how_it_ended(status),
                             succeeded ? ", but wrote no export" : "",
                             printed.empty() ? " nothing" : "\n" + printed));
  }
  pass_on_messages(printed);
  return exports;
}

}  // namespace capsim::cli
