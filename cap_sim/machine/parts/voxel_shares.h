#pragma once
// Voxel generation on the cells (--voxel-generation cells): the paper's
// future work (§5: "done on the host today, should run in parallel on CAP").
// Algorithm-3 is shared among the C cells in two steps, each ending in one
// broadcast from every cell over the command bus (docs/balancing.md, "Voxel
// generation on the cells"):
//   1. placing: cell k places the scene's placed primitives k P / C to
//      (k + 1) P / C - 1, in the scene's order: each one's box to world space,
//      projected, its voxel columns and their Z bounds (the host's primitive,
//      matrix and column operations, at a cell's costs). It broadcasts the
//      (voxel, primitive) entries it made, kVoxelEntryBytes each
//      ("voxel entries").
//   2. building: cell k owns the voxels k V / C to (k + 1) V / C - 1 (V = N^3,
//      in the grid's order, so its share is one run of the compressed rows).
//      From every cell's entries it keeps those of its voxels and builds their
//      lists (the grid voxel and entry operations), then broadcasts its rows,
//      their offsets and items, one word each ("voxel rows"), which every cell
//      puts in its grid.
// Once every cell's rows are in, every cell holds the whole grid, the same the
// host would have broadcast. Summed over the cells, each operation counts as
// often as in the host's generation. The universe and the divisions come from
// the host with the scene, with the grid's header (kCellGridHeaderBytes).

#include "kernel/cycles.h"
#include "machine/costs/cost_profile.h"
#include "machine/scene_footprint.h"

#include "capsim/trace/op_counts.h"
#include "capsim/trace/prepared_scene.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace capsim::sim {

enum class VoxelGeneration { Host, Cells };

// "host" or "cells"; nothing for any other text.
std::optional<VoxelGeneration> parse_voxel_generation(const std::string& text);
const char* to_string(VoxelGeneration g);

// An entry on the bus: the voxel's index and the primitive's, a word each.
inline constexpr std::uint64_t kVoxelEntryBytes = 8;
// What the scene broadcast carries for the cells to generate the grid: the
// grid's header (universe and divisions) and the rows' final offset.
inline constexpr std::uint64_t kCellGridHeaderBytes = kGridHeaderBytes + kGridWordBytes;

struct VoxelShare {
  VoxelGenCounts placing;   // its primitives: placed, products, columns
  VoxelGenCounts building;  // its voxels: grid voxels and the entries in them
  Cycles placing_cycles, building_cycles;  // at the profile's cell_voxel costs
  std::uint64_t entries_bytes = 0;  // its "voxel entries" broadcast
  std::uint64_t rows_bytes = 0;     // its "voxel rows" broadcast
};

// Every cell's share of the scene's grid, cell by cell (the cell ids 0 to
// cells - 1). Throws CycleOverflow (naming the cell) when a share's cycles do
// not fit. Precondition: cells >= 1; scene.grid is generate_voxels' grid of
// scene.prims and scene.placed.
std::vector<VoxelShare> voxel_shares(const PreparedScene& scene, int cells, const CostTable& costs);

}  // namespace capsim::sim
