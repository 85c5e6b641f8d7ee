// Mesh leaves on the simulated machine: the cycles their three cost terms
// charge under the shipped profiles, and the bytes a mesh takes in a cell's
// memory.

#include "machine/costs/cost_profile.h"
#include "machine/scene_footprint.h"

#include "capsim/scene/parser.h"

#include <gtest/gtest.h>

namespace capsim::sim {
namespace {

TEST(MeshCost, ChargedAsIntersectionWorkAtTheReasonedCosts) {
  OpCounts ops;
  ops.mesh_tests = 1;
  ops.mesh_node_tests = 2;
  ops.triangle_tests = 3;
  // cap at 8 MHz: 1194, 4386 and 1786 us.
  const CostBreakdown cap = pixel_cost(ops, load_cost_profile("cap").costs);
  EXPECT_EQ(cap[CostCategory::Intersection], Cycles(1 * 9552 + 2 * 35088 + 3 * 14288));
  // m380 at 1 GHz: 7.2, 35 and 11 us.
  const CostBreakdown m380 = pixel_cost(ops, load_cost_profile("m380").costs);
  EXPECT_EQ(m380[CostCategory::Intersection], Cycles(1 * 7200 + 2 * 35000 + 3 * 11000));
  for (CostCategory c : {CostCategory::Dda, CostCategory::Csg}) EXPECT_EQ(cap[c], Cycles(0));
}

TEST(MeshCost, AMeshTakesItsVerticesTrianglesAndHierarchyInCellMemory) {
  Scene one_sphere = parse_scene("sphere(1);", "s.csg");
  Scene tetrahedron = parse_scene(
      "polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], faces = [[0, 1, 2], [0, 3, 1], "
      "[0, 2, 3], [1, 3, 2]]);",
      "t.csg");
  const SceneFootprint s = scene_footprint(prepare_scene(std::move(one_sphere), {}));
  const SceneFootprint t = scene_footprint(prepare_scene(std::move(tetrahedron), {}));
  EXPECT_EQ(s.primitives, kPrimitiveRecordBytes);
  // 4 vertices, 4 triangles, one hierarchy node (a leaf holds up to 4).
  EXPECT_EQ(t.primitives, kPrimitiveRecordBytes + 4 * 12 + 4 * 28 + 32);
}

}  // namespace
}  // namespace capsim::sim
