#pragma once
// Usage errors: a command line that cannot run as given (a missing, unknown or
// repeated option, a value out of its range, an output that cannot be written,
// an image too large for the memory). main prints each on one line after the
// command's name ("capsim render: ...") and exits with status 2; scene-file
// errors and failures while running exit with status 1.

#include <CLI/CLI.hpp>

#include <stdexcept>
#include <string>
#include <vector>

namespace capsim::cli {

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// value as a message quotes it: control bytes escaped (\xNN), quoted when empty
// or holding a space.
std::string shown(const std::string& value);

// One line for a CLI11 parse error (the command's name not included): names
// the option or argument at fault and what it accepts (accepted_values), and
// for an unknown command or option the closest known name.
std::string describe_parse_error(const CLI::App& app, const CLI::ParseError& e);

// "capsim" and the name of the subcommand parsed, if any: the prefix of messages.
std::string command_name(const CLI::App& app);

// What word likely stands for: the one candidate it abbreviates (a word of two
// or more characters that starts it), else the candidate nearest by edit
// distance (insertions, deletions and substitutions) if that is at most a
// third of the word's length, rounded down; "" otherwise.
std::string closest_name(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace capsim::cli
