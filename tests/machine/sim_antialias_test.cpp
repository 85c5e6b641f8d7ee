// Antialiasing on the machine: the corner exchange over the neighbour links
// delivers what every cell needs, with exact timing; the screen equals the
// tracer's antialiased render; the load spread on BALLS.

#include "machine/parts/corner_exchange.h"
#include "machine/machine.h"
#include "machine/run_figures.h"
#include "support/sim_test_profile.h"

#include "capsim/scene/parser.h"
#include "capsim/trace/render.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <set>
#include <span>
#include <string>

namespace capsim::sim {
namespace {

PreparedScene balls(int width, int height) {
  PrepareOptions prep;
  prep.width = width;
  prep.height = height;
  return prepare_scene(parse_scene_file(std::string(CAPSIM_SOURCE_DIR) + "/scenes/balls.csg"), prep);
}

MachineConfig config_of(CellGrid grid, PixelMode mode, int depth, LinkTopology topology = LinkTopology::Mesh) {
  MachineConfig c;
  c.cells = grid;
  c.mode = mode;
  c.profile = load_cost_profile("cap");
  c.profile.link.topology = topology;
  c.aa = {depth, 0.3};
  return c;
}

bool same_floats(std::span<const float> a, std::span<const float> b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

// The corners cell n's pixels need from other cells, found pixel by pixel from
// the window controller alone.
std::set<CornerIndex> corners_needed(const WindowLayout& layout, CellId n) {
  const int w = layout.width(), h = layout.height();
  auto corner_owner = [&](int x, int y) { return layout.owner({std::min(x, w - 1), std::min(y, h - 1)}).cell; };
  std::set<CornerIndex> needed;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (layout.owner({x, y}).cell != n) continue;
      for (const auto& [cx, cy] : {std::pair{x + 1, y}, std::pair{x, y + 1}, std::pair{x + 1, y + 1}})
        if (corner_owner(cx, cy) != n) needed.insert(static_cast<CornerIndex>(cy * (w + 1) + cx));
    }
  return needed;
}

TEST(SimAntialias, ExchangeDeliversExactlyTheCornersEachCellNeeds) {
  // Every cell ends with every corner its pixels need; besides those it took
  // in only the corners it relays, and no corner twice.
  const PreparedScene scene = balls(13, 11);  // not a multiple of any grid below
  const Tracer tracer(scene, TraceOptions{true});
  for (PixelMode mode : {PixelMode::Dot, PixelMode::Line, PixelMode::Block})
    for (CellGrid grid : {CellGrid{1, 1}, CellGrid{1, 3}, CellGrid{3, 1}, CellGrid{2, 2}, CellGrid{3, 5},
                          CellGrid{4, 4}, CellGrid{8, 8}})
      for (LinkTopology topology : {LinkTopology::Mesh, LinkTopology::Torus}) {
        const std::string where =
            std::string(to_string(mode)) + " " + to_string(grid) + " " + to_string(topology);
        MachineConfig config = config_of(grid, mode, 1, topology);
        config.keep_received_corners = true;
        const SimulationResult r = simulate_frame(tracer, config, 2, false);
        // Without the list a run keeps only the counts, and they agree.
        config.keep_received_corners = false;
        const SimulationResult counted = simulate_frame(tracer, config, 2, false);
        const WindowLayout layout(mode, grid, 13, 11);
        const CornerExchange plan(layout);
        for (const CellReport& c : r.cells) {
          const std::set<CornerIndex> needed = corners_needed(layout, c.id);
          std::set<CornerIndex> relayed;
          for (const CornerMessage& m : plan.sends(c.id, ExchangeStep::Horizontal))
            for (CornerIndex k : m.corners)
              if (plan.owner(k) != c.id) relayed.insert(k);
          std::set<CornerIndex> expected = needed;
          expected.insert(relayed.begin(), relayed.end());
          const std::set<CornerIndex> got(c.received_corners.begin(), c.received_corners.end());
          EXPECT_EQ(got.size(), c.received_corners.size()) << where << " cell " << c.id << ": a corner came twice";
          EXPECT_EQ(got, expected) << where << " cell " << c.id;
          EXPECT_EQ(c.corners_received, c.received_corners.size()) << where << " cell " << c.id;
          const CellReport& without = counted.cells[c.id];
          EXPECT_TRUE(without.received_corners.empty()) << where << " cell " << c.id;
          EXPECT_EQ(without.corners_received, c.corners_received) << where << " cell " << c.id;
          EXPECT_EQ(without.finish, c.finish) << where << " cell " << c.id;
        }
        if (grid.cell_count() == 1) {
          EXPECT_TRUE(r.link_messages.empty()) << where;
        }
      }
}

TEST(SimAntialias, CornersNeededCountsWhatEachCellNeeds) {
  // Counted from the rows and columns apart, against the pixel-by-pixel sets
  // and the exchange's own lists: every mode, grids and screens of one row
  // or column, sides that divide and sides that do not, every dot shift.
  for (PixelMode mode : {PixelMode::Dot, PixelMode::Line, PixelMode::Block})
    for (CellGrid grid : {CellGrid{1, 1}, CellGrid{1, 3}, CellGrid{3, 1}, CellGrid{2, 2}, CellGrid{3, 5},
                          CellGrid{4, 4}})
      for (const auto& [w, h] : {std::pair{1, 1}, std::pair{1, 9}, std::pair{9, 1}, std::pair{2, 2},
                                 std::pair{13, 11}, std::pair{16, 16}, std::pair{40, 3}})
        for (int frame = 0; frame < (mode == PixelMode::Dot ? grid.cell_count() : 1); ++frame) {
          const std::string where = std::string(to_string(mode)) + " " + to_string(grid) + " " +
                                    std::to_string(w) + "x" + std::to_string(h) + " frame " + std::to_string(frame);
          const WindowLayout layout(mode, grid, w, h,
                                    mode == PixelMode::Dot ? dot_shift_for_frame(grid, frame) : DotShift{});
          const std::vector<std::uint64_t> counted = corners_needed(layout);
          const CornerExchange plan(layout);
          ASSERT_EQ(counted.size(), static_cast<std::size_t>(grid.cell_count())) << where;
          for (CellId c = 0; c < grid.cell_count(); ++c) {
            EXPECT_EQ(counted[c], corners_needed(layout, c).size()) << where << " cell " << c;
            EXPECT_EQ(counted[c], plan.needs(c).size()) << where << " cell " << c;
          }
        }
}

TEST(SimAntialias, ScreenEqualsTheAntialiasedRenderInEveryModeAndThreadCount) {
  const PreparedScene scene = balls(37, 29);
  const Tracer tracer(scene, TraceOptions{});
  for (int depth : {1, 2}) {
    const AntialiasOptions aa{depth, 0.3};
    const Framebuffer rendered = render(tracer, 2, nullptr, nullptr, aa);
    for (PixelMode mode : {PixelMode::Dot, PixelMode::Line, PixelMode::Block})
      for (CellGrid grid : {CellGrid{8, 8}, CellGrid{1, 1}, CellGrid{3, 7}})
        for (int threads : {1, 2}) {
          const std::string where = std::string(to_string(mode)) + " " + to_string(grid) + " threads " +
                                    std::to_string(threads) + " depth " + std::to_string(depth);
          const SimulationResult r = simulate_frame(tracer, config_of(grid, mode, depth), threads, false);
          EXPECT_TRUE(same_floats(r.screens[0].screen.rgba, rendered.rgba)) << where;
          EXPECT_TRUE(same_floats(r.screens[0].screen.depth, rendered.depth)) << where;
          EXPECT_TRUE(same_floats(r.screens[0].screen.id, rendered.id)) << where;
        }
  }
}

TEST(SimAntialias, ResultsDoNotDependOnHostThreads) {
  const PreparedScene scene = balls(64, 48);
  const Tracer tracer(scene, TraceOptions{});
  const MachineConfig config = config_of({8, 8}, PixelMode::Dot, 2);
  const SimulationResult one = simulate_frame(tracer, config, 1, false);
  const SimulationResult two = simulate_frame(tracer, config, 2, false);
  EXPECT_EQ(one.timeline, two.timeline);
  EXPECT_TRUE(same_floats(one.screens[0].pixel_cycles, two.screens[0].pixel_cycles));
  EXPECT_TRUE(same_floats(one.screens[0].pixel_samples, two.screens[0].pixel_samples));
}

// Cells of a 2 x 2 grid whose phase 1 takes 1000 (c + 1) cycles for cell c and
// whose phase 3 takes nothing, on a 4 x 4 screen in dot mode.
std::vector<TracedCell> staged_cells(const WindowLayout& layout) {
  std::vector<TracedCell> cells(layout.grid().cell_count());
  for (CellId c = 0; c < layout.grid().cell_count(); ++c) {
    const int n = layout.window(c).pixel_count();
    cells[c].samples = Framebuffer(n, 1);
    cells[c].pixel_cycles.assign(n, 0);
    cells[c].pixel_samples.assign(n, 1);
    cells[c].corner_work[CostCategory::Other] = Cycles(1000 * (c + 1));
    cells[c].work = cells[c].corner_work;
  }
  return cells;
}

TEST(SimAntialias, LinkMessagesCarryTheirBytesAndArriveOnTime) {
  // Dot mode, 2 x 2 cells, 4 x 4 pixels: cell (r, c) owns the pixels with
  // y % 2 == r and x % 2 == c. Worked by hand from the routes (vertical to the
  // cell in the needer's row and the owner's column, then horizontal):
  //   vertical   0 -> 2: (0,2) (2,2)                         2 corners
  //              1 -> 3: (1,2) (3,2) (4,2)                   3
  //              2 -> 0: (0,1) (2,1) (0,3) (2,3)             4
  //              3 -> 1: (1,1) (3,1) (4,1) (1,3) (3,3) (4,3) 6
  //   horizontal 0 -> 1: own (2,0) (2,2), relayed (2,1) (2,3)            4
  //              1 -> 0: own (1,0) (3,0) (1,2) (3,2), relayed 4 from 3   8
  //              2 -> 3: own (2,1) (2,3) (2,4), relayed (2,2)            4
  //              3 -> 2: own 6 ((1,1) (3,1) (1,3) (3,3) (1,4) (3,4)),
  //                      relayed (1,2) (3,2)                              8
  // 13 bytes a corner; a link moves a byte in 8 cycles and adds 5 of latency.
  // Cell c sends its vertical message when its phase 1 ends at T + 1000 (c + 1),
  // and its horizontal one when that is sent and its vertical message has come.
  const PreparedScene scene = balls(4, 4);
  MachineConfig config;
  config.cells = {2, 2};
  config.mode = PixelMode::Dot;
  config.profile = testing::round_number_profile();
  config.aa = {1, 0.3};
  const WindowLayout layout(config.mode, config.cells, 4, 4);
  const SimulationResult r = run_frame(scene, layout, staged_cells(layout), config);

  Cycles t;  // when the cells started
  for (const TimelineSpan& s : r.timeline.spans())
    if (s.name == "trace corners") t = s.begin;
  ASSERT_GT(t, Cycles(0));
  struct Expected {
    CellId from, to;
    std::uint64_t corners, sent, arrived;
  };
  // In order of arrival.
  const Expected expected[] = {
      {0, 2, 2, 1000, 1000 + 26 * 8 + 5},  // 1213
      {1, 3, 3, 2000, 2000 + 39 * 8 + 5},  // 2317
      {2, 0, 4, 3000, 3000 + 52 * 8 + 5},  // 3421
      {2, 3, 4, 3416, 3416 + 52 * 8 + 5},  // 3837: after its vertical message left
      {0, 1, 4, 3421, 3421 + 52 * 8 + 5},  // 3842: when 2 -> 0 came
      {3, 1, 6, 4000, 4000 + 78 * 8 + 5},  // 4629
      {3, 2, 8, 4624, 4624 + 104 * 8 + 5},  // 5461
      {1, 0, 8, 4629, 4629 + 104 * 8 + 5},  // 5466
  };
  ASSERT_EQ(r.link_messages.size(), std::size(expected));
  for (std::size_t i = 0; i < std::size(expected); ++i) {
    const LinkMessage& m = r.link_messages[i];
    const Expected& e = expected[i];
    EXPECT_EQ(m.from, e.from) << i;
    EXPECT_EQ(m.to, e.to) << i;
    EXPECT_EQ(m.bytes, e.corners * kScreenSampleBytes) << i;
    EXPECT_EQ(m.sent, t + Cycles(e.sent)) << i;
    EXPECT_EQ(m.arrived, t + Cycles(e.arrived)) << i;
    EXPECT_EQ(m.hops, 1) << i;
  }
  const LinkTotals totals = link_totals(r);
  EXPECT_EQ(totals.bytes, (2 + 3 + 4 + 6 + 4 + 8 + 4 + 8) * kScreenSampleBytes);
  EXPECT_EQ(totals.busiest, Cycles(104 * 8));
  // A cell's exchange ends when it has sent its last message and taken in its
  // last one: cell 0 waits for 1 -> 0; cell 3's 3 -> 2 leaves after 2 -> 3 came.
  EXPECT_EQ(r.cells[0].exchange, Cycles(5466 - 1000));
  EXPECT_EQ(r.cells[3].exchange, Cycles(4624 + 104 * 8 - 4000));
}

TEST(SimAntialias, TorusLinksShortenTheEdgeCellsRoutes) {
  // Dot mode: the last grid row and column need corners from the opposite
  // edge. Across a 4 x 4 mesh that is 3 hops; over a torus's wrap-around, 1.
  const PreparedScene scene = balls(32, 32);
  const Tracer tracer(scene, TraceOptions{true});
  const SimulationResult mesh = simulate_frame(tracer, config_of({4, 4}, PixelMode::Dot, 1), 2, false);
  const SimulationResult torus =
      simulate_frame(tracer, config_of({4, 4}, PixelMode::Dot, 1, LinkTopology::Torus), 2, false);
  EXPECT_EQ(link_totals(mesh).max_hops, 3);
  EXPECT_EQ(link_totals(torus).max_hops, 1);
  EXPECT_EQ(link_totals(mesh).messages, link_totals(torus).messages);
  EXPECT_EQ(link_totals(mesh).bytes, link_totals(torus).bytes);
  EXPECT_GT(link_totals(mesh).hops, link_totals(torus).hops);
  EXPECT_TRUE(same_floats(mesh.screens[0].screen.rgba, torus.screens[0].screen.rgba));
}

TEST(SimAntialias, OnBallsAntialiasingRaisesTheFrameTimeAndTheDeviation) {
  // Reduced screen; docs/antialiasing.md gives the full-size figures.
  const PreparedScene scene = balls(128, 128);
  const Tracer tracer(scene, TraceOptions{});
  const SimulationResult plain = simulate_frame(tracer, config_of({8, 8}, PixelMode::Dot, 0), 2, false);
  const SimulationResult aa = simulate_frame(tracer, config_of({8, 8}, PixelMode::Dot, 2), 2, false);
  EXPECT_GT(aa.frame, plain.frame);
  EXPECT_GT(load_spread(aa).deviation_percent, 2 * load_spread(plain).deviation_percent);
  EXPECT_TRUE(plain.link_messages.empty());
  EXPECT_EQ(aa.link_messages.size(), 128u);  // a vertical and a horizontal message per cell
  EXPECT_EQ(link_totals(aa).messages, 128u);
}

}  // namespace
}  // namespace capsim::sim
