#pragma once
// What the host and the cells say to each other for one distribution unit (a
// frame, or a group of frame-averaged frames).
//
// Over the command bus (BusMessage), in this order:
//   host -> all cells  program     the tracer program (profile.program_bytes),
//                                  before the first unit only
//   host -> all cells  scene       primitives, status tree, camera, lights  } each
//   host -> all cells  voxel data  the voxel grid                           } frame
//   host -> all cells  start       the start command (kStartCommandBytes)
// With voxel generation on the cells (voxel_shares.h) the host sends no voxel
// data (the scene carries the grid's header); after start, for each frame:
//   cell -> all cells  voxel entries  the entries of the primitives it placed
//   cell -> all cells  voxel rows     the lists of the voxels it owns
//   cell -> host       done        the cell has every pixel of the unit in video
//                                  memory (kDoneMessageBytes: the cell's id)
// Balanced on demand (balance.h), between start and done, any number of times:
//   cell -> host       request     the cell asks for a tile
//   host -> cell       grant       a tile, or
//   host -> cell       no tile     none is left
// Over the neighbour links, from cell to cell (LinkPacket): antialiased, the
// corner exchange's messages (corner_exchange.h plans them); stealing
// (balance.h), the requests, their answers and the pixels traced for another
// cell.

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace capsim::sim {

enum class BusMessage : std::uint8_t {
  Program, Scene, VoxelData, Start, Done, Request, Grant, NoTile, VoxelEntries, VoxelRows
};

// The one table of bus messages: each value and its name as the timeline and
// the reports print it ("broadcast voxel data", "done (cell[0,3])"), in the
// enum's order.
struct BusMessageName {
  BusMessage message;
  std::string_view name;
};
inline constexpr BusMessageName kBusMessages[] = {
    {BusMessage::Program, "program"}, {BusMessage::Scene, "scene"}, {BusMessage::VoxelData, "voxel data"},
    {BusMessage::Start, "start"},     {BusMessage::Done, "done"},           {BusMessage::Request, "request"},
    {BusMessage::Grant, "grant"},     {BusMessage::NoTile, "no tile"},      {BusMessage::VoxelEntries, "voxel entries"},
    {BusMessage::VoxelRows, "voxel rows"},
};

constexpr std::string_view to_string(BusMessage m) { return kBusMessages[static_cast<std::size_t>(m)].name; }

// One broadcast before a unit: its message and, for a scene or voxel data, the
// run's frame it describes (-1 for the others).
struct Broadcast {
  BusMessage message = BusMessage::Start;
  int frame = -1;

  bool operator==(const Broadcast&) const = default;
};

// The broadcasts every cell receives from the host before it starts the unit
// of `frames` frames from first_frame, in order: the program (before the first
// unit only), each frame's scene and (when the host generates the grids) voxel
// data, the start command.
std::vector<Broadcast> unit_broadcasts(bool first_unit, int first_frame, int frames, bool host_voxels = true);

inline constexpr std::uint64_t kStartCommandBytes = 4;  // one command word
inline constexpr std::uint64_t kDoneMessageBytes = 4;   // the sender's cell id

// The corner exchange's two steps: the corners go vertically first, then
// horizontally (corner_exchange.h).
enum class ExchangeStep : std::uint8_t { Vertical, Horizontal };

// What a message over the links carries.
enum class LinkKind : std::uint8_t { Corners, StealRequest, Work, NoWork, Pixels };

// A message over the links. Corners: its step and its place among its
// sender's messages of that step (CornerExchange::sends(sender, step)[index]),
// where its receiver finds which corners it carries. Work and pixels: the
// chunks first_chunk to first_chunk + chunks - 1 of frame `frame` of the
// window of cell `owner` (the victim's).
struct LinkPacket {
  LinkKind kind = LinkKind::Corners;
  ExchangeStep step = ExchangeStep::Vertical;
  std::size_t index = 0;
  int frame = 0;
  int owner = 0;
  int first_chunk = 0, chunks = 0;

  bool operator==(const LinkPacket&) const = default;
};

// Its name on the link tracks: "corners (vertical step)", "steal request",
// "work", "no work", "pixels".
constexpr std::string_view to_string(const LinkPacket& p) {
  switch (p.kind) {
    case LinkKind::Corners:
      return p.step == ExchangeStep::Vertical ? "corners (vertical step)" : "corners (horizontal step)";
    case LinkKind::StealRequest:
      return "steal request";
    case LinkKind::Work:
      return "work";
    case LinkKind::NoWork:
      return "no work";
    case LinkKind::Pixels:
      return "pixels";
  }
  return "";
}

}  // namespace capsim::sim
