#pragma once
// Where a simulated run came from: the command line as typed, capsim's
// version, the scene files and the cost profile with the SHA-256 of their
// content, and every option's effective value. The --report JSON, the text
// report and the HTML page all carry it, so a report names the exact inputs
// that give it again. Nothing in it depends on the host or the time of the run
// (no clock, no host name, no path the user did not type); --threads is
// recorded as typed, though no output depends on it. docs/simulation.md
// documents every field.

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace capsim::sim {

struct InputFile {
  std::string path;    // as given on the command line
  std::string sha256;  // of the file's bytes
};

struct Provenance {
  std::vector<std::string> argv;  // the command line as typed, program name first
  std::string version;            // capsim's
  std::vector<InputFile> scenes;  // each scene file as given, in order
  std::string profile;            // --profile as given: a built-in name or a file
  std::string profile_name;       // the "name" inside the profile
  std::string profile_sha256;     // of the profile's JSON text (built in or read)
  // Every option of the command (named as on the command line, without the
  // dashes, '-' as '_') with the value the run used.
  nlohmann::json options = nlohmann::json::object();
};

nlohmann::json provenance_json(const Provenance& p);

// The argv as one line a POSIX shell reads back as the same words: a word
// with anything but letters, digits and -_./=:,+@% in single quotes.
std::string shell_line(const std::vector<std::string>& argv);

// The options as "name value" pairs, one line: "cells 8x8, mode dot, ...";
// a string as it is, null as "none".
std::string options_line(const nlohmann::json& options);

// The block the text report ends with:
//   provenance: capsim 0.1.0
//     command  capsim simulate ...
//     scene    balls.csg sha256 ...
//     profile  cap (name cap) sha256 ...
//     options  aa 0, aa_threshold 0.3, ...
std::string provenance_text(const Provenance& p);

}  // namespace capsim::sim
