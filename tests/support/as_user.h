#pragma once
// Runs capsim as an ordinary user too. CI runs the tests as root, for whom
// file permissions do not hold; tests of what an output path may be then also
// run capsim as the user nobody (uid and gid 65534) through util-linux's
// setpriv, with their temporary directory given to that user.

#include "support/cli_run.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace capsim::testing {

inline constexpr int kNobody = 65534;

// The launcher that runs capsim as nobody, who must also be able to read
// `inputs` (the scene files the runs name); "" with the reason in why_not when
// that cannot be done.
inline std::string unprivileged_launcher(std::string& why_not, const std::vector<std::string>& inputs = {}) {
  if (::geteuid() != 0) {
    why_not = "the tests run as an ordinary user already: the run as the invoker is the unprivileged one";
    return "";
  }
  const std::string launcher = "setpriv --reuid=65534 --regid=65534 --clear-groups";
  const std::string probe = launcher + " " + CAPSIM_EXE + " --version >/dev/null 2>&1";
  if (std::system(probe.c_str()) != 0) {
    why_not = "setpriv cannot run capsim as uid 65534 (setpriv missing, or the binary out of that user's reach)";
    return "";
  }
  for (const std::string& input : inputs) {
    if (std::system((launcher + " test -r '" + input + "'").c_str()) != 0) {
      why_not = "uid 65534 cannot read " + input +
                ": a directory above it is closed to other users (mode 0700, as mktemp -d makes one); these "
                "cases need the checkout readable by all";
      return "";
    }
  }
  return launcher;
}

// Gives dir and everything in it to nobody, links themselves included.
inline void give_to_nobody(const std::filesystem::path& dir) {
  ASSERT_EQ(::lchown(dir.c_str(), kNobody, kNobody), 0) << dir;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
    ASSERT_EQ(::lchown(e.path().c_str(), kNobody, kNobody), 0) << e.path();
}

}  // namespace capsim::testing
