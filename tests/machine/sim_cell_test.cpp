// A cell on its own: its program (§3.3) run on hand-made traced work with
// round cycle costs, on a real kernel, command bus and neighbour links, with
// the host played by the test. Each phase takes exactly its cycles, records
// its spans and its busy and communication time; a wrong message is refused;
// an overflow names the cell and the phase.

#include "kernel/event_kernel.h"
#include "kernel/mailbox.h"
#include "kernel/timeline.h"
#include "machine/parts/cell.h"
#include "machine/parts/command_bus.h"
#include "machine/parts/corner_exchange.h"
#include "machine/parts/frame_protocol.h"
#include "machine/frame_work.h"
#include "machine/parts/neighbour_links.h"
#include "support/sim_test_profile.h"

#include <fmt/core.h>
#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace capsim::sim {
namespace {

// Bytes the test's host broadcasts: program, scene, voxel data, start. On the
// round-number bus (3 arbitration + 10 a byte + 2 latency) each takes
// 1005, 205, 305 and 45 cycles.
constexpr std::uint64_t kProgram = 100, kScene = 20, kVoxels = 30;

TracedCell traced(CostBreakdown work, std::uint64_t rays) {
  TracedCell t;
  t.work = work;
  t.rays = rays;
  t.ops.rays = rays;
  t.ops.sphere_tests = 2 * rays;
  return t;
}

CostBreakdown cycles(std::uint64_t intersection, std::uint64_t other = 0) {
  CostBreakdown b;
  b[CostCategory::Intersection] = Cycles(intersection);
  b[CostCategory::Other] = Cycles(other);
  return b;
}

// One frame whose scene and voxel data take kScene and kVoxels bytes.
FrameWork frame(const WindowLayout& layout, std::vector<TracedCell> cells) {
  SceneFootprint footprint;
  footprint.primitives = kScene;
  footprint.voxel_grid = kVoxels;
  return FrameWork{layout, footprint, Cycles(0), {}, std::move(cells), {}};
}

using Broadcasts = std::vector<std::pair<BusMessage, std::uint64_t>>;

// The cells under test and every part they talk to; the host is the test's
// process (host()), which sends what it is given and collects the cells' "done".
struct CellBench {
  CellBench(CellGrid g, std::vector<FrameWork> f, std::vector<DistributionUnit> u, bool antialiased)
      : grid(g), frames(std::move(f)), units(std::move(u)), links(kernel, grid, profile) {
    for (CellId id = 0; id < grid.cell_count(); ++id)
      cells.push_back(std::make_unique<Cell>(
          id, timeline.add_track("cell " + std::to_string(id)),
          Cell::Wiring{kernel, bus, links, grid, timeline, frames, units, antialiased, true, false, 0, {}}));
    bus.on_delivery([this](const BusTransfer& t) {
      if (t.receiver == kHost) {
        host_inbox.deliver(t);
      } else {
        for (auto& c : cells) c->bus_inbox().deliver(t);
      }
    });
    links.on_delivery([this](const LinkMessage& m) { cells.at(m.to)->deliver_link(m); });
  }

  // `before` cycles of its own; then for each unit the broadcasts back to
  // back and a "done" from every cell (their arrival cycles in done_at).
  Process host(Cycles before, std::vector<Broadcasts> per_unit) {
    co_await kernel.delay(before);
    for (const Broadcasts& broadcasts : per_unit) {
      for (const auto& [message, bytes] : broadcasts) co_await bus.transfer(kHost, kAllCells, bytes, message);
      for (std::size_t c = 0; c < cells.size(); ++c) {
        const BusTransfer t = co_await host_inbox.receive();
        EXPECT_EQ(t.message, BusMessage::Done);
        done_at.push_back(t.delivered);
      }
    }
  }

  void run(Cycles before, std::vector<Broadcasts> per_unit) {
    kernel.spawn(host(before, std::move(per_unit)));
    for (auto& c : cells) kernel.spawn(c->run());
    kernel.run();
  }

  // The spans of cell c's track, in recording order.
  std::vector<TimelineSpan> spans(CellId c) const {
    std::vector<TimelineSpan> out;
    for (const TimelineSpan& s : timeline.spans())
      if (s.track == c) out.push_back(s);
    return out;
  }

  const CostProfile profile = testing::round_number_profile();
  const CellGrid grid;
  std::vector<FrameWork> frames;
  std::vector<DistributionUnit> units;
  EventKernel kernel;
  CommandBus bus{kernel, profile};
  NeighbourLinks links;
  Timeline timeline;
  std::vector<std::unique_ptr<Cell>> cells;
  Mailbox<BusTransfer> host_inbox{kernel};
  std::vector<Cycles> done_at;
};

const Broadcasts kFirstUnit = {{BusMessage::Program, kProgram},
                               {BusMessage::Scene, kScene},
                               {BusMessage::VoxelData, kVoxels},
                               {BusMessage::Start, kStartCommandBytes}};
const Broadcasts kNextUnit = {
    {BusMessage::Scene, kScene}, {BusMessage::VoxelData, kVoxels}, {BusMessage::Start, kStartCommandBytes}};

TimelineSpan span(CellId c, std::string name, SpanCategory category, std::uint64_t begin, std::uint64_t end,
                  std::uint64_t bytes = 0) {
  return {c, std::move(name), category, Cycles(begin), Cycles(end), bytes};
}

std::vector<DistributionUnit> one_unit_per_frame(int frames) {
  std::vector<DistributionUnit> units(frames);
  for (int f = 0; f < frames; ++f) units[f].first_frame = f;
  return units;
}

TEST(Cell, ReceivesTracesAndReportsDoneEachInItsCycles) {
  const CellGrid grid{1, 1};
  const WindowLayout layout(PixelMode::Dot, grid, 2, 2);  // the cell shows all 4 pixels
  std::vector<FrameWork> frames;
  frames.push_back(frame(layout, {traced(cycles(1000, 200), 6)}));
  CellBench b(grid, std::move(frames), one_unit_per_frame(1), false);
  b.run(Cycles(50), {kFirstUnit});
  ASSERT_TRUE(b.kernel.all_processes_finished());

  // It waits for the host's first broadcast, takes in each as it comes, traces
  // its 1200 cycles in one go from the start command, then its "done" has the
  // bus at once.
  EXPECT_EQ(b.spans(0), (std::vector<TimelineSpan>{
                            span(0, "wait for host", SpanCategory::Wait, 0, 50),
                            span(0, "receive program", SpanCategory::Receive, 50, 1055, kProgram),
                            span(0, "receive scene", SpanCategory::Receive, 1055, 1260, kScene),
                            span(0, "receive voxel data", SpanCategory::Receive, 1260, 1565, kVoxels),
                            span(0, "receive start", SpanCategory::Receive, 1565, 1610, kStartCommandBytes),
                            span(0, "trace 4 pixels", SpanCategory::Compute, 1610, 2810),
                            span(0, "send done", SpanCategory::Message, 2810, 2855, kDoneMessageBytes),
                        }));
  const CellRecord& r = b.cells[0]->record();
  EXPECT_EQ(r.busy, Cycles(1200));
  EXPECT_EQ(r.comm, Cycles(1005 + 205 + 305 + 45 + 45));  // the broadcasts, then its "done"
  EXPECT_EQ(r.finish, Cycles(2855));
  EXPECT_EQ(b.done_at, (std::vector<Cycles>{Cycles(2855)}));
  EXPECT_EQ(r.unit_finish, (std::vector<Cycles>{Cycles(2855)}));
  EXPECT_EQ(r.frame_write_start, (std::vector<Cycles>{Cycles(1610)}));
  EXPECT_EQ(r.frame_busy, (std::vector<Cycles>{Cycles(1200)}));
  EXPECT_EQ(r.work[CostCategory::Intersection], Cycles(1000));
  EXPECT_EQ(r.work[CostCategory::Other], Cycles(200));
  EXPECT_EQ(r.pixels, 4u);
  EXPECT_EQ(r.rays, 6u);
  EXPECT_EQ(r.ops.sphere_tests, 12u);
  EXPECT_EQ(r.trace_corners, Cycles(0));
  EXPECT_EQ(r.exchange, Cycles(0));
  EXPECT_EQ(r.subdivide, Cycles(0));
}

TEST(Cell, RunsUnitAfterUnitAndTakesTheProgramOnlyOnce) {
  const CellGrid grid{1, 1};
  const WindowLayout layout(PixelMode::Dot, grid, 2, 1);
  std::vector<FrameWork> frames;
  frames.push_back(frame(layout, {traced(cycles(300), 2)}));
  frames.push_back(frame(layout, {traced(cycles(500), 2)}));
  CellBench b(grid, std::move(frames), one_unit_per_frame(2), false);
  b.run(Cycles(0), {kFirstUnit, kNextUnit});
  ASSERT_TRUE(b.kernel.all_processes_finished());

  // Unit 0: the broadcasts until 1560, tracing until 1860, "done" at 1905;
  // unit 1: scene, voxel data and start until 2460, tracing until 2960, "done"
  // at 3005. A sequence names each frame.
  EXPECT_EQ(b.spans(0), (std::vector<TimelineSpan>{
                            span(0, "receive program", SpanCategory::Receive, 0, 1005, kProgram),
                            span(0, "receive scene", SpanCategory::Receive, 1005, 1210, kScene),
                            span(0, "receive voxel data", SpanCategory::Receive, 1210, 1515, kVoxels),
                            span(0, "receive start", SpanCategory::Receive, 1515, 1560, kStartCommandBytes),
                            span(0, "trace 2 pixels, frame 0", SpanCategory::Compute, 1560, 1860),
                            span(0, "send done", SpanCategory::Message, 1860, 1905, kDoneMessageBytes),
                            span(0, "receive scene", SpanCategory::Receive, 1905, 2110, kScene),
                            span(0, "receive voxel data", SpanCategory::Receive, 2110, 2415, kVoxels),
                            span(0, "receive start", SpanCategory::Receive, 2415, 2460, kStartCommandBytes),
                            span(0, "trace 2 pixels, frame 1", SpanCategory::Compute, 2460, 2960),
                            span(0, "send done", SpanCategory::Message, 2960, 3005, kDoneMessageBytes),
                        }));
  const CellRecord& r = b.cells[0]->record();
  EXPECT_EQ(r.frame_write_start, (std::vector<Cycles>{Cycles(1560), Cycles(2460)}));
  EXPECT_EQ(r.frame_busy, (std::vector<Cycles>{Cycles(300), Cycles(500)}));
  EXPECT_EQ(r.busy, Cycles(800));
  EXPECT_EQ(r.comm, Cycles(1005 + 205 + 305 + 45 + 45 + 205 + 305 + 45 + 45));
  EXPECT_EQ(r.unit_finish, (std::vector<Cycles>{Cycles(1905), Cycles(3005)}));
  EXPECT_EQ(r.finish, Cycles(3005));
  EXPECT_EQ(r.pixels, 4u);
}

TEST(Cell, RefusesABroadcastOutOfTurn) {
  const CellGrid grid{1, 1};
  const WindowLayout layout(PixelMode::Dot, grid, 2, 2);
  std::vector<FrameWork> frames;
  frames.push_back(frame(layout, {traced(cycles(10), 1)}));
  CellBench b(grid, std::move(frames), one_unit_per_frame(1), false);
  try {
    b.run(Cycles(0), {{{BusMessage::Scene, kScene}, {BusMessage::Program, kProgram}}});
    FAIL() << "a scene before the program was taken in";
  } catch (const std::logic_error& e) {
    EXPECT_STREQ(e.what(), "cell 0 expected \"program\" from the host, got \"scene\"");
  }
}

// Antialiased, on a 1 x 2 grid showing a 2 x 1 screen in dot mode: cell 0
// shows pixel (0, 0), cell 1 pixel (1, 0). Of the 3 x 2 corners, cell 0 owns
// (0, 0) and (0, 1), cell 1 the other four; cell 0's pixel needs (1, 0) and
// (1, 1) from cell 1, which sends them left in the horizontal step
// (2 corners: 26 bytes, 208 cycles on the link + 5 latency). Cell 1 needs
// nothing.
struct AntialiasedPair {
  AntialiasedPair(CostBreakdown corners0, CostBreakdown subdivision0)
      : layout(PixelMode::Dot, {1, 2}, 2, 1) {
    std::vector<TracedCell> traced_cells(2);
    traced_cells[0].corner_work = corners0;
    traced_cells[0].subdivision_work = subdivision0;
    traced_cells[1].corner_work = cycles(200);
    traced_cells[1].subdivision_work = cycles(50);
    for (TracedCell& t : traced_cells) {
      t.work = t.corner_work;
      t.work += t.subdivision_work;
    }
    std::vector<FrameWork> frames;
    frames.push_back(frame(layout, std::move(traced_cells)));
    std::vector<DistributionUnit> units = one_unit_per_frame(1);
    units[0].exchange = std::make_unique<CornerExchange>(layout);
    bench = std::make_unique<CellBench>(CellGrid{1, 2}, std::move(frames), std::move(units), true);
  }
  WindowLayout layout;
  std::unique_ptr<CellBench> bench;
};

TEST(Cell, AntialiasedTracesCornersExchangesThemSubdividesAndReportsDone) {
  AntialiasedPair pair(cycles(100), cycles(300));
  CellBench& b = *pair.bench;
  b.run(Cycles(0), {kFirstUnit});
  ASSERT_TRUE(b.kernel.all_processes_finished());

  // Both start at 1560. Cell 1 traces its corners until 1760, sends them
  // [1760, 1968) (they arrive at 1973), subdivides until 2018 and has the bus
  // for its "done" at once. Cell 0 traces its corners until 1660, waits for
  // cell 1's until 1973 and subdivides until 2273.
  std::vector<TimelineSpan> cell0 = b.spans(0), cell1 = b.spans(1);
  ASSERT_EQ(cell0.size(), 8u);
  ASSERT_EQ(cell1.size(), 8u);
  cell0.erase(cell0.begin(), cell0.begin() + 4);  // the four broadcasts, as without antialiasing
  cell1.erase(cell1.begin(), cell1.begin() + 4);
  EXPECT_EQ(cell0, (std::vector<TimelineSpan>{
                       span(0, "trace corners", SpanCategory::Compute, 1560, 1660),
                       span(0, "wait for corners", SpanCategory::Wait, 1660, 1973),
                       span(0, "subdivide 1 pixels", SpanCategory::Subdivide, 1973, 2273),
                       span(0, "send done", SpanCategory::Message, 2273, 2318, kDoneMessageBytes),
                   }));
  EXPECT_EQ(cell1, (std::vector<TimelineSpan>{
                       span(1, "trace corners", SpanCategory::Compute, 1560, 1760),
                       span(1, "send corners to cell[0,0]", SpanCategory::Message, 1760, 1968, 26),
                       span(1, "subdivide 1 pixels", SpanCategory::Subdivide, 1968, 2018),
                       span(1, "send done", SpanCategory::Message, 2018, 2063, kDoneMessageBytes),
                   }));

  const CellRecord& r0 = b.cells[0]->record();
  EXPECT_EQ(r0.trace_corners, Cycles(100));
  EXPECT_EQ(r0.exchange, Cycles(1973 - 1660));
  EXPECT_EQ(r0.subdivide, Cycles(300));
  EXPECT_EQ(r0.busy, Cycles(400));
  EXPECT_EQ(r0.comm, Cycles(1560 + 45));
  EXPECT_EQ(r0.frame_write_start[0], Cycles(1973));  // its pixels are written as it subdivides
  EXPECT_EQ(r0.frame_busy[0], Cycles(400));
  EXPECT_EQ(r0.corners_received, 2u);
  const CornerExchange exchange(pair.layout);
  EXPECT_EQ(r0.received_corners, (std::vector<CornerIndex>{exchange.index(0, 1, 0), exchange.index(0, 1, 1)}));
  EXPECT_EQ(r0.finish, Cycles(2318));

  const CellRecord& r1 = b.cells[1]->record();
  EXPECT_EQ(r1.trace_corners, Cycles(200));
  EXPECT_EQ(r1.exchange, Cycles(208));
  EXPECT_EQ(r1.subdivide, Cycles(50));
  EXPECT_EQ(r1.busy, Cycles(250));
  EXPECT_EQ(r1.comm, Cycles(1560 + 208 + 45));  // the send until its last bit left
  EXPECT_EQ(r1.corners_received, 0u);
  EXPECT_EQ(r1.finish, Cycles(2063));

  // One message on the links, typed: the horizontal step's first of cell 1.
  ASSERT_EQ(b.links.log().size(), 1u);
  const LinkMessage& m = b.links.log()[0];
  EXPECT_EQ(m.packet, (LinkPacket{LinkKind::Corners, ExchangeStep::Horizontal, 0}));
  EXPECT_EQ(m.from, 1);
  EXPECT_EQ(m.to, 0);
  EXPECT_EQ(m.arrived, Cycles(1973));
  EXPECT_EQ(b.done_at, (std::vector<Cycles>{Cycles(2063), Cycles(2318)}));
}

TEST(Cell, AnOverflowNamesTheCellAndItsPhase) {
  const std::uint64_t huge = Cycles::kMax - 1000;  // past 2^64 - 1 from cycle 1560
  struct Case {
    CostBreakdown corners, subdivision;
    std::string where;
    std::uint64_t after;  // the cycle the phase begins
  };
  // Cell 0's subdivision waits for cell 1's corners (until 1973).
  for (const Case& c : {Case{cycles(huge), cycles(1), "cell[0,0]'s corner tracing: ", 1560},
                        Case{cycles(1), cycles(huge), "cell[0,0]'s subdivision: ", 1973}}) {
    AntialiasedPair pair(c.corners, c.subdivision);
    try {
      pair.bench->run(Cycles(0), {kFirstUnit});
      FAIL() << c.where;
    } catch (const CycleOverflow& e) {
      EXPECT_EQ(e.quantity(), c.where + fmt::format("an event {} cycles after cycle {}", huge, c.after));
    }
  }
}

}  // namespace
}  // namespace capsim::sim
