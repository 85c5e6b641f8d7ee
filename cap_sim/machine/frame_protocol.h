#pragma once
// What the host and the cells say to each other over the command bus for one
// distribution unit (a frame, or a group of frame-averaged frames), in this
// order:
//   host -> all cells  "program"     the tracer program (profile.program_bytes),
//                                    before the first unit only
//   host -> all cells  "scene"       primitives, status tree, camera, lights  } each
//   host -> all cells  "voxel data"  the voxel grid                           } frame
//   host -> all cells  "start"       the start command (kStartCommandBytes)
//   cell -> host       "done"        the cell has every pixel of the unit in video
//                                    memory (kDoneMessageBytes: the cell's id)

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

namespace capsim::sim {

inline constexpr std::string_view kProgramBroadcast = "program";
inline constexpr std::string_view kSceneBroadcast = "scene";
inline constexpr std::string_view kVoxelBroadcast = "voxel data";
inline constexpr std::string_view kStartCommand = "start";
inline constexpr std::string_view kDoneMessage = "done";

// The broadcasts every cell receives before it starts a unit, in order.
inline std::vector<std::string_view> unit_broadcasts(bool first_unit, int frames) {
  std::vector<std::string_view> labels;
  if (first_unit) labels.push_back(kProgramBroadcast);
  for (int f = 0; f < frames; ++f) {
    labels.push_back(kSceneBroadcast);
    labels.push_back(kVoxelBroadcast);
  }
  labels.push_back(kStartCommand);
  return labels;
}

inline constexpr std::uint64_t kStartCommandBytes = 4;  // one command word
inline constexpr std::uint64_t kDoneMessageBytes = 4;   // the sender's cell id

}  // namespace capsim::sim
