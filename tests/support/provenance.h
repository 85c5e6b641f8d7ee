#pragma once
// A simulate report's provenance records the command line as typed and every
// option, --threads and the output files included, though nothing else in the
// report depends on them. These give a report without those parts, for
// comparing runs given them differently.

#include <nlohmann/json.hpp>

#include <initializer_list>
#include <sstream>
#include <string>

namespace capsim::testing {

// The --report JSON text without the provenance's argv and the named options
// (those the runs compared were given differently).
inline std::string without_argv_and(const std::string& report, std::initializer_list<const char*> options) {
  nlohmann::json j = nlohmann::json::parse(report);
  j.at("provenance").erase("argv");
  for (const char* o : options) j.at("provenance").at("options").erase(o);
  return j.dump(2);
}

// The --report JSON text without provenance.argv and provenance.options.threads.
inline std::string without_threads(const std::string& report) { return without_argv_and(report, {"threads"}); }

// The text report without its provenance's "command" and "options" lines.
inline std::string text_without_threads(const std::string& text) {
  std::istringstream in(text);
  std::string out;
  for (std::string line; std::getline(in, line);)
    if (line.rfind("  command ", 0) != 0 && line.rfind("  options ", 0) != 0) out += line + "\n";
  return out;
}

}  // namespace capsim::testing
