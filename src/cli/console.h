#pragma once
// What a command prints for people, apart from its errors and warnings:
// - its summary, the few lines that say what the run came to, and its detail
//   (tables, a row per cell or per run), on stdout; or on stderr when one of
//   its outputs goes to standard output, so that stdout carries only that
//   output's bytes;
// - its progress (timed lines, a percentage on a terminal), on stderr.
// With --quiet only the summary is printed.
//
// Standard output's reader may go away early (`capsim ... | head -1`). main
// ignores SIGPIPE, so a write to it fails with EPIPE instead of ending the
// process; the console then stops printing to stdout and the command goes on:
// its outputs are files, and are still written. Any other failure to write
// stdout is an error.

#include <CLI/CLI.hpp>

#include <chrono>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace capsim::cli {

class Console {
 public:
  explicit Console(bool quiet) : quiet_(quiet) {}

  // An output goes to standard output: summary and detail go to stderr.
  void divert_to_stderr() { diverted_ = true; }

  void summary(std::string_view text) const;
  void detail(std::string_view text) const;  // nothing with --quiet
  void progress(std::string_view text) const;  // on stderr; nothing with --quiet
  // Whether to show a percentage while tracing: on a terminal, without --quiet.
  bool progress_bar() const;

 private:
  bool quiet_;
  bool diverted_ = false;
};

// Registers --quiet on cmd; `summary` names the lines it keeps, e.g. "the
// verdict", or is empty for a command with no summary.
void add_quiet_flag(CLI::App& cmd, bool& quiet, const std::string& summary);

// Timed progress lines for the long paper commands (repro, calibrate): what
// each is doing, after the seconds since it began.
class ElapsedLog {
 public:
  explicit ElapsedLog(const Console& console) : console_(&console), start_(std::chrono::steady_clock::now()) {}
  double seconds() const;
  void operator()(const std::string& what) const;  // "[   12.3 s] what"

 private:
  const Console* console_;
  std::chrono::steady_clock::time_point start_;
};

// The wall time of each stage of a run (`render --timings`): reading the
// scene, preparing it, tracing, writing. A stage ended again (the next frame
// of a sequence) adds to its time. POV-Ray ends a render with its parse and
// trace times in the same way.
class StageTimes {
 public:
  StageTimes() : last_(std::chrono::steady_clock::now()) {}
  // Ends the stage running since the last call (or since construction) as `stage`.
  void end(std::string_view stage);
  // The stages in the order first ended, and their sum:
  // "timings (wall clock): read 9.8 ms, prepare 4.1 ms, ...; 118.9 ms in all\n".
  std::string line() const;

 private:
  std::chrono::steady_clock::time_point last_;
  std::vector<std::pair<std::string, double>> stages_;  // milliseconds
};

}  // namespace capsim::cli
