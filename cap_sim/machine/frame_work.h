#pragma once
// The work of a run, traced ahead by the host threads, and how the host hands
// it out: a run is a sequence of frames, distributed in units. Without frame
// averaging a unit is one frame and the host starts the next unit when every
// cell has finished this one (the display shows whole frames). With frame
// averaging (dot mode) a unit is a group of frames (as many as a cell's memory
// and video memory hold, at most R x C; machine/unit_memory.h), each with its
// own dot shift; the cells run through the group's frames without waiting for each
// other, and the host collects the group.

#include "kernel/cycles.h"
#include "machine/parts/corner_exchange.h"
#include "machine/parts/voxel_shares.h"
#include "machine/scene_footprint.h"
#include "machine/traced_cells.h"
#include "machine/parts/window_controller.h"

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace capsim::sim {

struct FrameWork {
  WindowLayout layout;
  SceneFootprint footprint;  // what "scene" and "voxel data" broadcast for it
  Cycles voxel_generation;   // the host's Algorithm-3 for it
  VoxelGenCounts voxel_counts;  // the operations voxel_generation pays for
  std::vector<TracedCell> cells;
  // With voxel generation on the cells, every cell's share (by cell id);
  // empty when the host generates the grid.
  std::vector<VoxelShare> voxel_shares;
};

// The numbers first, first + 1, ..., past_last - 1 in a range-for. (Written out
// rather than std::views::iota: clang 14 cannot compile libstdc++ 12's
// ranges, and the sanitizer and fuzz builds use clang.)
struct FrameNumbers {
  struct iterator {
    int frame;
    int operator*() const { return frame; }
    iterator& operator++() {
      ++frame;
      return *this;
    }
    bool operator!=(const iterator& other) const { return frame != other.frame; }
  };
  int first = 0;
  int past_last = 0;
  iterator begin() const { return {first}; }
  iterator end() const { return {past_last}; }
};

struct DistributionUnit {
  int first_frame = 0;
  int frames = 1;
  // The run's numbers of the unit's frames, in order.
  FrameNumbers frame_numbers() const { return {first_frame, first_frame + frames}; }
  // Antialiasing: the corner exchange of all the unit's frames at once. It is
  // planned as the unit starts and dropped once every cell has finished it
  // (the cells have taken in all its messages by then), so that a run holds
  // one unit's plan at a time.
  std::unique_ptr<CornerExchange> exchange;
};

// A timeline span's name for work on one frame: `what`, with the frame's
// number when the run has several (frame_count > 1).
std::string frame_span_name(std::string_view what, int frame, std::size_t frame_count);

}  // namespace capsim::sim
