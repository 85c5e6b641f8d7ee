// Balancing on demand (machine/parts/balance.h): the tiles, the host handing them
// out over the command bus, and what must hold in every run: the screen is
// the tracer's, every pixel is traced once, the bus carries what was sent, no
// cell waits for a tile longer than the bus's queue and round trip allow, and
// the cycles of a small run are exactly these.

#include "machine/parts/balance.h"
#include "machine/machine.h"
#include "machine/run_figures.h"
#include "machine/unit_memory.h"

#include "support/balance_scenes.h"
#include "support/shipped_scene.h"

#include "capsim/scene/parser.h"
#include "capsim/trace/render.h"

#include <fmt/core.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <string>

namespace capsim::sim {
namespace {

PreparedScene balls(int width, int height) { return testing::shipped_scene("balls.csg", width, height); }

using testing::random_scene;
using testing::same_floats;

MachineConfig demand_config(CellGrid grid, int tile_pixels, ScreenFormat format = ScreenFormat::Float) {
  MachineConfig c;
  c.cells = grid;
  c.profile = load_cost_profile("cap");
  c.balance = {BalanceScheme::Demand, tile_pixels};
  c.screen = format;
  return c;
}

// Every pixel traced once: each tile by one cell, the cells' pixels adding up
// to the screen; the balancing bytes sent equal those received, on both
// sides, and what the bus carried; every request answered; no wait for an
// answer longer than every cell's request and answer queued on the bus ahead
// of it.
void expect_conserved(const SimulationResult& r, const std::string& what) {
  const CostProfile& p = r.config.profile;
  const WindowLayout tiles = tile_layout(r.config.balance, r.width, r.height);
  ASSERT_EQ(r.tile_cells.size(), 1u) << what;
  ASSERT_EQ(static_cast<int>(r.tile_cells[0].size()), tiles.grid().cell_count()) << what;
  std::uint64_t pixels = 0, tiles_taken = 0, requests = 0, sent = 0, received = 0;
  for (const CellReport& c : r.cells) {
    pixels += c.pixels;
    tiles_taken += c.tiles.size();
    requests += c.tile_requests;
    sent += c.balance_bytes_sent;
    received += c.balance_bytes_received;
    EXPECT_EQ(c.tile_requests, c.tiles.size() + 1) << what << ": one request per tile, and one answered \"no tile\"";
    std::uint64_t cell_pixels = 0;
    for (const TileRun& t : c.tiles) {
      EXPECT_EQ(r.tile_cells[0][t.tile], c.id) << what << " tile " << t.tile;
      cell_pixels += static_cast<std::uint64_t>(tiles.window(t.tile).pixel_count());
      EXPECT_LE(t.requested, t.granted);
      EXPECT_LE(t.granted, t.start);
    }
    EXPECT_EQ(c.pixels, cell_pixels) << what;
    EXPECT_EQ(c.idle + c.busy + c.comm, c.finish) << what;
  }
  EXPECT_EQ(pixels, static_cast<std::uint64_t>(r.width) * r.height) << what;
  EXPECT_EQ(tiles_taken, r.tile_cells[0].size()) << what;
  EXPECT_EQ(r.balancing.grants, tiles_taken) << what;
  EXPECT_EQ(r.balancing.requests, requests) << what;
  EXPECT_EQ(r.balancing.grants + r.balancing.refusals, requests) << what;
  EXPECT_EQ(r.balancing.bytes_received, sent) << what;
  EXPECT_EQ(r.balancing.bytes_sent, received) << what;
  EXPECT_EQ(r.balance_bus.bytes, sent + received) << what;
  EXPECT_EQ(sent, requests * kTileRequestBytes) << what;
  EXPECT_EQ(received, r.balancing.grants * kTileGrantBytes + r.balancing.refusals * kNoTileBytes) << what;

  const auto transfer = [&](std::uint64_t bytes) {
    return p.bus.arbitration + p.bus_data_cycles(bytes) + p.bus.latency;
  };
  const Cycles round_trip = transfer(kTileRequestBytes) + transfer(kTileGrantBytes);
  const Cycles bound = static_cast<std::uint64_t>(r.cells.size()) * round_trip;
  for (const CellReport& c : r.cells) EXPECT_LE(c.longest_tile_wait, bound) << what << " cell " << c.id;
}

TEST(Balance, ParsesTheSchemes) {
  EXPECT_EQ(parse_balance("static"), BalanceOptions{});
  EXPECT_EQ(parse_balance("demand"), (BalanceOptions{BalanceScheme::Demand, kDefaultTilePixels}));
  EXPECT_EQ(parse_balance("demand:16"), (BalanceOptions{BalanceScheme::Demand, 16}));
  EXPECT_EQ(parse_balance("demand:1").tile_side(), 1);
  EXPECT_EQ(parse_balance("demand:65536").tile_side(), 256);
  EXPECT_EQ(to_string(parse_balance("demand")), "demand:64");
  EXPECT_EQ(to_string(parse_balance("static")), "static");
  for (const char* bad : {"", "dynamic", "demand:", "demand:15", "demand:0", "demand:-4", "demand:+16", "demand:16x",
                          "demand:66049", "demand:4096000000", "Demand", "static:4"})
    EXPECT_THROW(parse_balance(bad), std::invalid_argument) << bad;
}

TEST(Balance, TilesCoverTheScreenOnceAndAreAtMostTheirSide) {
  for (int tile : {1, 4, 9, 16, 64})
    for (int width : {1, 5, 13, 64})
      for (int height : {1, 7, 48}) {
        const BalanceOptions b{BalanceScheme::Demand, tile};
        const WindowLayout layout = tile_layout(b, width, height);
        const int side = b.tile_side();
        EXPECT_EQ(layout.grid().rows, (height + side - 1) / side);
        EXPECT_EQ(layout.grid().cols, (width + side - 1) / side);
        std::vector<int> owners(static_cast<std::size_t>(width) * height, 0);
        for (CellId t = 0; t < layout.grid().cell_count(); ++t) {
          const CellWindow& w = layout.window(t);
          EXPECT_LE(w.columns(), side);
          EXPECT_LE(w.rows(), side);
          EXPECT_GE(w.pixel_count(), 1);
          for (int k = 0; k < w.pixel_count(); ++k) {
            const ScreenPixel px = w.screen_pixel(k);
            ++owners[static_cast<std::size_t>(px.y) * width + px.x];
          }
        }
        for (int o : owners) EXPECT_EQ(o, 1) << tile << " " << width << "x" << height;
      }
}

TEST(Balance, ScreenEqualsTheTracerAloneOnOneAndTwoThreads) {
  const PreparedScene scene = balls(45, 38);
  const Tracer tracer(scene, TraceOptions{});
  const Framebuffer rendered = render(tracer, 2);
  for (const CellGrid grid : {CellGrid{1, 1}, CellGrid{2, 3}, CellGrid{4, 4}})
    for (const int tile : {1, 16, 64})
      for (const int threads : {1, 2}) {
        const std::string what = fmt::format("{} demand:{} threads {}", to_string(grid), tile, threads);
        const SimulationResult r = simulate_frame(tracer, demand_config(grid, tile), threads, false);
        EXPECT_TRUE(same_floats(r.screens[0].screen.rgba, rendered.rgba)) << what;
        EXPECT_TRUE(same_floats(r.screens[0].screen.depth, rendered.depth)) << what;
        EXPECT_TRUE(same_floats(r.screens[0].screen.id, rendered.id)) << what;
        expect_conserved(r, what);
      }
}

TEST(Balance, ResultsDoNotDependOnHostThreadsInEitherFormat) {
  const PreparedScene scene = balls(40, 30);
  const Tracer tracer(scene, TraceOptions{});
  for (const ScreenFormat format : {ScreenFormat::Float, ScreenFormat::Srgb8}) {
    MachineConfig config = demand_config({3, 3}, 9, format);
    config.completion_cycles = true;
    const SimulationResult one = simulate_frame(tracer, config, 1, false);
    const SimulationResult two = simulate_frame(tracer, config, 2, false);
    EXPECT_EQ(one.timeline, two.timeline);
    EXPECT_EQ(one.tile_cells, two.tile_cells);
    EXPECT_EQ(one.screens[0].screen_srgb8, two.screens[0].screen_srgb8);
    EXPECT_TRUE(same_floats(one.screens[0].screen.rgba, two.screens[0].screen.rgba));
    EXPECT_EQ(one.screens[0].completion_cycles, two.screens[0].completion_cycles);
  }
}

TEST(Balance, ConservationHoldsOnRandomScenesAndGrids) {
  std::mt19937 rng(18);
  for (unsigned seed = 0; seed < 6; ++seed) {
    const int width = 5 + static_cast<int>(rng() % 20), height = 5 + static_cast<int>(rng() % 20);
    const PreparedScene scene = random_scene(seed, width, height);
    const Tracer tracer(scene, TraceOptions{});
    const Framebuffer rendered = render(tracer, 1);
    const CellGrid grid{1 + static_cast<int>(rng() % 4), 1 + static_cast<int>(rng() % 4)};
    const int side = 1 + static_cast<int>(rng() % 5);
    const std::string what = fmt::format("seed {} {}x{} cells {} demand:{}", seed, width, height, to_string(grid),
                                         side * side);
    const SimulationResult r = simulate_frame(tracer, demand_config(grid, side * side), 2, false);
    EXPECT_TRUE(same_floats(r.screens[0].screen.rgba, rendered.rgba)) << what;
    expect_conserved(r, what);
  }
}

// A pixel is on the screen when its cell has traced the pixels before it in
// its tile: the last one when the tile's tracing ends.
TEST(Balance, CompletionCyclesFollowTheTiles) {
  const PreparedScene scene = balls(24, 16);
  const Tracer tracer(scene, TraceOptions{});
  MachineConfig config = demand_config({2, 2}, 16);
  config.completion_cycles = true;
  const SimulationResult r = simulate_frame(tracer, config, 2, false);
  const WindowLayout tiles = tile_layout(config.balance, 24, 16);
  for (const CellReport& c : r.cells)
    for (const TileRun& t : c.tiles) {
      const CellWindow& w = tiles.window(t.tile);
      const ScreenPixel last = w.screen_pixel(w.pixel_count() - 1);
      EXPECT_EQ(r.screens[0].completion_cycles[static_cast<std::size_t>(last.y) * 24 + last.x], t.end.count());
      const ScreenPixel first = w.screen_pixel(0);
      EXPECT_GT(r.screens[0].completion_cycles[static_cast<std::size_t>(first.y) * 24 + first.x], t.start.count());
    }
}

// The exact cycles of a small run: BALLS at 32x24 on 2x2 cells in tiles of 16
// pixels (48 tiles).
TEST(Balance, SmallDemandRunTakesExactlyTheseCycles) {
  const PreparedScene scene = balls(32, 24);
  const Tracer tracer(scene, TraceOptions{});
  const SimulationResult r = simulate_frame(tracer, demand_config({2, 2}, 16), 2, false);
  std::vector<std::uint64_t> finish, tiles;
  for (const CellReport& c : r.cells) {
    finish.push_back(c.finish.count());
    tiles.push_back(c.tiles.size());
  }
  EXPECT_EQ(finish, (std::vector<std::uint64_t>{48273951, 47378386, 49356345, 48360275}));
  EXPECT_EQ(tiles, (std::vector<std::uint64_t>{10, 19, 13, 6}));
  EXPECT_EQ(r.frame.count(), 49356345u);
  // The cap profile's bus: 8 cycles of arbitration, 4 a byte, 8 of latency.
  // The four first requests leave in one cycle and win the bus in cell order
  // (24 cycles each: arbitration and 4 bytes) before the host's first grant,
  // asked for once cell 0's request is in (32 cycles): that grant holds the
  // bus from 96 to 136 (8 bytes) and reaches cell 0 at 144. So cell 0 takes
  // tile 0, 144 cycles after it asked, and cell k tile k.
  for (CellId c = 0; c < 4; ++c) EXPECT_EQ(r.cells[c].tiles.front().tile, c);
  const TileRun& first = r.cells[0].tiles.front();
  EXPECT_EQ((first.granted - first.requested).count(), 144u);
  EXPECT_EQ(r.cells[0].longest_tile_wait.count(), 144u - 32u);
  // Every request and "no tile" holds the bus 24 cycles, every grant 40.
  EXPECT_EQ(r.balancing.requests, 52u);
  EXPECT_EQ(r.balance_bus.busy.count(), 52u * 24 + 48u * 40 + 4u * 24);
  expect_conserved(r, "pinned run");
}

// On demand the same frames reach the screen frame after frame, and each
// frame's tiles are handed out anew.
TEST(Balance, SequencesHandOutEachFramesTiles) {
  const PreparedScene a = balls(20, 12), b = balls(20, 12);
  const Tracer ta(a, TraceOptions{}), tb(b, TraceOptions{});
  const SimulationResult r = simulate_frames({&ta, &tb}, demand_config({2, 2}, 4), 2, false);
  ASSERT_EQ(r.screens.size(), 2u);
  ASSERT_EQ(r.tile_cells.size(), 2u);
  const Framebuffer rendered = render(ta, 1);
  for (const FrameScreen& s : r.screens) EXPECT_TRUE(same_floats(s.screen.rgba, rendered.rgba));
  std::uint64_t tiles = 0;
  for (const CellReport& c : r.cells) tiles += c.tiles.size();
  EXPECT_EQ(tiles, 2 * r.tile_cells[0].size());
  EXPECT_EQ(r.balancing.grants, tiles);
  EXPECT_EQ(r.balancing.refusals, 2 * r.cells.size());
}

// Antialiased, a tile traces every corner of its pixels itself: the screen is
// render's, and the cells' corner tracing is every corner's cost once for
// each tile that has a pixel it is a corner of.
TEST(Balance, AntialiasedTilesTraceTheirCornersThemselves) {
  const PreparedScene scene = balls(30, 22);
  const Tracer tracer(scene, TraceOptions{});
  const AntialiasOptions aa{2, 0.3};
  const Framebuffer rendered = render(tracer, 2, nullptr, nullptr, aa);
  MachineConfig config = demand_config({2, 2}, 16);
  config.aa = aa;
  config.completion_cycles = true;
  const WindowLayout tiles = tile_layout(config.balance, 30, 22);
  std::vector<std::uint64_t> corner_cost((30 + 1) * (22 + 1), 0);
  (void)trace_corners(
      tracer, 1,
      [&](int y, std::span<const OpCounts> row) {
        for (int x = 0; x <= 30; ++x)
          corner_cost[static_cast<std::size_t>(y) * 31 + x] = pixel_cost(row[x], config.profile.costs).total().count();
      },
      nullptr);
  std::uint64_t expected = 0;
  for (int y = 0; y <= 22; ++y)
    for (int x = 0; x <= 30; ++x) {
      std::vector<CellId> needers;
      for (int py = y - 1; py <= y; ++py)
        for (int px = x - 1; px <= x; ++px)
          if (px >= 0 && py >= 0 && px < 30 && py < 22) {
            const CellId t = tiles.owner({px, py}).cell;
            if (std::find(needers.begin(), needers.end(), t) == needers.end()) needers.push_back(t);
          }
      expected += needers.size() * corner_cost[static_cast<std::size_t>(y) * 31 + x];
    }
  for (const int threads : {1, 2}) {
    const SimulationResult r = simulate_frame(tracer, config, threads, false);
    EXPECT_TRUE(same_floats(r.screens[0].screen.rgba, rendered.rgba)) << threads;
    std::uint64_t corners = 0, subdivision = 0;
    for (const CellReport& c : r.cells) {
      corners += c.trace_corners.count();
      subdivision += c.subdivide.count();
      EXPECT_EQ(c.trace_corners + c.subdivide, c.busy);
      EXPECT_EQ(c.corners_received, 0u) << "no corner crosses the links";
    }
    EXPECT_EQ(corners, expected);
    EXPECT_GT(subdivision, 0u) << "the antialiasing subdivides some pixel";
    EXPECT_TRUE(r.links.empty());
    expect_conserved(r, "antialiased");
    // A tile's pixels reach the screen as it subdivides them, after its corners.
    for (const CellReport& c : r.cells)
      for (const TileRun& t : c.tiles) {
        const CellWindow& w = tiles.window(t.tile);
        const ScreenPixel last = w.screen_pixel(w.pixel_count() - 1);
        EXPECT_EQ(r.screens[0].completion_cycles[static_cast<std::size_t>(last.y) * 30 + last.x], t.end.count());
      }
  }
}

TEST(Balance, RefusesWhatItDoesNotModel) {
  const PreparedScene scene = balls(8, 8);
  const Tracer tracer(scene, TraceOptions{});
  MachineConfig averaged = demand_config({2, 2}, 4);
  averaged.frame_average = true;
  EXPECT_THROW(simulate_frame(tracer, averaged, 1, false), std::invalid_argument);
  EXPECT_THROW(simulate_frame(tracer, demand_config({2, 2}, 5), 1, false), std::invalid_argument);
}

TEST(Balance, RefusesTilesThatDoNotFitAVideoMemory) {
  const PreparedScene scene = balls(16, 16);
  const Tracer tracer(scene, TraceOptions{});
  // The static split's 128 pixels a cell would fit; the one tile of 256 does not.
  MachineConfig config = demand_config({1, 2}, 256);
  config.profile.video_memory_bytes = 200 * kVideoPixelBytes;
  try {
    simulate_frame(tracer, config, 1, false);
    ADD_FAILURE() << "no refusal";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("traced 256 pixels of tiles, which need 768 B of video memory"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace capsim::sim
