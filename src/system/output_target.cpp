#include "capsim/system/output_target.h"

#include <fcntl.h>
#include <fmt/core.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace capsim {

namespace {

namespace fs = std::filesystem;

// As the kernel's limit on links followed in one path (MAXSYMLINKS).
constexpr int kMaxLinks = 40;

std::runtime_error failure(const std::string& target, const std::string& reason) {
  return std::runtime_error(fmt::format("{}: {}", target, reason));
}

bool is_link(const std::string& path) {
  struct stat st {};
  return ::lstat(path.c_str(), &st) == 0 && S_ISLNK(st.st_mode);
}

// A file that does not exist yet: its name must be a file's, in a directory
// that exists. Messages name target, the path as given.
void check_new_file(const std::string& target, const fs::path& path) {
  const std::string name = path.filename().string();
  if (name.empty() || name == "." || name == "..") throw failure(target, "names a directory, not a file");
  const fs::path dir = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  std::error_code ec;
  const fs::file_status status = fs::status(dir, ec);
  if (!fs::exists(status)) throw failure(target, fmt::format("directory {} does not exist", dir.string()));
  if (!fs::is_directory(status)) throw failure(target, fmt::format("{} is not a directory", dir.string()));
}

// Standard output must be open for writing; the check is made before any work
// so that a run with nowhere to put its output does not start.
OutputTarget standard_output() {
  const int flags = ::fcntl(STDOUT_FILENO, F_GETFL);
  if (flags < 0) throw failure(kStandardOutputPath, "standard output is closed");
  if ((flags & O_ACCMODE) == O_RDONLY) throw failure(kStandardOutputPath, "standard output is not open for writing");
  return {OutputTarget::Kind::WriteThrough, kStandardOutputPath};
}

}  // namespace

std::string follow_links(const std::string& target) {
  fs::path path(target);
  for (int followed = 0; followed < kMaxLinks && is_link(path.string()); ++followed) {
    std::error_code ec;
    const fs::path to = fs::read_symlink(path, ec);
    if (ec) break;
    path = to.is_absolute() ? to : path.parent_path() / to;
  }
  return path.string();
}

OutputTarget resolve_output_target(const std::string& target) {
  if (target == kStandardOutputPath) return standard_output();
  const std::string name = fs::path(target).filename().string();
  if (name.empty() || name == "." || name == "..") throw failure(target, "names a directory, not a file");
  struct stat st {};
  if (::stat(target.c_str(), &st) != 0) {
    if (errno == ELOOP) throw failure(target, std::strerror(ELOOP));
    if (!is_link(target)) {
      check_new_file(target, target);
      return {OutputTarget::Kind::Replace, target};
    }
    // A dangling link: the file it names is created.
    const std::string leads_to = follow_links(target);
    if (is_link(leads_to)) throw failure(target, std::strerror(ELOOP));
    check_new_file(target, leads_to);
    return {OutputTarget::Kind::Replace, leads_to};
  }
  switch (st.st_mode & S_IFMT) {
    case S_IFREG: {
      if (!is_link(target)) return {OutputTarget::Kind::Replace, target};
      std::error_code ec;
      const fs::path resolved = fs::canonical(target, ec);
      if (ec) throw failure(target, ec.message());
      return {OutputTarget::Kind::Replace, resolved.string()};
    }
    case S_IFIFO:
    case S_IFCHR:
      if (::access(target.c_str(), W_OK) != 0)
        throw failure(target, fmt::format("cannot write to it: {}", std::strerror(errno)));
      return {OutputTarget::Kind::WriteThrough, target};
    case S_IFDIR:
      throw failure(target, "is a directory");
    case S_IFSOCK:
      throw failure(target, "is a socket");
    case S_IFBLK:
      throw failure(target, "is a block device");
    default:
      throw failure(target, "is not a regular file, a FIFO or a character device");
  }
}

bool names_standard_output(const std::string& target) {
  if (target == kStandardOutputPath) return true;
  struct stat out {}, st {};
  // A character device (a terminal, /dev/null) takes any number of writers
  // without harm, so it is not counted as standard output.
  return ::fstat(STDOUT_FILENO, &out) == 0 && ::stat(target.c_str(), &st) == 0 && !S_ISCHR(st.st_mode) &&
         out.st_dev == st.st_dev && out.st_ino == st.st_ino;
}

}  // namespace capsim
