#include "cli/console.h"

#include "capsim/system/progress.h"
#include "cli/options/cli_options.h"

#include <fmt/core.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace capsim::cli {

namespace {

std::atomic<bool> reader_gone{false};

// Writes text and flushes it, so that a failure is seen here rather than at
// exit. On stderr a failure has nowhere to be told and is let go.
void put(std::FILE* f, std::string_view text) {
  if (f == stdout && reader_gone.load()) return;
  if (std::fwrite(text.data(), 1, text.size(), f) == text.size() && std::fflush(f) == 0) return;
  const int error = errno;
  std::clearerr(f);
  if (f != stdout) return;
  if (error == EPIPE) {
    reader_gone.store(true);
    return;
  }
  throw std::runtime_error(fmt::format("standard output: {}", std::strerror(error)));
}

}  // namespace

void Console::summary(std::string_view text) const { put(diverted_ ? stderr : stdout, text); }

void Console::detail(std::string_view text) const {
  if (!quiet_) summary(text);
}

void Console::progress(std::string_view text) const {
  if (!quiet_) put(stderr, text);
}

bool Console::progress_bar() const { return !quiet_ && Progress::stderr_is_terminal(); }

void add_quiet_flag(CLI::App& cmd, bool& quiet, const std::string& summary) {
  const std::string kept = summary.empty() ? "warnings and errors" : summary + ", warnings and errors";
  accepts(cmd.add_flag("--quiet", quiet, "No progress; print only " + kept), flag_values());
}

double ElapsedLog::seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void ElapsedLog::operator()(const std::string& what) const {
  console_->progress(fmt::format("[{:7.1f} s] {}\n", seconds(), what));
}

void StageTimes::end(std::string_view stage) {
  const auto now = std::chrono::steady_clock::now();
  const double ms = std::chrono::duration<double, std::milli>(now - last_).count();
  last_ = now;
  for (auto& [name, total] : stages_) {
    if (name == stage) {
      total += ms;
      return;
    }
  }
  stages_.emplace_back(stage, ms);
}

std::string StageTimes::line() const {
  std::string out = "timings (wall clock):";
  double sum = 0;
  for (std::size_t k = 0; k < stages_.size(); ++k) {
    out += fmt::format("{} {} {:.1f} ms", k == 0 ? "" : ",", stages_[k].first, stages_[k].second);
    sum += stages_[k].second;
  }
  return out + fmt::format("; {:.1f} ms in all\n", sum);
}

}  // namespace capsim::cli
