#pragma once
// An output file that appears whole or not at all. Its content is written to a
// temporary file first and put in place by commit(), as output_target.h
// decides for its target:
// - a file replaced whole (a regular file, a new name, or what a symbolic link
//   leads to): the temporary file is ".NAME.RANDOM.tmp" beside that file (in
//   the same directory so that the final rename stays on one file system) and
//   is renamed over it;
// - a target written through (a FIFO, a character device, "-" for standard
//   output): the temporary file is in the system's temporary directory
//   ($TMPDIR, else /tmp), and commit() copies it into the target.
// A PendingFile destroyed without commit() removes its temporary file, and so
// does a signal that ends the process once main has called
// remove_temp_files_on_signals (temp_file_registry.h); nothing reaches a
// target before commit(). Creating the temporary file first proves, before any
// work, that the content has somewhere to go.

#include "capsim/system/output_target.h"

#include <string>
#include <vector>

namespace capsim {

class PendingFile {
 public:
  // Resolves the target (resolve_output_target) and creates the empty
  // temporary file. Throws std::runtime_error "TARGET: REASON" (e.g.
  // "out/x.png: cannot create a file in out: Permission denied").
  explicit PendingFile(std::string target);
  PendingFile(PendingFile&& other) noexcept;
  PendingFile(const PendingFile&) = delete;
  PendingFile& operator=(const PendingFile&) = delete;
  PendingFile& operator=(PendingFile&&) = delete;
  ~PendingFile();

  // The path as given, which messages name.
  const std::string& target() const { return target_; }
  // Where the content goes; a writer opens it again, truncating it.
  const std::string& temp_path() const { return temp_; }
  bool writes_through() const { return destination_.kind == OutputTarget::Kind::WriteThrough; }

  // Renames the temporary file over the file replaced, or copies it into the
  // target written through, then removes it. Throws std::runtime_error
  // "TARGET: cannot replace it: REASON" or "TARGET: cannot write to it: REASON"
  // (e.g. "-: cannot write to it: Broken pipe" once standard output's reader
  // has gone) and removes the temporary file.
  void commit();

 private:
  std::string target_;
  OutputTarget destination_;
  std::string temp_;
  bool pending_ = false;  // the temporary file exists and is ours to remove
  int signal_slot_ = -1;  // in the temp_file_registry, so that a signal removes it too
};

// Commits every file once all are written: those written through first, then,
// in order, those replaced. A failure while writing any of them leaves none of
// them changed; a target written through that fails at commit (its reader gone)
// leaves the files replaced unchanged too.
void commit_all(std::vector<PendingFile>& files);

}  // namespace capsim
