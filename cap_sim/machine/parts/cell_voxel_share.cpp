// A cell's part in voxel generation on the cells (voxel_shares.h): the phase
// of its program between receiving the scenes and tracing.

#include "machine/parts/cell.h"

#include <fmt/core.h>

#include <algorithm>
#include <stdexcept>

namespace capsim::sim {

// For each of the unit's frames: place this cell's primitives and broadcast
// their entries; once every other cell's entries are in, build the lists of
// its voxels and broadcast them; once every other cell's lists are in, the
// frame's grid is whole and the next frame's begins. A lone cell has no one
// to send to: it does the whole grid's work itself.
Task<> Cell::generate_voxel_shares(const DistributionUnit& unit) {
  const bool alone = wire_.grid.cell_count() == 1;
  for (const int f : unit.frame_numbers()) {
    const VoxelShare& share = wire_.frames[f].voxel_shares.at(id_);
    co_await clock_.compute(share.placing_cycles, frame_name("place primitives", f), "voxel generation");
    if (!alone) {
      co_await broadcast_share(BusMessage::VoxelEntries, f, share.entries_bytes);
      co_await gather_shares(BusMessage::VoxelEntries, f);
    }
    co_await clock_.compute(share.building_cycles, frame_name("build voxel lists", f), "voxel generation");
    if (!alone) {
      co_await broadcast_share(BusMessage::VoxelRows, f, share.rows_bytes);
      co_await gather_shares(BusMessage::VoxelRows, f);
    }
    const Cycles work = share.placing_cycles + share.building_cycles;
    record_.voxel_generation += work;
    record_.work[CostCategory::VoxelGeneration] += work;
  }
}

// Its share to every other cell in one transfer, as the host broadcasts.
Task<> Cell::broadcast_share(BusMessage message, int frame, std::uint64_t bytes) {
  const BusTransfer t = co_await wire_.bus.transfer(id_, kAllCells, bytes, message, -1, frame);
  clock_.wait("wait for bus", t.requested, t.granted);
  clock_.span(frame_name(fmt::format("broadcast {}", to_string(message)), frame), SpanCategory::Broadcast, t.granted,
              t.delivered, t.bytes);
  record_.comm += t.delivered - t.requested;
  record_.voxel_bytes_sent += t.bytes;
}

// Take in the other cells' broadcasts of `message` for `frame`, in the order
// the bus delivered them. A faster cell's broadcast of a later step or frame
// may come first: it is kept until then. Nothing else reaches the cell's bus
// interface meanwhile (the host's next broadcasts wait for every "done").
Task<> Cell::gather_shares(BusMessage message, int frame) {
  const Cycles start = clock_.now();
  const int expected = wire_.grid.cell_count() - 1;
  int received = 0;
  std::uint64_t bytes = 0;
  auto is_wanted = [&](const BusTransfer& t) { return t.message == message && t.frame == frame; };
  for (auto it = early_shares_.begin(); it != early_shares_.end();) {
    if (!is_wanted(*it)) {
      ++it;
      continue;
    }
    ++received;
    bytes += it->bytes;
    it = early_shares_.erase(it);
  }
  while (received < expected) {
    const BusTransfer t = co_await bus_inbox_.receive();
    if (t.message != BusMessage::VoxelEntries && t.message != BusMessage::VoxelRows)
      throw std::logic_error(fmt::format("{} expected \"{}\" from the cells, got \"{}\"", cell_name(id_),
                                         to_string(message), to_string(t.message)));
    if (!is_wanted(t)) {
      early_shares_.push_back(t);
      continue;
    }
    ++received;
    bytes += t.bytes;
  }
  clock_.span(frame_name(fmt::format("gather {}", to_string(message)), frame), SpanCategory::Receive, start,
              clock_.now(), bytes);
  record_.comm += clock_.now() - start;
  record_.voxel_gather += clock_.now() - start;
  record_.voxel_bytes_received += bytes;
}

}  // namespace capsim::sim
