#pragma once
// What capsim tells of a command that ended with an exception, and its exit
// status: main's answer to every command, and a sweep's for each MPI rank
// that failed (rank 0 tells them all).

#include <exception>
#include <string>

namespace capsim::cli {

struct CommandFailure {
  int status = 1;  // 2 for a usage error, 1 for any other
  std::string message;
};

// command: "capsim sweep", as command_name gives it. A scene's error is told
// as FILE:LINE:COL: message, a usage error and running out of memory after
// the command's name, any other after "capsim". Precondition: e holds a
// std::exception; any other is thrown again.
CommandFailure describe_failure(const std::exception_ptr& e, const std::string& command);

}  // namespace capsim::cli
