// The README against the code: every command has a usage line naming exactly
// the options its --help lists (by either of an option's names), the quoted
// error lines are what capsim prints, and CI runs the test command as written.

#include "support/cli_run.h"

#include <map>
#include <regex>
#include <set>
#include <vector>

using namespace capsim::testing;

namespace {

std::string readme() { return read_file(std::string(CAPSIM_SOURCE_DIR) + "/README.md"); }

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// Usage lines by command ("render", "bench modes"): a line of a code block
// (indented four spaces) starting with "capsim COMMAND" or "./build/capsim
// COMMAND" that shows an optional option ("["), with its continuation lines
// (indented further, starting with "[").
std::map<std::string, std::string> readme_usage() {
  static const std::regex start(R"(^    (?:\./build/)?capsim ((?:bench )?[a-z]+)\b(.*\[.*)$)");
  static const std::regex continuation(R"(^     +\[.*$)");
  std::map<std::string, std::string> usage;
  const std::vector<std::string> lines = lines_of(readme());
  for (std::size_t i = 0; i < lines.size(); ++i) {
    std::smatch m;
    if (!std::regex_match(lines[i], m, start)) continue;
    std::string text = m[2];
    while (i + 1 < lines.size() && std::regex_match(lines[i + 1], continuation)) text += " " + lines[++i];
    usage[m[1]] += text;
  }
  return usage;
}

// The options a usage text names: --long and single-letter -x.
std::set<std::string> options_named(const std::string& text) {
  static const std::regex option(R"((?:^|[\s\[|])(--?[A-Za-z][A-Za-z0-9-]*))");
  std::set<std::string> names;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), option); it != std::sregex_iterator(); ++it)
    names.insert((*it)[1]);
  return names;
}

// The options a --help lists, each as the set of its names, --help left out.
std::vector<std::set<std::string>> help_options(const std::string& help) {
  static const std::regex entry(R"(^  (-{1,2}[A-Za-z][A-Za-z0-9-]*(?:,-{1,2}[A-Za-z][A-Za-z0-9-]*)*)\b.*$)");
  std::vector<std::set<std::string>> options;
  for (const std::string& line : lines_of(help)) {
    std::smatch m;
    if (!std::regex_match(line, m, entry)) continue;
    std::set<std::string> names;
    std::istringstream in(m[1].str());
    for (std::string name; std::getline(in, name, ',');) names.insert(name);
    if (!names.count("--help")) options.push_back(names);
  }
  return options;
}

// The subcommands a --help lists, under its "Subcommands:" heading.
std::vector<std::string> subcommands(const std::string& help) {
  static const std::regex entry(R"(^  ([a-z]+)\s.*$)");
  std::vector<std::string> names;
  bool in_list = false;
  for (const std::string& line : lines_of(help)) {
    if (line == "Subcommands:") in_list = true;
    std::smatch m;
    if (in_list && std::regex_match(line, m, entry)) names.push_back(m[1]);
  }
  return names;
}

std::string help_of(const std::string& command, const TempDir& dir) {
  const RunResult r = run_capsim(command + " --help", dir);
  EXPECT_EQ(r.status, 0) << command << ": " << r.err;
  return r.out;
}

// Every command, "bench modes" as bench's subcommands are: those capsim --help lists.
std::vector<std::string> commands(const TempDir& dir) {
  std::vector<std::string> all;
  for (const std::string& command : subcommands(help_of("", dir))) {
    const std::vector<std::string> nested = subcommands(help_of(command, dir));
    if (nested.empty()) all.push_back(command);
    for (const std::string& sub : nested) all.push_back(command + " " + sub);
  }
  return all;
}

TEST(ReadmeUsage, EveryCommandHasAUsageLineNamingExactlyItsOptions) {
  TempDir dir;
  const std::map<std::string, std::string> usage = readme_usage();
  const std::vector<std::string> all = commands(dir);
  ASSERT_GE(all.size(), 6u);
  for (const std::string& command : all) {
    SCOPED_TRACE("capsim " + command);
    const auto found = usage.find(command);
    ASSERT_NE(found, usage.end()) << "README.md has no usage line for it";
    const std::set<std::string> in_readme = options_named(found->second);
    std::set<std::string> known;
    for (const std::set<std::string>& names : help_options(help_of(command, dir))) {
      known.insert(names.begin(), names.end());
      bool named = false;
      for (const std::string& name : names) named = named || in_readme.count(name) > 0;
      EXPECT_TRUE(named) << "the README's usage line omits " << *names.rbegin();
    }
    for (const std::string& name : in_readme) EXPECT_TRUE(known.count(name)) << "--help does not list " << name;
  }
  for (const auto& [command, text] : usage)
    EXPECT_NE(std::find(all.begin(), all.end(), command), all.end()) << "README.md shows capsim " << command;
}

TEST(ReadmeUsage, QuotedErrorLinesAreWhatCapsimPrints) {
  TempDir dir;
  const std::string text = readme();
  for (const std::string& args : {std::string("rendr"), "render " + scene_path("balls.csg") + " -o " + (dir / "x.png") +
                                               " --threads -1"}) {
    SCOPED_TRACE(args);
    const RunResult r = run_capsim(args, dir);
    ASSERT_EQ(r.status, 2);
    std::string line = r.err.substr(0, r.err.find('\n'));
    EXPECT_NE(text.find("    " + line + "\n"), std::string::npos) << "README.md does not quote: " << line;
  }
}

// CI runs the README's test command as written (docs/testing.md).
TEST(ReadmeUsage, CiRunsTheReadmeTestCommand) {
  std::string command;
  for (const std::string& line : lines_of(readme()))
    if (line.rfind("    sh .ci/install-deps --tests ", 0) == 0) command = line.substr(4);
  ASSERT_NE(command, "") << "README.md has no test command";
  EXPECT_NE(read_file(std::string(CAPSIM_SOURCE_DIR) + "/.ci/run").find("\n" + command + "\n"), std::string::npos)
      << ".ci/run does not run: " << command;
}

}  // namespace
