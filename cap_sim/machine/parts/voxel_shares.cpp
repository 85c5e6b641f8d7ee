#include "machine/parts/voxel_shares.h"

#include "capsim/trace/voxel_grid.h"

#include <fmt/core.h>

namespace capsim::sim {

std::optional<VoxelGeneration> parse_voxel_generation(const std::string& text) {
  if (text == "host") return VoxelGeneration::Host;
  if (text == "cells") return VoxelGeneration::Cells;
  return std::nullopt;
}

const char* to_string(VoxelGeneration g) { return g == VoxelGeneration::Cells ? "cells" : "host"; }

namespace {

// The k-th of `parts` even shares of `count` things: [k count / parts, (k + 1) count / parts).
std::uint64_t share_start(std::uint64_t count, int parts, int k) {
  return static_cast<std::uint64_t>((static_cast<unsigned __int128>(count) * static_cast<unsigned>(k)) /
                                    static_cast<unsigned>(parts));
}

}  // namespace

std::vector<VoxelShare> voxel_shares(const PreparedScene& scene, int cells, const CostTable& costs) {
  if (cells < 1) throw std::invalid_argument("voxel generation on the cells needs a cell");
  const VoxelGrid& grid = scene.grid;
  const std::vector<VoxelGenCounts> by_primitive =
      voxel_counts_by_primitive(scene.prims, scene.placed, grid.universe, grid.n);
  std::vector<std::size_t> placed;
  for (std::size_t i = 0; i < scene.prims.size(); ++i)
    if (scene.placed[i]) placed.push_back(i);
  const std::uint64_t voxels = grid.offsets.size() - 1;

  std::vector<VoxelShare> shares(static_cast<std::size_t>(cells));
  for (int k = 0; k < cells; ++k) {
    VoxelShare& s = shares[static_cast<std::size_t>(k)];
    for (std::uint64_t p = share_start(placed.size(), cells, k); p < share_start(placed.size(), cells, k + 1); ++p) {
      const VoxelGenCounts& c = by_primitive[placed[p]];
      s.placing.primitives += c.primitives;
      s.placing.matmat += c.matmat;
      s.placing.matvec += c.matvec;
      s.placing.columns += c.columns;
      s.entries_bytes += c.voxel_entries * kVoxelEntryBytes;
    }
    const std::uint64_t first = share_start(voxels, cells, k), end = share_start(voxels, cells, k + 1);
    s.building.grid_voxels = end - first;
    s.building.voxel_entries = grid.offsets[end] - grid.offsets[first];
    s.rows_bytes = (s.building.grid_voxels + s.building.voxel_entries) * kGridWordBytes;
    try {
      s.placing_cycles = voxel_generation_cost(s.placing, costs, CostPayer::CellVoxels).total();
      s.building_cycles = voxel_generation_cost(s.building, costs, CostPayer::CellVoxels).total();
    } catch (const CycleOverflow& e) {
      throw e.inside(fmt::format("cell {}'s share of the voxel generation", k));
    }
  }
  return shares;
}

}  // namespace capsim::sim
