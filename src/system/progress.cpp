#include "capsim/system/progress.h"

#include <fmt/core.h>
#include <unistd.h>

#include <cstdio>

namespace capsim {

namespace {
constexpr auto kQuietStart = std::chrono::seconds(1);
constexpr auto kInterval = std::chrono::milliseconds(250);
}  // namespace

Progress::Progress(std::string label, std::uint64_t total, bool enabled)
    : label_(std::move(label)), total_(total), enabled_(enabled),
      start_(std::chrono::steady_clock::now()), last_print_(start_) {}

Progress::~Progress() {
  if (enabled_ && printed_) fmt::print(stderr, "\r{}: done{:20}\n", label_, "");
}

bool Progress::stderr_is_terminal() { return isatty(STDERR_FILENO) == 1; }

void Progress::advance(std::uint64_t n) {
  const std::uint64_t done = done_.fetch_add(n, std::memory_order_relaxed) + n;
  if (enabled_) print(done);
}

void Progress::print(std::uint64_t done) {
  const auto now = std::chrono::steady_clock::now();
  if (now - start_ < kQuietStart) return;
  std::unique_lock lock(print_mutex_, std::try_to_lock);
  if (!lock.owns_lock() || now - last_print_ < kInterval) return;
  last_print_ = now;
  printed_ = true;
  const double percent = total_ ? 100.0 * static_cast<double>(done) / static_cast<double>(total_) : 100.0;
  fmt::print(stderr, "\r{}: {:5.1f}%", label_, percent);
  std::fflush(stderr);
}

}  // namespace capsim
