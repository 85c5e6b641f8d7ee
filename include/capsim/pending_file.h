#pragma once
// An output file that appears whole or not at all. It is written under a
// temporary name beside its target (".NAME.RANDOM.tmp", in the same directory
// so that the final rename stays on one file system) and renamed over the
// target by commit(); a PendingFile destroyed without commit() removes its
// temporary file, and so does a signal that ends the process once main has
// called remove_temp_files_on_signals (temp_file_registry.h). Creating the
// temporary file first proves, before any work, that the target can be written.

#include <string>
#include <vector>

namespace capsim {

class PendingFile {
 public:
  // Checks that target names a file (not a directory) in a directory that
  // exists, and creates the empty temporary file there. Throws
  // std::runtime_error "TARGET: REASON" (e.g. "out/x.png: cannot create a file
  // in out: Permission denied").
  explicit PendingFile(std::string target);
  PendingFile(PendingFile&& other) noexcept;
  PendingFile(const PendingFile&) = delete;
  PendingFile& operator=(const PendingFile&) = delete;
  PendingFile& operator=(PendingFile&&) = delete;
  ~PendingFile();

  const std::string& target() const { return target_; }
  // Where the content goes; a writer opens it again, truncating it.
  const std::string& temp_path() const { return temp_; }

  // Renames the temporary file over the target. Throws std::runtime_error
  // "TARGET: cannot replace it: REASON" and removes the temporary file.
  void commit();

 private:
  std::string target_;
  std::string temp_;
  bool pending_ = false;  // the temporary file exists and is ours to remove
  int signal_slot_ = -1;  // in the temp_file_registry, so that a signal removes it too
};

// Commits every file, in order, once all are written: a failure while writing
// any of them leaves none of them changed.
void commit_all(std::vector<PendingFile>& files);

}  // namespace capsim
