#include "capsim/pending_file.h"

#include "capsim/temp_file_registry.h"

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

// Creates a new empty file with a random hidden name beside target, and
// registers it for removal on a signal; O_EXCL makes sure no other writer's file
// is taken over. It is registered before it is created, so that no moment
// exists when it is on disk and a signal would leave it.
std::string create_temporary_beside(const std::string& target, int& signal_slot) {
  static thread_local std::mt19937_64 rng{std::random_device{}()};
  const fs::path path(target);
  for (int attempt = 0;; ++attempt) {
    const std::string temp =
        (path.parent_path() / fmt::format(".{}.{:016x}.tmp", path.filename().string(), rng())).string();
    signal_slot = register_temp_file(temp);
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    const int error = errno;
    if (fd >= 0) {
      ::close(fd);
      return temp;
    }
    unregister_temp_file(std::exchange(signal_slot, -1));
    if (error != EEXIST || attempt == 100)
      throw failure(target, fmt::format("cannot create a file in {}: {}", directory_of(path).string(),
                                        std::strerror(error)));
  }
}

}  // namespace

PendingFile::PendingFile(std::string target) : target_(std::move(target)) {
  check_target(target_);
  temp_ = create_temporary_beside(target_, signal_slot_);
  pending_ = true;
}

PendingFile::PendingFile(PendingFile&& other) noexcept
    : target_(std::move(other.target_)),
      temp_(std::move(other.temp_)),
      pending_(std::exchange(other.pending_, false)),
      signal_slot_(std::exchange(other.signal_slot_, -1)) {}

PendingFile::~PendingFile() {
  if (pending_) ::unlink(temp_.c_str());
  unregister_temp_file(signal_slot_);
}

void PendingFile::commit() {
  if (!pending_) throw std::logic_error(fmt::format("{}: committed twice", target_));
  const bool renamed = std::rename(temp_.c_str(), target_.c_str()) == 0;
  const int error = errno;
  if (!renamed) ::unlink(temp_.c_str());
  pending_ = false;
  // After the rename: a signal in between finds no file under the old name.
  unregister_temp_file(std::exchange(signal_slot_, -1));
  if (!renamed) throw failure(target_, fmt::format("cannot replace it: {}", std::strerror(error)));
}

void commit_all(std::vector<PendingFile>& files) {
  for (PendingFile& f : files) f.commit();
}

}  // namespace capsim
