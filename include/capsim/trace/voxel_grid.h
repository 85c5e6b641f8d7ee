#pragma once
// The uniform voxel grid and the paper's voxel generation (Algorithm-3).

#include "capsim/trace/op_counts.h"
#include "capsim/trace/primitive_geometry.h"

#include <cstdint>
#include <span>
#include <stdexcept>
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
  std::uint32_t largest_voxel = 0;  // the most primitives any voxel holds

  int index(int x, int y, int z) const { return (z * n + y) * n + x; }
  std::span<const std::uint32_t> voxel(int v) const {
    return {items.data() + offsets[v], items.data() + offsets[v + 1]};
  }
  std::size_t entries() const { return items.size(); }
};

inline constexpr int kMaxGridDivisions = 256;

// The voxel index along one axis of a grid of n divisions for a position v in
// voxel units (position - universe.lo, times n / extent): floor(v) clamped to
// [0, n - 1]. Defined for every double: NaN gives 0 and a value beyond the
// range of int is clamped before it is converted (the conversion itself
// would be undefined).
inline int clamped_voxel_index(double v, int n) {
  if (!(v >= 0)) return 0;
  if (v >= n) return n - 1;
  return static_cast<int>(v);  // 0 <= v < n: truncation is floor
}

// The most (voxel, primitive) entries a grid may hold: 4 bytes each, and
// generation holds them twice at its peak (256 MiB at the limit).
inline constexpr std::size_t kMaxVoxelEntries = std::size_t{1} << 25;

// The average entries per placed primitive that the automatic grid keeps to:
// as many as a primitive filling an 8 x 8 x 8 block of voxels has. Separate
// primitives put about 8 each (Table 4-2's optimum); where they overlap a lot
// (hundreds of copies of one shape), the divisions auto_grid_divisions gives
// would make every primitive fill the grid, and fewer serve the rays better.
inline constexpr std::size_t kAutoVoxelEntriesPerPrimitive = 512;

// Thrown by generate_voxels when the entries would pass kMaxVoxelEntries.
class VoxelGridTooLarge : public std::length_error {
 public:
  using std::length_error::length_error;
};

// The universe: the union of the placed primitives' world bounds, padded so that
// no primitive touches its faces.
Aabb universe_of(std::span<const PreparedPrimitive> prims, const std::vector<bool>& placed);

// Algorithm-3. For every placed primitive: transform its object bounding box to
// world space (an oriented box), project it onto the X-Y plane, and in every voxel
// column the projection covers bound Z by the box faces taken as infinite planes
// (Zmax = min over front faces of the max over the column's corners, Zmin = max
// over back faces of the min); the primitive is recorded in the voxels between.
// The primitive's world axis-aligned bounds act as extra circumscribing planes.
// Conservative: every voxel the primitive's surface touches holds it. Throws
// VoxelGridTooLarge rather than hold more than kMaxVoxelEntries entries.
// Primitives are placed on `threads` host threads (0 = all); the grid, the
// counts and the refusal are the same for every count.
VoxelGrid generate_voxels(std::span<const PreparedPrimitive> prims,
                          const std::vector<bool>& placed, const Aabb& universe, int n,
                          VoxelGenCounts* counts, int threads = 1);

// Algorithm-3's operations primitive by primitive, as generate_voxels counts
// them: element i holds primitive i's (all zero where it is not placed), with
// its (voxel, primitive) entries in voxel_entries and no grid_voxels (the
// grid's, not a primitive's). Their sum plus the grid's n^3 voxels is
// generate_voxels' count.
std::vector<VoxelGenCounts> voxel_counts_by_primitive(std::span<const PreparedPrimitive> prims,
                                                      const std::vector<bool>& placed, const Aabb& universe, int n);

// The same grid filled from each primitive's world axis-aligned bounding box only:
// the baseline that Algorithm-3's tighter fit is measured against.
VoxelGrid generate_voxels_aabb(std::span<const PreparedPrimitive> prims,
                               const std::vector<bool>& placed, const Aabb& universe, int n);

// The automatic division count (docs/architecture.md gives the rule and its fit).
int auto_grid_divisions(std::size_t placed_primitives);

// The entries generate_voxels_aabb would make: an upper bound of
// generate_voxels' count, found in O(primitives) without placing anything.
std::size_t bounding_box_entries(std::span<const PreparedPrimitive> prims,
                                 const std::vector<bool>& placed, const Aabb& universe, int n);

// The divisions of --grid auto: auto_grid_divisions' count, or fewer while the
// bounding-box entries would pass kAutoVoxelEntriesPerPrimitive per placed
// primitive or kMaxVoxelEntries (never fewer than 1). Unchanged for primitives
// that overlap little, as in every shipped scene.
int fitted_grid_divisions(std::span<const PreparedPrimitive> prims,
                          const std::vector<bool>& placed, const Aabb& universe);

}  // namespace capsim
