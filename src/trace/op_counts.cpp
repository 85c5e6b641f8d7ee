#include "capsim/trace/op_counts.h"

namespace capsim {

VoxelGenCounts& VoxelGenCounts::operator+=(const VoxelGenCounts& o) {
  primitives += o.primitives;
  matmat += o.matmat;
  matvec += o.matvec;
  columns += o.columns;
  voxel_entries += o.voxel_entries;
  grid_voxels += o.grid_voxels;
  return *this;
}

}  // namespace capsim
