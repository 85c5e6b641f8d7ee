#pragma once
// The files a command writes, checked and reserved before any work: each is a
// different file, none is one of the command's inputs, and each can be created
// (PendingFile). They are written under temporary names and put in place only
// once all are complete, so a failure leaves none of them changed.

#include "capsim/pending_file.h"

#include <chrono>
#include <string>
#include <vector>

namespace capsim::cli {

struct OutputOption {
  std::string option;  // "--output", "--report", ...
  std::string path;    // empty = not asked for
};

class StagedOutputs {
 public:
  // inputs: files the command reads (scene, profile), which no output may
  // replace. Throws UsageError "OPTION PATH: REASON" for the first output that
  // cannot be written.
  StagedOutputs(const std::vector<OutputOption>& outputs, const std::vector<std::string>& inputs);

  // The pending file of an output asked for. Precondition: its path was not empty.
  PendingFile& operator[](const std::string& option);

  // Puts every output in place, in the order given.
  void commit();

 private:
  std::vector<std::string> options_;
  std::vector<PendingFile> files_;
};

// Timed lines on stderr for the long paper commands (repro, calibrate): what
// each is doing, after the seconds since it began.
class ElapsedLog {
 public:
  ElapsedLog() : start_(std::chrono::steady_clock::now()) {}
  double seconds() const;
  void operator()(const std::string& what) const;  // "[   12.3 s] what"

 private:
  std::chrono::steady_clock::time_point start_;
};

}  // namespace capsim::cli
