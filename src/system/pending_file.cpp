#include "capsim/system/pending_file.h"

#include "capsim/system/temp_file_registry.h"

#include <fcntl.h>
#include <fmt/core.h>
#include <unistd.h>

#include <array>
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

// The directory a file goes in, as messages name it.
fs::path directory_of(const fs::path& file) {
  return file.parent_path().empty() ? fs::path(".") : file.parent_path();
}

// Creates a new empty file with a random hidden name beside `beside`, and
// registers it for removal on a signal; O_EXCL makes sure no other writer's file
// is taken over. It is registered before it is created, so that no moment
// exists when it is on disk and a signal would leave it. Messages name target.
std::string create_temporary_beside(const std::string& target, const fs::path& beside, int& signal_slot) {
  static thread_local std::mt19937_64 rng{std::random_device{}()};
  for (int attempt = 0;; ++attempt) {
    const std::string temp =
        (beside.parent_path() / fmt::format(".{}.{:016x}.tmp", beside.filename().string(), rng())).string();
    signal_slot = register_temp_file(temp);
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    const int error = errno;
    if (fd >= 0) {
      ::close(fd);
      return temp;
    }
    unregister_temp_file(std::exchange(signal_slot, -1));
    if (error != EEXIST || attempt == 100)
      throw failure(target, fmt::format("cannot create a file in {}: {}", directory_of(beside).string(),
                                        std::strerror(error)));
  }
}

// Where the content of a target written through waits for commit: the
// system's temporary directory, which a device's or a FIFO's directory (/dev)
// may not be.
fs::path staging_name(const OutputTarget& destination) {
  std::error_code ec;
  fs::path dir = fs::temp_directory_path(ec);
  if (ec) dir = "/tmp";
  const std::string name =
      destination.path == kStandardOutputPath ? "stdout" : fs::path(destination.path).filename().string();
  return dir / ("capsim-" + name);
}

// Copies the file at `from` into `to_fd` to its end; returns 0 or the errno of
// the failure.
int copy_into(const std::string& from, int to_fd) {
  const int in = ::open(from.c_str(), O_RDONLY | O_CLOEXEC);
  if (in < 0) return errno;
  std::array<char, 1 << 16> buffer;
  int error = 0;
  while (error == 0) {
    const ssize_t got = ::read(in, buffer.data(), buffer.size());
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) {
      if (got < 0) error = errno;
      break;
    }
    for (ssize_t done = 0; done < got;) {
      const ssize_t n = ::write(to_fd, buffer.data() + done, static_cast<std::size_t>(got - done));
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) {
        error = errno;
        break;
      }
      done += n;
    }
  }
  ::close(in);
  return error;
}

// Opens the target (standard output is already open; a FIFO's open waits for
// a reader) and copies the content in; returns 0 or the errno of the failure.
int write_through(const std::string& temp, const std::string& path) {
  if (path == kStandardOutputPath) {
    std::fflush(stdout);  // whatever was printed before comes first
    return copy_into(temp, STDOUT_FILENO);
  }
  int fd;
  do fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
  while (fd < 0 && errno == EINTR);
  if (fd < 0) return errno;
  const int error = copy_into(temp, fd);
  const bool closed = ::close(fd) == 0;
  return error != 0 ? error : closed ? 0 : errno;
}

}  // namespace

PendingFile::PendingFile(std::string target)
    : target_(std::move(target)), destination_(resolve_output_target(target_)) {
  temp_ = create_temporary_beside(target_, writes_through() ? staging_name(destination_) : fs::path(destination_.path),
                                  signal_slot_);
  pending_ = true;
}

PendingFile::PendingFile(PendingFile&& other) noexcept
    : target_(std::move(other.target_)),
      destination_(std::move(other.destination_)),
      temp_(std::move(other.temp_)),
      pending_(std::exchange(other.pending_, false)),
      signal_slot_(std::exchange(other.signal_slot_, -1)) {}

PendingFile::~PendingFile() {
  if (pending_) ::unlink(temp_.c_str());
  unregister_temp_file(signal_slot_);
}

void PendingFile::commit() {
  if (!pending_) throw std::logic_error(fmt::format("{}: committed twice", target_));
  int error = 0;
  if (writes_through()) {
    error = write_through(temp_, destination_.path);
    ::unlink(temp_.c_str());
  } else if (std::rename(temp_.c_str(), destination_.path.c_str()) != 0) {
    error = errno;
    ::unlink(temp_.c_str());
  }
  pending_ = false;
  // After the rename: a signal in between finds no file under the old name.
  unregister_temp_file(std::exchange(signal_slot_, -1));
  if (error != 0)
    throw failure(target_, fmt::format("cannot {} it: {}", writes_through() ? "write to" : "replace",
                                       std::strerror(error)));
}

void commit_all(std::vector<PendingFile>& files) {
  for (PendingFile& f : files)
    if (f.writes_through()) f.commit();
  for (PendingFile& f : files)
    if (!f.writes_through()) f.commit();
}

}  // namespace capsim
