#include "capsim/op_counts.h"

namespace capsim {

OpCounts& OpCounts::operator+=(const OpCounts& o) {
  sphere_tests += o.sphere_tests;
  cone_tests += o.cone_tests;
  box_tests += o.box_tests;
  mesh_tests += o.mesh_tests;
  mesh_node_tests += o.mesh_node_tests;
  triangle_tests += o.triangle_tests;
  revolution_tests += o.revolution_tests;
  revolution_edge_tests += o.revolution_edge_tests;
  quartic_tests += o.quartic_tests;
  dda_setups += o.dda_setups;
  dda_steps += o.dda_steps;
  voxel_passes += o.voxel_passes;
  tree_visits += o.tree_visits;
  hits_sorted += o.hits_sorted;
  shading_evals += o.shading_evals;
  matvec += o.matvec;
  rays += o.rays;
  primary_rays += o.primary_rays;
  shadow_rays += o.shadow_rays;
  secondary_rays += o.secondary_rays;
  aa_squares += o.aa_squares;
  return *this;
}

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
