#pragma once
// The files a command writes, checked and reserved before any work: each is a
// different file, at most one is standard output ("-" or the file stdout is),
// none is one of the command's inputs, and each can be created (PendingFile).
// They are written under temporary names and put in place only once all are
// complete, so a failure leaves none of them changed.

#include "capsim/system/pending_file.h"

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

  // Puts every output in place (commit_all).
  void commit();

  // Whether an output goes to standard output: the command's own lines then go
  // to stderr (Console::divert_to_stderr).
  bool stdout_taken() const { return stdout_taken_; }

 private:
  bool stdout_taken_ = false;
  std::vector<std::string> options_;
  std::vector<PendingFile> files_;
};

}  // namespace capsim::cli
