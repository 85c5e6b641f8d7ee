#include "machine/host.h"

#include "machine/frame_protocol.h"

#include <fmt/core.h>

#include <stdexcept>
#include <utility>

namespace capsim::sim {

Host::Host(const Wiring& wiring, int timeline_track, int cell_count, std::uint64_t program_bytes)
    : wire_(wiring),
      track_(timeline_track),
      cell_count_(cell_count),
      program_bytes_(program_bytes),
      bus_inbox_(wiring.kernel) {}

Process Host::run() {
  const bool sequence = wire_.frames.size() > 1;
  auto frame_name = [&](std::string_view what, int f) {
    return sequence ? fmt::format("{}, frame {}", what, f) : std::string(what);
  };
  for (std::size_t u = 0; u < wire_.units.size(); ++u) {
    const DistributionUnit& unit = wire_.units[u];
    const int first = unit.first_frame, end = unit.first_frame + unit.frames;
    if (wire_.unit_begins) wire_.unit_begins(u);
    unit_start_.push_back(wire_.kernel.now());

    // Voxel generation runs on the host before anything is sent (§5: "done on
    // the host today").
    for (int f = first; f < end; ++f) {
      const Cycles start = wire_.kernel.now();
      co_await wire_.kernel.delay(wire_.frames[f].voxel_generation);
      wire_.timeline.span(track_, frame_name("voxel generation", f), SpanCategory::Compute, start, wire_.kernel.now());
    }

    // Broadcast the program (once), each frame's scene and voxel data, then the
    // start command: each one transfer that reaches every cell.
    std::vector<std::pair<std::string_view, std::uint64_t>> broadcasts;
    if (u == 0) broadcasts.emplace_back(kProgramBroadcast, program_bytes_);
    for (int f = first; f < end; ++f) {
      broadcasts.emplace_back(kSceneBroadcast, wire_.frames[f].footprint.scene_bytes());
      broadcasts.emplace_back(kVoxelBroadcast, wire_.frames[f].footprint.voxel_bytes());
    }
    broadcasts.emplace_back(kStartCommand, kStartCommandBytes);
    for (const auto& [label, bytes] : broadcasts) {
      const BusTransfer t = co_await wire_.bus.transfer(kHost, kAllCells, bytes, std::string(label));
      wire_.timeline.span(track_, fmt::format("broadcast {}", label), SpanCategory::Broadcast, t.granted, t.delivered,
                          t.bytes);
    }

    // Collect one completion message from every cell.
    const Cycles collecting = wire_.kernel.now();
    for (int received = 0; received < cell_count_; ++received) {
      const BusTransfer t = co_await bus_inbox_.receive();
      if (t.label != kDoneMessage)
        throw std::logic_error(fmt::format("host expected \"done\", got \"{}\"", t.label));
    }
    unit_end_.push_back(wire_.kernel.now());
    wire_.timeline.span(track_, "wait for cells", SpanCategory::Wait, collecting, wire_.kernel.now());
    if (wire_.unit_ends) wire_.unit_ends(u);
  }
}

}  // namespace capsim::sim
