#pragma once
// Where an output path leads, decided before any work, and what writing it
// therefore means:
// - a regular file, or a name that does not exist yet: a file replaced whole
//   (PendingFile renames a finished file over it); a symbolic link is followed
//   to the file it names, resolved fully, and that file is replaced, so the link
//   stays a link; a dangling link creates the file it names;
// - a FIFO, a character device (a terminal, /dev/null) or "-" (standard output):
//   written through, its content copied in once the run has succeeded;
// - anything else (a directory, a socket, a block device) is refused.

#include <string>

namespace capsim {

// The output path that means standard output.
inline constexpr const char* kStandardOutputPath = "-";

struct OutputTarget {
  enum class Kind { Replace, WriteThrough };
  Kind kind = Kind::Replace;
  // Replace: the file renamed over (the path given, or with a link given the
  // file it leads to). WriteThrough: the path opened for writing, or "-".
  std::string path;
};

// Throws std::runtime_error "TARGET: REASON" (e.g. "out: is a directory",
// "sock: is a socket", "-: standard output is closed").
OutputTarget resolve_output_target(const std::string& target);

// target with symbolic links in its last component followed, up to 40 of them,
// relative links read against the link's directory; target itself if it is no
// link. A dangling link leads to the name it holds.
std::string follow_links(const std::string& target);

// Whether target is "-", or the same file (not a character device) as this
// process's standard output, e.g. /dev/stdout when that is a pipe.
bool names_standard_output(const std::string& target);

}  // namespace capsim
