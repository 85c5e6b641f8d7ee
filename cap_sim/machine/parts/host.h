#pragma once
// The host computer: for each distribution unit of the run it generates the
// voxel data of the unit's frames (Algorithm-3, charged with the profile's host
// costs), broadcasts program (before the first unit), scene and voxel data of
// each frame over the command bus, starts the cells and collects their
// completion messages; the next unit starts when every cell has finished this
// one.

#include "kernel/event_kernel.h"
#include "kernel/mailbox.h"
#include "kernel/task.h"
#include "kernel/timeline.h"
#include "machine/parts/command_bus.h"
#include "machine/costs/cost_profile.h"
#include "machine/parts/frame_protocol.h"
#include "machine/frame_work.h"
#include "machine/parts/program_clock.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace capsim::sim {

class Host {
 public:
  struct Wiring {
    EventKernel& kernel;
    CommandBus& bus;
    Timeline& timeline;
    const std::vector<FrameWork>& frames;
    const std::vector<DistributionUnit>& units;
    // The simulator's bookkeeping, not the host program's: called as a unit
    // starts and once its last completion message is in, in no simulated
    // time. May be empty.
    std::function<void(std::size_t unit)> unit_begins, unit_ends;
    // Balanced on demand: each frame's tiles (frames[f].layout's windows) are
    // handed out to the cells that ask (balance.h).
    bool on_demand = false;
    // The cells generate the voxel grids (voxel_shares.h): the host sends no
    // voxel data, and each scene carries the grid's header.
    bool cells_generate_voxels = false;
  };

  // The balancing traffic it handled, all units (on demand).
  struct Balancing {
    std::uint64_t requests = 0, grants = 0, refusals = 0;  // refusals: "no tile"
    std::uint64_t bytes_received = 0, bytes_sent = 0;
  };

  Host(const Wiring& wiring, int timeline_track, int cell_count, std::uint64_t program_bytes);

  // The host's program, for each unit in turn: generate its frames' voxel
  // data, broadcast it, start the cells, collect their "done". Precondition:
  // every one of the cell_count cells runs Cell::run on the same units.
  Process run();

  Mailbox<BusTransfer>& bus_inbox() { return bus_inbox_; }
  // When each unit started (the host began its voxel generation) and ended (the
  // last cell's completion message arrived); the last end is the run's time.
  const std::vector<Cycles>& unit_start() const { return unit_start_; }
  const std::vector<Cycles>& unit_end() const { return unit_end_; }
  // The cycles it spent generating voxel data, all units.
  Cycles busy() const { return busy_; }
  const Balancing& balancing() const { return balancing_; }

 private:
  // The phases of run(), each for one unit (generate_voxels only when the
  // host generates the grids).
  Task<> generate_voxels(const DistributionUnit& unit);
  Task<> broadcast(std::size_t unit);
  Task<> collect_done();
  // On demand: answer every request, a tile while the unit's frame has one
  // left, else "no tile", until every cell has sent "done".
  Task<> hand_out_tiles(const DistributionUnit& unit);
  // The bytes of a broadcast: the program, a frame's scene or voxel data
  // (its footprint), the start command.
  std::uint64_t bytes_of(const Broadcast& b) const;

  Wiring wire_;
  int cell_count_;
  std::uint64_t program_bytes_;
  Cycles busy_;
  ProgramClock clock_;  // counts its busy cycles in busy_
  Mailbox<BusTransfer> bus_inbox_;
  std::vector<Cycles> unit_start_, unit_end_;
  Balancing balancing_;
};

}  // namespace capsim::sim
