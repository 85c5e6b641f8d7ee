#include "host.h"

#include "frame_protocol.h"

#include <fmt/core.h>

#include <stdexcept>
#include <utility>

namespace capsim::sim {

Host::Host(const Wiring& wiring, int timeline_track, int cell_count, std::uint64_t program_bytes,
           const SceneFootprint& footprint, Cycles voxel_generation)
    : wire_(wiring),
      track_(timeline_track),
      cell_count_(cell_count),
      program_bytes_(program_bytes),
      footprint_(footprint),
      voxel_generation_(voxel_generation),
      bus_inbox_(wiring.kernel) {}

Process Host::run_frame() {
  // Voxel generation runs on the host before anything is sent (§5: "done on the
  // host today").
  const Cycles start = wire_.kernel.now();
  co_await wire_.kernel.delay(voxel_generation_);
  wire_.timeline.span(track_, "voxel generation", "compute", start, wire_.kernel.now());

  // Broadcast program, scene and voxel data, then the start command: each one
  // transfer that reaches every cell.
  const std::pair<std::string_view, std::uint64_t> broadcasts[] = {
      {kProgramBroadcast, program_bytes_},
      {kSceneBroadcast, footprint_.scene_bytes()},
      {kVoxelBroadcast, footprint_.voxel_bytes()},
      {kStartCommand, kStartCommandBytes}};
  for (const auto& [label, bytes] : broadcasts) {
    const BusTransfer t = co_await wire_.bus.transfer(kHost, kAllCells, bytes, std::string(label));
    wire_.timeline.span(track_, fmt::format("broadcast {}", label), "broadcast", t.granted,
                        t.delivered, t.bytes);
  }

  // Collect one completion message from every cell.
  const Cycles collecting = wire_.kernel.now();
  for (int received = 0; received < cell_count_; ++received) {
    const BusTransfer t = co_await bus_inbox_.receive();
    if (t.label != kDoneMessage)
      throw std::logic_error(fmt::format("host expected \"done\", got \"{}\"", t.label));
  }
  frame_end_ = wire_.kernel.now();
  wire_.timeline.span(track_, "wait for cells", "wait", collecting, frame_end_);
}

}  // namespace capsim::sim
