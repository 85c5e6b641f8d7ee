#include "machine/parts/host.h"

#include "machine/parts/balance.h"
#include "machine/parts/frame_protocol.h"

#include <fmt/core.h>

#include <stdexcept>
#include <utility>

namespace capsim::sim {

Host::Host(const Wiring& wiring, int timeline_track, int cell_count, std::uint64_t program_bytes)
    : wire_(wiring),
      cell_count_(cell_count),
      program_bytes_(program_bytes),
      clock_(wiring.kernel, wiring.timeline, timeline_track, "the host", busy_),
      bus_inbox_(wiring.kernel) {}

Process Host::run() {
  for (std::size_t u = 0; u < wire_.units.size(); ++u) {
    if (wire_.unit_begins) wire_.unit_begins(u);
    unit_start_.push_back(clock_.now());
    if (!wire_.cells_generate_voxels) co_await generate_voxels(wire_.units[u]);
    co_await broadcast(u);
    if (wire_.on_demand)
      co_await hand_out_tiles(wire_.units[u]);
    else
      co_await collect_done();
    if (wire_.unit_ends) wire_.unit_ends(u);
  }
}

// Voxel generation (Algorithm-3) runs on the host before anything is sent (§5:
// "done on the host today"). Its cost was located when the frame's work was
// made (frame_work), so an overflow here is the run's clock, as the kernel
// words it.
Task<> Host::generate_voxels(const DistributionUnit& unit) {
  for (const int f : unit.frame_numbers())
    co_await clock_.compute(wire_.frames[f].voxel_generation,
                            frame_span_name("voxel generation", f, wire_.frames.size()));
}

// Broadcast the program (before the first unit only), each frame's scene and
// voxel data, then the start command: each one transfer that reaches every
// cell.
Task<> Host::broadcast(std::size_t u) {
  const DistributionUnit& unit = wire_.units[u];
  for (const Broadcast b : unit_broadcasts(u == 0, unit.first_frame, unit.frames, !wire_.cells_generate_voxels)) {
    const BusTransfer t = co_await wire_.bus.transfer(kHost, kAllCells, bytes_of(b), b.message);
    clock_.span(fmt::format("broadcast {}", to_string(b.message)), SpanCategory::Broadcast, t.granted, t.delivered,
                t.bytes);
  }
}

// Collect one completion message from every cell: the unit ends with the last.
Task<> Host::collect_done() {
  const Cycles collecting = clock_.now();
  for (int received = 0; received < cell_count_; ++received) {
    const BusTransfer t = co_await bus_inbox_.receive();
    if (t.message != BusMessage::Done)
      throw std::logic_error(fmt::format("host expected \"done\", got \"{}\"", to_string(t.message)));
  }
  unit_end_.push_back(clock_.now());
  clock_.span("wait for cells", SpanCategory::Wait, collecting, clock_.now());
}

// The host answers one request at a time, in the order they reached it; its
// own handling takes no cycles beyond the bus transfer of the answer
// (docs/balancing.md). Tiles go out in their order, row by row.
Task<> Host::hand_out_tiles(const DistributionUnit& unit) {
  if (unit.frames != 1) throw std::logic_error("tiles are handed out one frame at a time");
  const Cycles serving = clock_.now();
  const int tiles = wire_.frames[unit.first_frame].layout.grid().cell_count();
  int next = 0;
  for (int done = 0; done < cell_count_;) {
    const BusTransfer t = co_await bus_inbox_.receive();
    if (t.message == BusMessage::Done) {
      ++done;
      continue;
    }
    if (t.message != BusMessage::Request)
      throw std::logic_error(fmt::format("host expected \"request\" or \"done\", got \"{}\"", to_string(t.message)));
    ++balancing_.requests;
    balancing_.bytes_received += t.bytes;
    if (next < tiles) {
      const BusTransfer grant =
          co_await wire_.bus.transfer(kHost, t.sender, kTileGrantBytes, BusMessage::Grant, next++);
      ++balancing_.grants;
      balancing_.bytes_sent += grant.bytes;
    } else {
      const BusTransfer refusal = co_await wire_.bus.transfer(kHost, t.sender, kNoTileBytes, BusMessage::NoTile);
      ++balancing_.refusals;
      balancing_.bytes_sent += refusal.bytes;
    }
  }
  unit_end_.push_back(clock_.now());
  clock_.span("hand out tiles", SpanCategory::Wait, serving, clock_.now());
}

std::uint64_t Host::bytes_of(const Broadcast& b) const {
  switch (b.message) {
    case BusMessage::Program: return program_bytes_;
    case BusMessage::Scene:
      return wire_.frames[b.frame].footprint.scene_bytes() + (wire_.cells_generate_voxels ? kCellGridHeaderBytes : 0);
    case BusMessage::VoxelData: return wire_.frames[b.frame].footprint.voxel_bytes();
    case BusMessage::Start: return kStartCommandBytes;
    case BusMessage::Done:
    case BusMessage::Request:
    case BusMessage::Grant:
    case BusMessage::NoTile:
    case BusMessage::VoxelEntries:
    case BusMessage::VoxelRows: break;
  }
  throw std::logic_error(fmt::format("the host does not broadcast \"{}\"", to_string(b.message)));
}

}  // namespace capsim::sim
