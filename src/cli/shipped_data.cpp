#include "cli/shipped_data.h"

#include "cli/options/cli_options.h"
#include "cli/options/cli_usage.h"

#include <fmt/core.h>
#include <fmt/format.h>

#include <system_error>

// The build (CAPSIM_BUILD_DIR, where CMake puts the program) and source
// (CAPSIM_SOURCE_DIR) directories, and the installed data's directory from the
// installed program's (CAPSIM_SHARE_FROM_BIN, "../share/capsim" by default)
// come from CMakeLists.txt, for this file alone.
#if !defined(CAPSIM_BUILD_DIR) || !defined(CAPSIM_SOURCE_DIR) || !defined(CAPSIM_SHARE_FROM_BIN)
#error "CMakeLists.txt defines CAPSIM_BUILD_DIR, CAPSIM_SOURCE_DIR and CAPSIM_SHARE_FROM_BIN for this file"
#endif

namespace capsim::cli {

namespace fs = std::filesystem;

namespace {

// The running program's directory; empty if it cannot be read.
fs::path program_dir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : exe.parent_path();
}

bool is_build_dir(const fs::path& dir) {
  std::error_code ec;
  return !dir.empty() && fs::equivalent(dir, fs::path(CAPSIM_BUILD_DIR), ec) && !ec;
}

// p relative to the current directory when inside it, else as it is.
std::string shown_from_here(const fs::path& p) {
  std::error_code ec;
  const fs::path here = fs::current_path(ec);
  if (ec) return p.string();
  const fs::path full = fs::weakly_canonical(p, ec);
  if (ec) return p.string();
  const fs::path rel = full.lexically_relative(fs::weakly_canonical(here, ec));
  if (ec || rel.empty() || *rel.begin() == "..") return full.string();
  return rel.string();
}

}  // namespace

std::vector<fs::path> shipped_data_candidates(ShippedData what) {
  const bool scenes = what == ShippedData::Scenes;
  std::vector<fs::path> dirs;
  const fs::path dir = program_dir();
  if (dir.empty()) return dirs;
  dirs.push_back((dir / CAPSIM_SHARE_FROM_BIN / (scenes ? "scenes" : "baselines")).lexically_normal());
  if (is_build_dir(dir)) dirs.push_back(fs::path(CAPSIM_SOURCE_DIR) / (scenes ? "scenes" : "bench/baselines"));
  return dirs;
}

std::optional<std::string> find_shipped_data(ShippedData what) {
  for (const fs::path& dir : shipped_data_candidates(what)) {
    std::error_code ec;
    if (fs::is_directory(dir, ec)) return shown_from_here(dir);
  }
  return std::nullopt;
}

void add_scenes_option(CLI::App& cmd, OptionText<>& scenes) {
  add_option(cmd, "--scenes", scenes,
             "Directory of the models (balls.csg, chess.csg, ..., disb/) (default: the shipped ones, found beside "
             "an installed capsim or in the source tree of its build)",
             shipped_models_check());
}

std::string scenes_dir(const OptionText<>& scenes) {
  if (scenes.option->count() > 0) return checked(scenes);
  if (const std::optional<std::string> found = find_shipped_data(ShippedData::Scenes)) return *found;
  std::vector<std::string> looked;
  for (const fs::path& dir : shipped_data_candidates(ShippedData::Scenes)) looked.push_back(dir.string());
  throw UsageError(fmt::format("--scenes is needed: the shipped models are not in {} (accepted: {})",
                               looked.empty() ? std::string("the program's share/capsim/scenes")
                                              : fmt::format("{}", fmt::join(looked, " or ")),
                               accepted_values(*scenes.option)));
}

}  // namespace capsim::cli
