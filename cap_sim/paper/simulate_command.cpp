#include "paper/simulate_command.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace capsim::sim {
namespace {

// `text` as one shell word, taken verbatim: inside single quotes, each ' as '\''.
std::string single_quoted(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

std::string simulate_command(const SimulateSettings& s, CommandForm form) {
  const bool every = form == CommandForm::EveryOption;
  const SimulateSettings defaults;
  std::string cmd = fmt::format("capsim simulate {} -o {}", fmt::join(s.scenes, " "), s.output);
  if (s.width > 0) cmd += fmt::format(" --size {}x{}", s.width, s.height);
  if (every || s.grid != defaults.grid) cmd += s.grid > 0 ? fmt::format(" --grid {}", s.grid) : " --grid auto";
  // The two forms list --primary-only in different places: each as the pages
  // and docs/reproduction.md have always given it.
  if (!every && s.primary_only) cmd += " --primary-only";
  if (every || !(s.cells == defaults.cells)) cmd += " --cells " + to_string(s.cells);
  // On demand the tiles decide what a cell shows: --mode is refused there.
  if (!s.balance.on_demand() && (every || s.mode != defaults.mode))
    cmd += fmt::format(" --mode {}", to_string(s.mode));
  if (every || s.profile != defaults.profile) cmd += " --profile " + s.profile;
  if (s.frames > 0) cmd += fmt::format(" --frames {}", s.frames);
  if (every && s.primary_only) cmd += " --primary-only";
  if (s.aa.depth > 0) {
    cmd += fmt::format(" --aa {}", s.aa.depth);
    if (every || s.aa.threshold != defaults.aa.threshold) cmd += fmt::format(" --aa-threshold {}", s.aa.threshold);
  }
  if (s.frame_average) cmd += " --frame-average";
  if (!s.balance.is_static()) cmd += " --balance " + to_string(s.balance);
  if (s.voxel_generation != defaults.voxel_generation)
    cmd += fmt::format(" --voxel-generation {}", to_string(s.voxel_generation));
  if (every || s.threads != defaults.threads) cmd += fmt::format(" --threads {}", s.threads);
  for (const std::string& d : s.defines) cmd += " -D " + single_quoted(d);
  return cmd;
}

}  // namespace capsim::sim
