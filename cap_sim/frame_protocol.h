#pragma once
// What the host and the cells say to each other over the command bus during one
// frame, in this order:
//   host -> all cells  "program"     the tracer program (profile.program_bytes)
//   host -> all cells  "scene"       primitives, status tree, camera, lights
//   host -> all cells  "voxel data"  the voxel grid
//   host -> all cells  "start"       the start command (kStartCommandBytes)
//   cell -> host       "done"        the cell has every pixel in video memory
//                                    (kDoneMessageBytes: the cell's id)

#include <array>
#include <cstdint>
#include <string_view>

namespace capsim::sim {

inline constexpr std::string_view kProgramBroadcast = "program";
inline constexpr std::string_view kSceneBroadcast = "scene";
inline constexpr std::string_view kVoxelBroadcast = "voxel data";
inline constexpr std::string_view kStartCommand = "start";
inline constexpr std::string_view kDoneMessage = "done";

// The broadcasts every cell receives before it starts, in order.
inline constexpr std::array<std::string_view, 4> kFrameBroadcasts = {
    kProgramBroadcast, kSceneBroadcast, kVoxelBroadcast, kStartCommand};

inline constexpr std::uint64_t kStartCommandBytes = 4;  // one command word
inline constexpr std::uint64_t kDoneMessageBytes = 4;   // the sender's cell id

}  // namespace capsim::sim
