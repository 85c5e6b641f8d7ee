#pragma once
// Progress on stderr for long runs: silent unless stderr is a terminal, and
// silent for the first second, so short runs and redirected runs print nothing.
// Progress never reaches stdout or any output file.

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace capsim {

class Progress {
 public:
  // enabled = false prints nothing; stderr_is_terminal() is the usual choice.
  Progress(std::string label, std::uint64_t total, bool enabled);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // Thread-safe.
  void advance(std::uint64_t n);

  static bool stderr_is_terminal();

 private:
  void print(std::uint64_t done);

  std::string label_;
  std::uint64_t total_;
  bool enabled_;
  std::atomic<std::uint64_t> done_{0};
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_print_;
  std::mutex print_mutex_;
  bool printed_ = false;
};

}  // namespace capsim
