#include "cli/cli_outputs.h"

#include "cli/options/cli_usage.h"

#include <fmt/core.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>

namespace capsim::cli {

namespace {

namespace fs = std::filesystem;

// Whether two paths name the same file: the same path once symbolic links
// (dangling ones too), "." and ".." are resolved, or, for files that exist, the
// same inode (hard links).
bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec;
  if (fs::equivalent(a, b, ec)) return true;
  const auto resolved = [](const std::string& p) {
    std::error_code e;
    const fs::path absolute = fs::absolute(follow_links(p), e);
    const fs::path canonical = fs::weakly_canonical(absolute, e);
    return e ? absolute.lexically_normal() : canonical;
  };
  return resolved(a) == resolved(b);
}

}  // namespace

StagedOutputs::StagedOutputs(const std::vector<OutputOption>& outputs, const std::vector<std::string>& inputs) {
  std::vector<const OutputOption*> given;
  for (const OutputOption& o : outputs)
    if (!o.path.empty()) given.push_back(&o);
  const OutputOption* to_stdout = nullptr;
  for (std::size_t i = 0; i < given.size(); ++i) {
    const OutputOption& o = *given[i];
    if (names_standard_output(o.path)) {
      if (to_stdout)
        throw UsageError(fmt::format("{} {} is standard output, which {} {} already takes: at most one output can "
                                     "go to standard output",
                                     o.option, shown(o.path), to_stdout->option, shown(to_stdout->path)));
      to_stdout = &o;
      stdout_taken_ = true;
    }
    for (std::size_t j = 0; j < i; ++j)
      if (same_file(o.path, given[j]->path))
        throw UsageError(fmt::format("{} {} is the same file as {}: every output needs a file of its own",
                                     o.option, shown(o.path), given[j]->option));
    for (const std::string& input : inputs)
      if (same_file(o.path, input))
        throw UsageError(fmt::format("{} {} is an input of the command; writing it would replace it", o.option,
                                     shown(o.path)));
  }
  files_.reserve(given.size());
  for (const OutputOption* o : given) {
    try {
      files_.emplace_back(o->path);
    } catch (const std::runtime_error& e) {
      throw UsageError(fmt::format("{} {}", o->option, e.what()));
    }
    options_.push_back(o->option);
  }
}

PendingFile& StagedOutputs::operator[](const std::string& option) {
  const auto at = std::find(options_.begin(), options_.end(), option);
  if (at == options_.end()) throw std::logic_error(fmt::format("no output {} was staged", option));
  return files_[static_cast<std::size_t>(at - options_.begin())];
}

void StagedOutputs::commit() { commit_all(files_); }

}  // namespace capsim::cli
