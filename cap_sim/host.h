#pragma once
// The host computer: it generates the voxel data (Algorithm-3, charged with the
// profile's host costs), broadcasts program, scene and voxel data over the command
// bus, starts the cells and collects their completion messages.

#include "command_bus.h"
#include "cost_profile.h"
#include "event_kernel.h"
#include "mailbox.h"
#include "scene_footprint.h"
#include "timeline.h"

namespace capsim::sim {

class Host {
 public:
  struct Wiring {
    EventKernel& kernel;
    CommandBus& bus;
    Timeline& timeline;
  };

  // voxel_generation: the cycles Algorithm-3 costs the host for this scene.
  Host(const Wiring& wiring, int timeline_track, int cell_count, std::uint64_t program_bytes,
       const SceneFootprint& footprint, Cycles voxel_generation);

  // The host's part of one frame.
  Process run_frame();

  Mailbox<BusTransfer>& bus_inbox() { return bus_inbox_; }
  // When the last cell's completion message arrived: the frame time.
  Cycles frame_end() const { return frame_end_; }

 private:
  Wiring wire_;
  int track_;
  int cell_count_;
  std::uint64_t program_bytes_;
  SceneFootprint footprint_;
  Cycles voxel_generation_;
  Mailbox<BusTransfer> bus_inbox_;
  Cycles frame_end_;
};

}  // namespace capsim::sim
