#include "machine/unit_memory.h"

#include "machine/parts/corner_exchange.h"

#include "capsim/trace/antialias.h"

#include <fmt/core.h>

#include <algorithm>
#include <stdexcept>

namespace capsim::sim {

int unit_frames(const MachineConfig& config) {
  if (!config.frame_average) return 1;
  return config.frame_average_group > 0 ? config.frame_average_group : config.cells.cell_count();
}

std::vector<std::uint64_t> frame_video_memory(const WindowLayout& layout, bool antialiased) {
  const int cells = layout.grid().cell_count();
  std::vector<std::uint64_t> bytes(static_cast<std::size_t>(cells), 0);
  for (CellId c = 0; c < cells; ++c) {
    const CellWindow& w = layout.window(c);
    bytes[c] = static_cast<std::uint64_t>(w.pixel_count()) * kVideoPixelBytes;
    if (!antialiased) continue;
    std::uint64_t owned = 0;
    for (int k = 0; k < w.pixel_count(); ++k) {
      const ScreenPixel p = w.screen_pixel(k);
      owned += static_cast<std::uint64_t>(owned_corner_count(p.x, p.y, layout.width(), layout.height()));
    }
    bytes[c] += owned * kScreenSampleBytes;
  }
  if (antialiased) {
    const std::vector<std::uint64_t> needed = corners_needed(layout);
    for (CellId c = 0; c < cells; ++c) bytes[c] += needed[c] * kScreenSampleBytes;
  }
  return bytes;
}

namespace {

// The video memory of a frame depends only on its place k in its unit (its
// dot shift), not on its scene or the unit's size: each k's is computed once.
class VideoByShift {
 public:
  VideoByShift(const MachineConfig& config, int width, int height)
      : config_(config), width_(width), height_(height) {}

  const std::vector<std::uint64_t>& of(int k) {
    if (static_cast<std::size_t>(k) >= memo_.size()) memo_.resize(static_cast<std::size_t>(k) + 1);
    std::vector<std::uint64_t>& bytes = memo_[k];
    // On demand the run decides which tiles a cell's video memory holds: it is
    // checked once the run has handed them out (run_frames).
    if (bytes.empty() && config_.balance.on_demand())
      bytes.assign(static_cast<std::size_t>(config_.cells.cell_count()), 0);
    if (bytes.empty()) {
      const DotShift shift = config_.frame_average ? dot_shift_for_frame(config_.cells, k) : DotShift{};
      bytes = frame_video_memory(WindowLayout(config_.mode, config_.cells, width_, height_, shift),
                                 config_.aa.depth > 0);
    }
    return bytes;
  }

 private:
  const MachineConfig& config_;
  int width_, height_;
  std::vector<std::vector<std::uint64_t>> memo_;
};

std::vector<UnitMemory> units_of(const std::vector<SceneFootprint>& frames, const MachineConfig& config, int group,
                                 VideoByShift& video) {
  const int count = static_cast<int>(frames.size());
  std::vector<UnitMemory> units;
  for (int first = 0; first < count; first += group) {
    UnitMemory u;
    u.unit = static_cast<int>(units.size());
    u.first_frame = first;
    u.frames = std::min(group, count - first);
    u.cell_memory = config.profile.program_bytes;
    std::vector<std::uint64_t> per_cell(static_cast<std::size_t>(config.cells.cell_count()), 0);
    for (int k = 0; k < u.frames; ++k) {
      const SceneFootprint& f = frames[static_cast<std::size_t>(first + k)];
      u.cell_memory += static_cast<unsigned __int128>(f.scene_bytes()) + f.voxel_bytes();
      u.scene_bytes += f.scene_bytes();
      u.voxel_bytes += f.voxel_bytes();
      const std::vector<std::uint64_t>& bytes = video.of(k);
      for (std::size_t c = 0; c < per_cell.size(); ++c) per_cell[c] += bytes[c];
    }
    u.video_memory = *std::max_element(per_cell.begin(), per_cell.end());
    units.push_back(u);
  }
  return units;
}

bool fits(const UnitMemory& u, const CostProfile& profile) {
  return u.cell_memory <= profile.cell_memory_bytes && u.video_memory <= profile.video_memory_bytes;
}

// "distribution unit 2 (frames 8 to 11)", "distribution unit 0 (frame 0)".
std::string unit_name(const UnitMemory& u) {
  return u.frames == 1 ? fmt::format("distribution unit {} (frame {})", u.unit, u.first_frame)
                       : fmt::format("distribution unit {} (frames {} to {})", u.unit, u.first_frame,
                                     u.first_frame + u.frames - 1);
}

}  // namespace

std::vector<UnitMemory> unit_memories(const std::vector<SceneFootprint>& frames, const MachineConfig& config,
                                      int width, int height) {
  VideoByShift video(config, width, height);
  return units_of(frames, config, unit_frames(config), video);
}

namespace {

// What can make a unit over the cell memory fit. A coarser grid shrinks only
// the voxel data: when the program and the scenes alone are over, it cannot.
std::string cell_memory_advice(const UnitMemory& u, const CostProfile& profile) {
  const unsigned __int128 without_grid = static_cast<unsigned __int128>(profile.program_bytes) + u.scene_bytes;
  if (without_grid <= profile.cell_memory_bytes) return "try a coarser --grid";
  return fmt::format(
      "the program and the scene{} alone need {} bytes, without any voxel grid, so a coarser --grid cannot "
      "help; {}use a profile with more cell memory (--profile){}",
      u.frames == 1 ? "" : "s of its frames", static_cast<std::uint64_t>(without_grid),
      u.frames == 1 ? "" : "put fewer frames in a unit, ",
      u.frames == 1 ? " or a scene of fewer primitives" : "");
}

}  // namespace

void check_unit_memory(const UnitMemory& u, const CostProfile& profile) {
  if (u.cell_memory > profile.cell_memory_bytes)
    throw std::runtime_error(fmt::format(
        "{} does not fit a cell's memory: it needs {} bytes (program {} + scene {} + voxel data {}{}) but a "
        "cell of profile '{}' has {} bytes; {}",
        unit_name(u), u.cell_memory, profile.program_bytes, u.scene_bytes, u.voxel_bytes,
        u.frames == 1 ? "" : fmt::format(", its {} frames", u.frames), profile.name, profile.cell_memory_bytes,
        cell_memory_advice(u, profile)));
  if (u.video_memory > profile.video_memory_bytes)
    throw std::runtime_error(fmt::format(
        "{} does not fit a cell's video memory: a cell needs {} bytes for its pixels{} but a cell of profile "
        "'{}' has {} bytes of video memory; try more --cells or a smaller --size",
        unit_name(u), u.video_memory, u.frames == 1 ? "" : fmt::format(" of its {} frames", u.frames),
        profile.name, profile.video_memory_bytes));
}

int frames_per_unit(const std::vector<SceneFootprint>& frames, const MachineConfig& config, int width,
                    int height) {
  VideoByShift video(config, width, height);
  auto all_fit = [&](int group) {
    for (const UnitMemory& u : units_of(frames, config, group, video))
      if (!fits(u, config.profile)) return false;
    return true;
  };
  if (config.frame_average) {
    const int rows = config.cells.rows;
    for (int group = config.cells.cell_count(); group >= rows; group -= rows)
      if (all_fit(group)) return group;
  }
  for (const UnitMemory& u : units_of(frames, config, 1, video)) check_unit_memory(u, config.profile);
  return 1;
}

MachineConfig resolve_units(const std::vector<SceneFootprint>& frames, const MachineConfig& config, int width,
                            int height) {
  MachineConfig resolved = config;
  if (config.frame_average && config.frame_average_group == 0) {
    resolved.frame_average_group = frames_per_unit(frames, config, width, height);
  } else {
    for (const UnitMemory& u : unit_memories(frames, config, width, height)) check_unit_memory(u, config.profile);
  }
  return resolved;
}

}  // namespace capsim::sim
