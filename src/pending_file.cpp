#include "capsim/pending_file.h"

#include <fcntl.h>
#include <fmt/core.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>
#include <stdexcept>
#include <utility>

namespace capsim {

namespace {

namespace fs = std::filesystem;

std::runtime_error failure(const std::string& target, const std::string& reason) {
  return std::runtime_error(fmt::format("{}: {}", target, reason));
}

// The directory a target goes in, as messages name it.
fs::path directory_of(const fs::path& target) {
  return target.parent_path().empty() ? fs::path(".") : target.parent_path();
}

void check_target(const std::string& target) {
  const fs::path path(target);
  const std::string name = path.filename().string();
  if (name.empty() || name == "." || name == "..") throw failure(target, "names a directory, not a file");
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw failure(target, "is a directory");
  const fs::path dir = directory_of(path);
  const fs::file_status status = fs::status(dir, ec);
  if (!fs::exists(status)) throw failure(target, fmt::format("directory {} does not exist", dir.string()));
  if (!fs::is_directory(status)) throw failure(target, fmt::format("{} is not a directory", dir.string()));
}

// Creates a new empty file with a random hidden name beside target; O_EXCL
// makes sure no other writer's file is taken over.
std::string create_temporary_beside(const std::string& target) {
  static thread_local std::mt19937_64 rng{std::random_device{}()};
  const fs::path path(target);
  for (int attempt = 0;; ++attempt) {
    const std::string temp =
        (path.parent_path() / fmt::format(".{}.{:016x}.tmp", path.filename().string(), rng())).string();
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      ::close(fd);
      return temp;
    }
    if (errno != EEXIST || attempt == 100)
      throw failure(target, fmt::format("cannot create a file in {}: {}", directory_of(path).string(),
                                        std::strerror(errno)));
  }
}

}  // namespace

PendingFile::PendingFile(std::string target) : target_(std::move(target)) {
  check_target(target_);
  temp_ = create_temporary_beside(target_);
  pending_ = true;
}

PendingFile::PendingFile(PendingFile&& other) noexcept
    : target_(std::move(other.target_)), temp_(std::move(other.temp_)), pending_(std::exchange(other.pending_, false)) {}

PendingFile::~PendingFile() {
  if (pending_) ::unlink(temp_.c_str());
}

void PendingFile::commit() {
  if (!pending_) throw std::logic_error(fmt::format("{}: committed twice", target_));
  if (std::rename(temp_.c_str(), target_.c_str()) != 0) {
    const int error = errno;
    ::unlink(temp_.c_str());
    pending_ = false;
    throw failure(target_, fmt::format("cannot replace it: {}", std::strerror(error)));
  }
  pending_ = false;
}

void commit_all(std::vector<PendingFile>& files) {
  for (PendingFile& f : files) f.commit();
}

}  // namespace capsim
