#include "report/text_output.h"

#include <fcntl.h>
#include <fmt/core.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace capsim::sim {

namespace {

// errno's text, read before anything else can change errno.
std::runtime_error write_failure(const PendingFile& out) {
  return std::runtime_error(fmt::format("{}: {}", out.target(), std::strerror(errno)));
}

}  // namespace

void write_text_file(PendingFile& out, const std::string& text) {
  const int fd = ::open(out.temp_path().c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
  if (fd < 0) throw write_failure(out);
  for (std::size_t done = 0; done < text.size();) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const std::runtime_error error = write_failure(out);
      ::close(fd);
      throw error;
    }
    done += static_cast<std::size_t>(n);
  }
  if (::close(fd) != 0) throw write_failure(out);
}

void write_text_file(const std::string& path, const std::string& text) {
  PendingFile out(path);
  write_text_file(out, text);
  out.commit();
}

}  // namespace capsim::sim
