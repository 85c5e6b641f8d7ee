#pragma once
// What a cell holds for a distribution unit, checked against the profile's
// two sizes before anything is traced. Until the host has collected a unit, a
// cell keeps:
//   in its memory (cell_memory_bytes): the program, and the scene and voxel
//     data of every frame of the unit as the host broadcast them; frame
//     averaged, the host broadcasts all of a group's frames before "start";
//   in its video memory (video_memory_bytes): its pixels of every frame of the
//     unit, kVideoPixelBytes each, and, antialiased, the corner samples it
//     traced and those it took in from other cells, kScreenSampleBytes each;
//     balanced on demand, the pixels of the tiles it was granted, which only
//     the run decides, and which run_frames checks once it has.
// Frame averaged, frames_per_unit decides from both how many frames a unit
// holds.

#include "machine/costs/cost_profile.h"
#include "machine/machine.h"
#include "machine/scene_footprint.h"
#include "machine/parts/window_controller.h"

#include <cstdint>
#include <vector>

namespace capsim::sim {

inline constexpr std::uint64_t kVideoPixelBytes = 3;  // 8-bit R, G, B

// A unit's frames and what one cell holds for them.
struct UnitMemory {
  int unit = 0;  // its number in the run
  int first_frame = 0;
  int frames = 1;
  // Program + every frame's scene and voxel data; 128 bits, so that no sum of
  // 64-bit sizes wraps into a fit.
  unsigned __int128 cell_memory = 0;
  std::uint64_t scene_bytes = 0, voxel_bytes = 0;  // summed over its frames
  std::uint64_t video_memory = 0;  // the most one cell needs
};

// The frames of a unit: frame_average_group frame averaged (R x C while it
// is unresolved, 0), else 1.
int unit_frames(const MachineConfig& config);

// Per cell, the video memory of one frame laid out as `layout`: its pixels and,
// antialiased, the corners it owns and those it needs from other cells.
std::vector<std::uint64_t> frame_video_memory(const WindowLayout& layout, bool antialiased);

// What a cell holds for each unit of the run: units of unit_frames(config)
// frames from frame 0 (the last may be shorter), frame f with the footprint
// frames[f], laid out as frame_layout(config, width, height, f).
std::vector<UnitMemory> unit_memories(const std::vector<SceneFootprint>& frames, const MachineConfig& config,
                                      int width, int height);

// Throws std::runtime_error naming the unit, its frames, the bytes it needs
// and the bytes the profile gives, when it does not fit the cell's memory or
// its video memory.
void check_unit_memory(const UnitMemory& unit, const CostProfile& profile);

// Frame averaged: how many frames a unit holds: the most for which every unit
// of the run fits the cell's memory and video memory, at most R x C and
// rounded down to a whole multiple of R, so that the diagonal shifts of a unit
// (dot_shift_for_frame) move every cell over R different rows of the square;
// 1 if fewer than R fit. Throws as check_unit_memory when a unit of one frame
// does not fit. Without frame averaging: 1, every frame checked.
int frames_per_unit(const std::vector<SceneFootprint>& frames, const MachineConfig& config, int width,
                    int height);

// config with frame_average_group resolved by frames_per_unit, unless it
// already is; its units checked either way.
MachineConfig resolve_units(const std::vector<SceneFootprint>& frames, const MachineConfig& config, int width,
                            int height);

}  // namespace capsim::sim
