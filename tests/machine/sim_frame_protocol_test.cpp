// What the host and the cells say to each other: the bus messages' table, the
// broadcasts of a unit in order, the corner packets' names.

#include "machine/parts/frame_protocol.h"

#include <gtest/gtest.h>

#include <set>
#include <string_view>
#include <vector>

namespace capsim::sim {
namespace {

TEST(FrameProtocol, TheTableNamesEveryBusMessageOnceInTheEnumsOrder) {
  std::set<std::string_view> names;
  for (std::size_t i = 0; i < std::size(kBusMessages); ++i) {
    EXPECT_EQ(static_cast<std::size_t>(kBusMessages[i].message), i);
    names.insert(kBusMessages[i].name);
  }
  EXPECT_EQ(names.size(), std::size(kBusMessages));
  // The names the timeline and the reports print.
  EXPECT_EQ(to_string(BusMessage::Program), "program");
  EXPECT_EQ(to_string(BusMessage::Scene), "scene");
  EXPECT_EQ(to_string(BusMessage::VoxelData), "voxel data");
  EXPECT_EQ(to_string(BusMessage::Start), "start");
  EXPECT_EQ(to_string(BusMessage::Done), "done");
}

TEST(FrameProtocol, TheProgramGoesBeforeTheFirstUnitOnlyThenEachFramesSceneAndVoxelsThenStart) {
  using B = Broadcast;
  EXPECT_EQ(unit_broadcasts(true, 0, 1), (std::vector<B>{{BusMessage::Program}, {BusMessage::Scene, 0},
                                                         {BusMessage::VoxelData, 0}, {BusMessage::Start}}));
  EXPECT_EQ(unit_broadcasts(false, 4, 2),
            (std::vector<B>{{BusMessage::Scene, 4}, {BusMessage::VoxelData, 4}, {BusMessage::Scene, 5},
                            {BusMessage::VoxelData, 5}, {BusMessage::Start}}));
}

TEST(FrameProtocol, ALinkPacketIsNamedByItsKindAndStep) {
  EXPECT_EQ(to_string(LinkPacket{LinkKind::Corners, ExchangeStep::Vertical, 3}), "corners (vertical step)");
  EXPECT_EQ(to_string(LinkPacket{LinkKind::Corners, ExchangeStep::Horizontal, 0}), "corners (horizontal step)");
  EXPECT_NE((LinkPacket{LinkKind::Corners, ExchangeStep::Vertical, 1}),
            (LinkPacket{LinkKind::Corners, ExchangeStep::Horizontal, 1}));
  EXPECT_EQ(to_string(LinkPacket{LinkKind::StealRequest}), "steal request");
  EXPECT_EQ(to_string(LinkPacket{LinkKind::Work}), "work");
  EXPECT_EQ(to_string(LinkPacket{LinkKind::NoWork}), "no work");
  EXPECT_EQ(to_string(LinkPacket{LinkKind::Pixels}), "pixels");
}

}  // namespace
}  // namespace capsim::sim
