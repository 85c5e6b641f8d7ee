// Revolution leaves on the simulated machine: the cycles their three cost
// terms charge under the shipped profiles, and the bytes a revolution takes in
// a cell's memory.

#include "machine/costs/cost_profile.h"
#include "machine/scene_footprint.h"

#include "capsim/scene/parser.h"

#include <gtest/gtest.h>

namespace capsim::sim {
namespace {

TEST(RevolutionCost, ChargedAsIntersectionWorkAtTheReasonedCosts) {
  OpCounts ops;
  ops.revolution_tests = 1;
  ops.revolution_edge_tests = 2;
  ops.quartic_tests = 3;
  // cap at 8 MHz: 1194, 4589 and 22945 us.
  const CostBreakdown cap = pixel_cost(ops, load_cost_profile("cap").costs);
  EXPECT_EQ(cap[CostCategory::Intersection], Cycles(1 * 9552 + 2 * 36712 + 3 * 183560));
  // m380 at 1 GHz: 7.2, 24.6 and 123 us.
  const CostBreakdown m380 = pixel_cost(ops, load_cost_profile("m380").costs);
  EXPECT_EQ(m380[CostCategory::Intersection], Cycles(1 * 7200 + 2 * 24600 + 3 * 123000));
  for (CostCategory c : {CostCategory::Dda, CostCategory::Csg}) EXPECT_EQ(cap[c], Cycles(0));
}

TEST(RevolutionCost, ARevolutionTakesItsEdgesAndEllipsesInCellMemory) {
  Scene tube = parse_scene("rotate_extrude() translate([10, 0, 0]) square(5);", "t.csg");
  Scene torus = parse_scene("rotate_extrude() translate([10, 0, 0]) circle(5);", "t.csg");
  EXPECT_EQ(scene_footprint(prepare_scene(std::move(tube), {})).primitives,
            kPrimitiveRecordBytes + kRevolutionHeaderBytes + 4 * kRevolvedEdgeBytes);
  EXPECT_EQ(scene_footprint(prepare_scene(std::move(torus), {})).primitives,
            kPrimitiveRecordBytes + kRevolutionHeaderBytes + kRevolvedEllipseBytes);
}

}  // namespace
}  // namespace capsim::sim
