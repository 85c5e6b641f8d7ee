#pragma once
// Figures of a run that the paper's tables and the reports compare: Max, Min
// and d over the cells (Table 4-4), per frame and per distribution unit, the
// largest d (Table 4-5), and the neighbour links' traffic.

#include "machine/machine.h"

#include <cstdint>
#include <vector>

namespace capsim::sim {

struct LoadSpread {
  Cycles max_finish, min_finish;
  double deviation_percent = 0;  // (max - min) / max x 100; 0 if max is 0
};
LoadSpread load_spread(const SimulationResult& r);
// The same over the cells' busy cycles only: the cycles each computed, without
// the host's prefix (voxel generation, broadcasts) and the waits that every
// cell's finish time includes, so that d compares the cells' work alone.
LoadSpread busy_spread(const SimulationResult& r);
// The peak over the run's units of what one cell held (UnitTimes).
struct UnitMemoryPeak {
  std::uint64_t cell_memory_bytes = 0, video_memory_bytes = 0;
};
UnitMemoryPeak unit_memory_peak(const SimulationResult& r);

// A run of several frames (docs/animation.md). Per frame: Max, Min and d of the
// cells' time on it. With a barrier after each frame that is, as in Table 4-4,
// from the frame's start to the cell's "done" reaching the host; frame
// averaged, the frames of a group are not synchronised, and it is the cycles
// the cell worked on the frame.
std::vector<LoadSpread> frame_spreads(const SimulationResult& r);
// Per distribution unit: Max, Min and d of the cells' "done" arrivals, counted
// from the unit's start (for one frame per unit, the frames' spreads).
std::vector<LoadSpread> unit_spreads(const SimulationResult& r);
// Table 4-5's "max deviation": the largest d over the distribution units (the
// frames, or the frame-averaged groups).
double max_deviation_percent(const SimulationResult& r);

// Balanced on demand: the cycles the command bus was held by balancing
// messages (requests, grants, "no tile") as a share of the run's time, in
// percent; 0 for a run of no time.
double balance_bus_percent(const SimulationResult& r);

// The neighbour links' traffic over a frame (antialiasing's corner exchange).
struct LinkTotals {
  std::uint64_t messages = 0, bytes = 0;
  std::uint64_t hops = 0;  // link crossings, summed over the messages
  int max_hops = 0;
  Cycles busiest;       // the most cycles one link direction carried bits
  Cycles longest_wait;  // the longest a message waited for a link
};
LinkTotals link_totals(const SimulationResult& r);

}  // namespace capsim::sim
