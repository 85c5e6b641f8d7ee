#pragma once
// The uniform voxel grid and the paper's voxel generation (Algorithm-3).

#include "capsim/op_counts.h"
#include "capsim/primitive_geometry.h"

#include <cstdint>
#include <span>
#include <vector>

namespace capsim {

struct VoxelGrid {
  Aabb universe;            // the box that holds every primitive, slightly padded
  int n = 1;                // divisions per axis
  glm::dvec3 voxel_size{1};  // universe extent / n
  glm::dvec3 inv_voxel_size{1};  // n / universe extent
  // Compressed rows: the primitives of voxel v are items[offsets[v] .. offsets[v+1]),
  // v = (z * n + y) * n + x, in ascending primitive order.
  std::vector<std::uint32_t> offsets;
  std::vector<std::uint32_t> items;

  int index(int x, int y, int z) const { return (z * n + y) * n + x; }
  std::span<const std::uint32_t> voxel(int v) const {
    return {items.data() + offsets[v], items.data() + offsets[v + 1]};
  }
  std::size_t entries() const { return items.size(); }
};

inline constexpr int kMaxGridDivisions = 256;

// The universe: the union of the placed primitives' world bounds, padded so that
// no primitive touches its faces.
Aabb universe_of(const std::vector<PreparedPrimitive>& prims, const std::vector<bool>& placed);

// Algorithm-3. For every placed primitive: transform its object bounding box to
// world space (an oriented box), project it onto the X-Y plane, and in every voxel
// column the projection covers bound Z by the box faces taken as infinite planes
// (Zmax = min over front faces of the max over the column's corners, Zmin = max
// over back faces of the min); the primitive is recorded in the voxels between.
// The primitive's world axis-aligned bounds act as extra circumscribing planes.
// Conservative: every voxel the primitive's surface touches holds it.
VoxelGrid generate_voxels(const std::vector<PreparedPrimitive>& prims,
                          const std::vector<bool>& placed, const Aabb& universe, int n,
                          VoxelGenCounts* counts);

// The same grid filled from each primitive's world axis-aligned bounding box only:
// the baseline that Algorithm-3's tighter fit is measured against.
VoxelGrid generate_voxels_aabb(const std::vector<PreparedPrimitive>& prims,
                               const std::vector<bool>& placed, const Aabb& universe, int n);

// The automatic division count (docs/architecture.md gives the rule and its fit).
int auto_grid_divisions(std::size_t placed_primitives);

}  // namespace capsim
