// The host on its own: its program run against cells played by the test,
// which take in the broadcasts and answer "done" after fixed delays, on a real
// kernel and command bus with round cycle costs. Its broadcasts go out in the
// protocol's order with their byte counts; each unit starts and ends on the
// expected cycle; a wrong message is refused.

#include "kernel/event_kernel.h"
#include "kernel/mailbox.h"
#include "kernel/timeline.h"
#include "machine/parts/command_bus.h"
#include "machine/parts/frame_protocol.h"
#include "machine/frame_work.h"
#include "machine/parts/host.h"
#include "support/sim_test_profile.h"

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace capsim::sim {
namespace {

// On the round-number bus (3 arbitration + 10 a byte + 2 latency) a transfer
// of n bytes takes 5 + 10 n cycles.
constexpr std::uint64_t kProgram = 100, kVoxels = 30;

// A frame whose voxel generation costs `voxel_generation` cycles and whose
// scene takes `scene_bytes`. The host reads nothing else of it.
FrameWork frame(std::uint64_t voxel_generation, std::uint64_t scene_bytes) {
  SceneFootprint footprint;
  footprint.primitives = scene_bytes;
  footprint.voxel_grid = kVoxels;
  return FrameWork{WindowLayout(PixelMode::Dot, {1, 2}, 2, 1), footprint, Cycles(voxel_generation), {}, {}, {}};
}

// The host under test, the bus, and two cells played by the test: cell c
// takes in every broadcast up to the start command, works `work[c]` cycles
// and answers `answer` (in the protocol, "done").
struct HostBench {
  HostBench(std::vector<FrameWork> f, std::vector<DistributionUnit> u)
      : frames(std::move(f)),
        units(std::move(u)),
        host({kernel, bus, timeline, frames, units,
              [this](std::size_t unit) { begins.emplace_back(unit, kernel.now()); },
              [this](std::size_t unit) { ends.emplace_back(unit, kernel.now()); }},
             timeline.add_track("host"), 2, kProgram) {
    bus.on_delivery([this](const BusTransfer& t) {
      if (t.receiver == kHost) {
        host.bus_inbox().deliver(t);
      } else {
        for (auto& inbox : inboxes) inbox.deliver(t);
      }
    });
  }

  Process cell(CellId c, Cycles work, BusMessage answer) {
    for (std::size_t u = 0; u < units.size(); ++u) {
      for (BusTransfer t = co_await inboxes[c].receive(); t.message != BusMessage::Start;
           t = co_await inboxes[c].receive())
        if (c == 0) received.push_back(t.message);
      co_await kernel.delay(work);
      co_await bus.transfer(c, kHost, kDoneMessageBytes, answer);
    }
  }

  void run(Cycles work0, Cycles work1, BusMessage answer = BusMessage::Done) {
    kernel.spawn(host.run());
    kernel.spawn(cell(0, work0, answer));
    kernel.spawn(cell(1, work1, answer));
    kernel.run();
  }

  // The bus's transfers as (message, sender, bytes), in order.
  std::vector<std::tuple<BusMessage, Endpoint, std::uint64_t>> transfers() const {
    std::vector<std::tuple<BusMessage, Endpoint, std::uint64_t>> out;
    for (const BusTransfer& t : bus.log()) out.emplace_back(t.message, t.sender, t.bytes);
    return out;
  }

  const CostProfile profile = testing::round_number_profile();
  std::vector<FrameWork> frames;
  std::vector<DistributionUnit> units;
  EventKernel kernel;
  CommandBus bus{kernel, profile};
  Timeline timeline;
  Host host;
  Mailbox<BusTransfer> inboxes[2] = {Mailbox<BusTransfer>(kernel), Mailbox<BusTransfer>(kernel)};
  std::vector<BusMessage> received;  // by cell 0, before each start command
  std::vector<std::pair<std::size_t, Cycles>> begins, ends;  // the simulator's calls, with their cycles
};

TimelineSpan span(std::string name, SpanCategory category, std::uint64_t begin, std::uint64_t end,
                  std::uint64_t bytes = 0) {
  return {0, std::move(name), category, Cycles(begin), Cycles(end), bytes};
}

std::vector<DistributionUnit> one_unit_per_frame(int frames) {
  std::vector<DistributionUnit> units(frames);
  for (int f = 0; f < frames; ++f) units[f].first_frame = f;
  return units;
}

using Transfers = std::vector<std::tuple<BusMessage, Endpoint, std::uint64_t>>;

TEST(Host, GeneratesVoxelsBroadcastsInOrderAndCollectsEveryDone) {
  std::vector<FrameWork> frames;
  frames.push_back(frame(500, 20));
  HostBench b(std::move(frames), one_unit_per_frame(1));
  b.run(Cycles(1000), Cycles(300));
  ASSERT_TRUE(b.kernel.all_processes_finished());

  // Voxel generation, then program, scene, voxel data and start back to back;
  // the cells start at 2060, cell 1's "done" is in at 2360 + 45, cell 0's at
  // 3060 + 45: the unit's end.
  EXPECT_EQ(b.transfers(), (Transfers{{BusMessage::Program, kHost, kProgram},
                                      {BusMessage::Scene, kHost, 20},
                                      {BusMessage::VoxelData, kHost, kVoxels},
                                      {BusMessage::Start, kHost, kStartCommandBytes},
                                      {BusMessage::Done, 1, kDoneMessageBytes},
                                      {BusMessage::Done, 0, kDoneMessageBytes}}));
  for (const BusTransfer& t : b.bus.log())
    EXPECT_EQ(t.receiver, t.message == BusMessage::Done ? kHost : kAllCells);
  EXPECT_EQ(b.timeline.spans(), (std::vector<TimelineSpan>{
                                    span("voxel generation", SpanCategory::Compute, 0, 500),
                                    span("broadcast program", SpanCategory::Broadcast, 500, 1505, kProgram),
                                    span("broadcast scene", SpanCategory::Broadcast, 1505, 1710, 20),
                                    span("broadcast voxel data", SpanCategory::Broadcast, 1710, 2015, kVoxels),
                                    span("broadcast start", SpanCategory::Broadcast, 2015, 2060,
                                         kStartCommandBytes),
                                    span("wait for cells", SpanCategory::Wait, 2060, 3105),
                                }));
  EXPECT_EQ(b.host.unit_start(), (std::vector<Cycles>{Cycles(0)}));
  EXPECT_EQ(b.host.unit_end(), (std::vector<Cycles>{Cycles(3105)}));
  EXPECT_EQ(b.host.busy(), Cycles(500));
  EXPECT_EQ(b.received, (std::vector<BusMessage>{BusMessage::Program, BusMessage::Scene, BusMessage::VoxelData}));
}

TEST(Host, StartsTheNextUnitWhenEveryCellIsDoneAndSendsTheProgramOnce) {
  std::vector<FrameWork> frames;
  frames.push_back(frame(500, 20));
  frames.push_back(frame(700, 40));
  HostBench b(std::move(frames), one_unit_per_frame(2));
  b.run(Cycles(1000), Cycles(300));
  ASSERT_TRUE(b.kernel.all_processes_finished());

  // Unit 0 as a single frame's, until 3105. Unit 1: voxel generation until
  // 3805, scene (40 bytes) until 4210, voxel data until 4515, start until
  // 4560; cell 0's "done" is in at 5560 + 45.
  EXPECT_EQ(b.host.unit_start(), (std::vector<Cycles>{Cycles(0), Cycles(3105)}));
  EXPECT_EQ(b.host.unit_end(), (std::vector<Cycles>{Cycles(3105), Cycles(5605)}));
  EXPECT_EQ(b.begins, (std::vector<std::pair<std::size_t, Cycles>>{{0, Cycles(0)}, {1, Cycles(3105)}}));
  EXPECT_EQ(b.ends, (std::vector<std::pair<std::size_t, Cycles>>{{0, Cycles(3105)}, {1, Cycles(5605)}}));
  EXPECT_EQ(b.host.busy(), Cycles(1200));
  const Transfers transfers = b.transfers();
  ASSERT_EQ(transfers.size(), 11u);
  EXPECT_EQ(Transfers(transfers.begin() + 6, transfers.end()),
            (Transfers{{BusMessage::Scene, kHost, 40},
                       {BusMessage::VoxelData, kHost, kVoxels},
                       {BusMessage::Start, kHost, kStartCommandBytes},
                       {BusMessage::Done, 1, kDoneMessageBytes},
                       {BusMessage::Done, 0, kDoneMessageBytes}}));
  std::vector<std::string> names;
  for (const TimelineSpan& s : b.timeline.spans()) names.push_back(s.name);
  EXPECT_EQ(names, (std::vector<std::string>{"voxel generation, frame 0", "broadcast program", "broadcast scene",
                                             "broadcast voxel data", "broadcast start", "wait for cells",
                                             "voxel generation, frame 1", "broadcast scene",
                                             "broadcast voxel data", "broadcast start", "wait for cells"}));
}

TEST(Host, AFrameAveragedUnitBroadcastsEachFramesSceneAndVoxelsBeforeOneStart) {
  std::vector<FrameWork> frames;
  frames.push_back(frame(500, 20));
  frames.push_back(frame(700, 40));
  std::vector<DistributionUnit> units(1);
  units[0].frames = 2;
  HostBench b(std::move(frames), std::move(units));
  b.run(Cycles(10), Cycles(10));
  ASSERT_TRUE(b.kernel.all_processes_finished());

  EXPECT_EQ(b.transfers(), (Transfers{{BusMessage::Program, kHost, kProgram},
                                      {BusMessage::Scene, kHost, 20},
                                      {BusMessage::VoxelData, kHost, kVoxels},
                                      {BusMessage::Scene, kHost, 40},
                                      {BusMessage::VoxelData, kHost, kVoxels},
                                      {BusMessage::Start, kHost, kStartCommandBytes},
                                      {BusMessage::Done, 0, kDoneMessageBytes},
                                      {BusMessage::Done, 1, kDoneMessageBytes}}));
  ASSERT_GE(b.timeline.spans().size(), 3u);
  EXPECT_EQ(b.timeline.spans()[0], span("voxel generation, frame 0", SpanCategory::Compute, 0, 500));
  EXPECT_EQ(b.timeline.spans()[1], span("voxel generation, frame 1", SpanCategory::Compute, 500, 1200));
  EXPECT_EQ(b.timeline.spans()[2].begin, Cycles(1200));  // the program's broadcast
  EXPECT_EQ(b.host.unit_end().size(), 1u);
}

TEST(Host, RefusesAnAnswerThatIsNotDone) {
  std::vector<FrameWork> frames;
  frames.push_back(frame(500, 20));
  HostBench b(std::move(frames), one_unit_per_frame(1));
  try {
    b.run(Cycles(10), Cycles(20), BusMessage::Start);
    FAIL() << "the host took in a start command from a cell";
  } catch (const std::logic_error& e) {
    EXPECT_STREQ(e.what(), "host expected \"done\", got \"start\"");
  }
}

}  // namespace
}  // namespace capsim::sim
