#include "machine/scene_footprint.h"

namespace capsim::sim {

SceneFootprint scene_footprint(const PreparedScene& s) {
  SceneFootprint f;
  const std::uint64_t prims = s.prims.size();
  f.primitives = prims * kPrimitiveRecordBytes;
  for (const PreparedPrimitive& p : s.prims)
    if (p.mesh)
      f.primitives += p.mesh->mesh->vertices.size() * kMeshVertexBytes +
                      p.mesh->mesh->triangles.size() * kMeshTriangleBytes + p.mesh->nodes.size() * kMeshNodeBytes;
  for (const PreparedPrimitive& p : s.prims)
    if (p.revolution)
      f.primitives += kRevolutionHeaderBytes + p.revolution->edges.size() * kRevolvedEdgeBytes +
                      p.revolution->profile.ellipses.size() * kRevolvedEllipseBytes;
  f.status_tree = s.tree_template.nodes().size() * kStatusNodeBytes + prims * kStatusLeafBytes;
  f.view = kCameraBytes + s.lights.size() * kLightBytes + kBackgroundBytes;
  f.voxel_grid = kGridHeaderBytes + (s.grid.offsets.size() + s.grid.items.size()) * kGridWordBytes;
  return f;
}

}  // namespace capsim::sim
