// Stealing (machine/parts/balance.h): the windows cut into chunks, idle cells
// taking half of a neighbour's unstarted chunks over the links and sending
// the pixels back, and what must hold in every run: the screen is the
// tracer's, every chunk is traced once, the links carry what was sent and
// received, and the cycles of a small run are exactly these.

#include "machine/parts/balance.h"
#include "machine/machine.h"
#include "machine/run_figures.h"
#include "machine/unit_memory.h"

#include "support/balance_scenes.h"
#include "support/shipped_scene.h"

#include "capsim/trace/antialias.h"
#include "capsim/trace/render.h"

#include <fmt/core.h>
#include <gtest/gtest.h>

#include <random>
#include <string>

namespace capsim::sim {
namespace {

using testing::random_scene;
using testing::same_floats;

PreparedScene balls(int width, int height) { return testing::shipped_scene("balls.csg", width, height); }

MachineConfig steal_config(CellGrid grid, PixelMode mode, int chunk_pixels, ScreenFormat format = ScreenFormat::Float) {
  MachineConfig c;
  c.cells = grid;
  c.mode = mode;
  c.profile = load_cost_profile("cap");
  c.balance.scheme = BalanceScheme::Steal;
  c.balance.chunk_pixels = chunk_pixels;
  c.screen = format;
  return c;
}

std::uint64_t count_kind(const SimulationResult& r, LinkKind kind) {
  std::uint64_t n = 0;
  for (const LinkMessage& m : r.link_messages) n += m.packet.kind == kind ? 1 : 0;
  return n;
}

// Every chunk of every window traced once, by its owner or a neighbour that
// took it; the cells' pixels add up to the screen; every request answered
// with work or "no work"; the balancing bytes the cells sent equal those they
// took in and what the links carried for stealing; the chunks taken equal
// those given; a thief stops only after each of its neighbours said "no
// work".
void expect_conserved(const SimulationResult& r, const std::string& what) {
  const int chunk = r.config.balance.chunk_pixels;
  ASSERT_EQ(r.chunk_cells.size(), r.screens.size()) << what;
  std::uint64_t pixels = 0, requests = 0, refused = 0, answered = 0, stolen = 0, given = 0, sent = 0, received = 0;
  for (const CellReport& c : r.cells) {
    pixels += c.pixels;
    requests += c.steal_requests;
    refused += c.steals_refused;
    answered += c.requests_answered;
    stolen += c.chunks_stolen;
    given += c.chunks_given;
    sent += c.balance_bytes_sent;
    received += c.balance_bytes_received;
    EXPECT_EQ(c.idle + c.busy + c.comm, c.finish) << what << " cell " << c.id;
    std::uint64_t traced = 0;
    for (const ChunkRun& run : c.chunk_runs)
      for (int k = run.first_chunk; k < run.first_chunk + run.chunks; ++k) {
        EXPECT_EQ(r.chunk_cells.at(run.frame).at(run.owner).at(k), c.id) << what << " chunk " << k;
        ++traced;
      }
    std::uint64_t listed = 0;
    for (std::size_t f = 0; f < r.chunk_cells.size(); ++f)
      for (const auto& window : r.chunk_cells[f])
        for (const CellId tracer : window) listed += tracer == c.id ? 1 : 0;
    EXPECT_EQ(traced, listed) << what << " cell " << c.id;
    const int neighbours = (c.position.row > 0) + (c.position.row + 1 < r.config.cells.rows) +
                           (c.position.col > 0) + (c.position.col + 1 < r.config.cells.cols);
    EXPECT_GE(c.steals_refused, static_cast<std::uint64_t>(neighbours) * r.screens.size()) << what << " cell " << c.id;
  }
  for (std::size_t f = 0; f < r.chunk_cells.size(); ++f) {
    ASSERT_EQ(r.chunk_cells[f].size(), r.cells.size()) << what;
    const WindowLayout layout(r.config.mode, r.config.cells, r.width, r.height);
    for (CellId w = 0; w < static_cast<CellId>(r.cells.size()); ++w)
      EXPECT_EQ(static_cast<int>(r.chunk_cells[f][w].size()), chunk_count(layout.window(w).pixel_count(), chunk))
          << what;
  }
  EXPECT_EQ(pixels, static_cast<std::uint64_t>(r.width) * r.height * r.screens.size()) << what;
  EXPECT_EQ(stolen, given) << what;
  EXPECT_EQ(requests, answered) << what;
  EXPECT_EQ(count_kind(r, LinkKind::StealRequest), requests) << what;
  EXPECT_EQ(count_kind(r, LinkKind::NoWork), refused) << what;
  EXPECT_EQ(count_kind(r, LinkKind::Work), requests - refused) << what;
  EXPECT_EQ(count_kind(r, LinkKind::Pixels), requests - refused) << what;
  EXPECT_EQ(sent, received) << what;
  EXPECT_EQ(sent, r.steal_links.bytes) << what;
  EXPECT_EQ(r.steal_links.messages, count_kind(r, LinkKind::StealRequest) + count_kind(r, LinkKind::Work) +
                                        count_kind(r, LinkKind::NoWork) + count_kind(r, LinkKind::Pixels))
      << what;
}

TEST(Steal, ParsesTheSchemeAndCutsWindowsIntoChunks) {
  EXPECT_TRUE(parse_balance("steal").stealing());
  EXPECT_EQ(parse_balance("steal").chunk_pixels, kDefaultChunkPixels);
  EXPECT_EQ(parse_balance("steal:1").chunk_pixels, 1);
  EXPECT_EQ(parse_balance("steal:65536").chunk_pixels, 65536);
  EXPECT_EQ(to_string(parse_balance("steal")), "steal:16");
  EXPECT_EQ(to_string(parse_balance("steal:5")), "steal:5");
  for (const char* bad : {"steal:", "steal:0", "steal:65537", "steal:-1", "steal:+4", "steal:4x", "Steal", "steal4"})
    EXPECT_THROW(parse_balance(bad), std::invalid_argument) << bad;
  EXPECT_EQ(chunk_count(0, 16), 0);
  EXPECT_EQ(chunk_count(33, 16), 3);
  EXPECT_EQ(chunk_range(2, 33, 16).first_pixel, 32);
  EXPECT_EQ(chunk_range(2, 33, 16).pixels, 1);
  EXPECT_EQ(chunk_range(1, 33, 16).pixels, 16);
}

TEST(Steal, ScreenEqualsTheTracerAloneInEveryModeOnOneAndTwoThreads) {
  const PreparedScene scene = balls(45, 38);
  const Tracer tracer(scene, TraceOptions{});
  const Framebuffer rendered = render(tracer, 2);
  for (const CellGrid grid : {CellGrid{1, 1}, CellGrid{2, 3}, CellGrid{4, 4}})
    for (const PixelMode mode : {PixelMode::Block, PixelMode::Line, PixelMode::Dot})
      for (const int chunk : {1, 5, 16})
        for (const int threads : {1, 2}) {
          const std::string what =
              fmt::format("{} {} steal:{} threads {}", to_string(grid), to_string(mode), chunk, threads);
          const SimulationResult r = simulate_frame(tracer, steal_config(grid, mode, chunk), threads, false);
          EXPECT_TRUE(same_floats(r.screens[0].screen.rgba, rendered.rgba)) << what;
          EXPECT_TRUE(same_floats(r.screens[0].screen.depth, rendered.depth)) << what;
          EXPECT_TRUE(same_floats(r.screens[0].screen.id, rendered.id)) << what;
          expect_conserved(r, what);
        }
}

TEST(Steal, ResultsDoNotDependOnHostThreadsInEitherFormat) {
  const PreparedScene scene = balls(40, 30);
  const Tracer tracer(scene, TraceOptions{});
  for (const ScreenFormat format : {ScreenFormat::Float, ScreenFormat::Srgb8}) {
    MachineConfig config = steal_config({3, 3}, PixelMode::Block, 7, format);
    config.completion_cycles = true;
    const SimulationResult one = simulate_frame(tracer, config, 1, false);
    const SimulationResult two = simulate_frame(tracer, config, 2, false);
    EXPECT_EQ(one.timeline, two.timeline);
    EXPECT_EQ(one.chunk_cells, two.chunk_cells);
    EXPECT_EQ(one.screens[0].screen_srgb8, two.screens[0].screen_srgb8);
    EXPECT_TRUE(same_floats(one.screens[0].screen.rgba, two.screens[0].screen.rgba));
    EXPECT_EQ(one.screens[0].completion_cycles, two.screens[0].completion_cycles);
  }
}

TEST(Steal, ConservationHoldsOnRandomScenesGridsModesAndChunks) {
  std::mt19937 rng(19);
  for (unsigned seed = 0; seed < 8; ++seed) {
    const int width = 5 + static_cast<int>(rng() % 20), height = 5 + static_cast<int>(rng() % 20);
    const PreparedScene scene = random_scene(seed, width, height);
    const Tracer tracer(scene, TraceOptions{});
    const Framebuffer rendered = render(tracer, 1);
    const CellGrid grid{1 + static_cast<int>(rng() % 4), 1 + static_cast<int>(rng() % 4)};
    const PixelMode mode = static_cast<PixelMode>(rng() % 3);
    const int chunk = 1 + static_cast<int>(rng() % 9);
    const std::string what = fmt::format("seed {} {}x{} cells {} {} steal:{}", seed, width, height, to_string(grid),
                                         to_string(mode), chunk);
    const SimulationResult r = simulate_frame(tracer, steal_config(grid, mode, chunk), 2, false);
    EXPECT_TRUE(same_floats(r.screens[0].screen.rgba, rendered.rgba)) << what;
    expect_conserved(r, what);
  }
}

// One cell has no neighbour to steal from: it traces its window chunk by
// chunk, in the static run's time.
TEST(Steal, OneCellTakesTheStaticTime) {
  const PreparedScene scene = balls(24, 20);
  const Tracer tracer(scene, TraceOptions{});
  MachineConfig fixed = steal_config({1, 1}, PixelMode::Dot, 16);
  fixed.balance = {};
  const SimulationResult s = simulate_frame(tracer, fixed, 2, false);
  const SimulationResult r = simulate_frame(tracer, steal_config({1, 1}, PixelMode::Dot, 16), 2, false);
  EXPECT_EQ(r.frame, s.frame);
  EXPECT_EQ(r.cells[0].busy, s.cells[0].busy);
  EXPECT_EQ(r.cells[0].steal_requests, 0u);
  EXPECT_TRUE(r.link_messages.empty());
}

// The exact cycles of a small run: BALLS at 32x24 in block mode on 2x2 cells,
// chunks of 4 pixels. The cap profile's links carry 15 Mbit/s at 8 MHz with
// 8 cycles of latency: a 4-byte request is on its link 18 cycles and in the
// victim 26 cycles after it left; "no work" (4 bytes) is back 26 cycles
// later, so a refused request keeps its thief waiting 26 + 26 - 18 = 34
// cycles from the moment the request has left it; work (8 bytes, 35 cycles
// on the link) is back 26 + 43 - 18 = 51 cycles after.
TEST(Steal, SmallStealRunTakesExactlyTheseCycles) {
  const PreparedScene scene = balls(32, 24);
  const Tracer tracer(scene, TraceOptions{});
  const SimulationResult r = simulate_frame(tracer, steal_config({2, 2}, PixelMode::Block, 4), 2, false);
  std::vector<std::uint64_t> finish, stolen, given;
  for (const CellReport& c : r.cells) {
    finish.push_back(c.finish.count());
    stolen.push_back(c.chunks_stolen);
    given.push_back(c.chunks_given);
  }
  EXPECT_EQ(finish, (std::vector<std::uint64_t>{50619267, 47563678, 47558805, 47627546}));
  // Cells 1 and 2 ask cell 3 first (south of cell 1, east of cell 2): it
  // gives them 10 chunks; cell 0, the slowest, never has two unstarted
  // chunks when asked.
  EXPECT_EQ(stolen, (std::vector<std::uint64_t>{0, 9, 1, 0}));
  EXPECT_EQ(given, (std::vector<std::uint64_t>{0, 0, 0, 10}));
  EXPECT_EQ(r.frame.count(), 50619267u);
  for (const CellReport& c : r.cells)
    EXPECT_EQ(c.steal_wait.count(), 51u * (c.steal_requests - c.steals_refused) + 34u * c.steals_refused)
        << "cell " << c.id;
  expect_conserved(r, "pinned run");
}

// Stolen pixels are on the screen when they are back in their owner's video
// memory; the owner's own as it traces them.
TEST(Steal, CompletionCyclesFollowTheChunks) {
  const PreparedScene scene = balls(24, 16);
  const Tracer tracer(scene, TraceOptions{});
  MachineConfig config = steal_config({2, 2}, PixelMode::Block, 4);
  config.completion_cycles = true;
  const SimulationResult r = simulate_frame(tracer, config, 2, false);
  const WindowLayout layout(PixelMode::Block, config.cells, 24, 16);
  std::size_t returned = 0;
  for (const CellReport& c : r.cells) {
    const CellWindow& w = layout.window(c.id);
    for (const ReturnedChunks& back : c.returned) {
      ++returned;
      const ChunkRange range = chunk_range(back.first_chunk, w.pixel_count(), 4);
      const ScreenPixel p = w.screen_pixel(range.first_pixel);
      EXPECT_EQ(r.screens[0].completion_cycles[static_cast<std::size_t>(p.y) * 24 + p.x], back.arrived.count());
    }
    for (const ChunkRun& run : c.chunk_runs) {
      if (run.owner != c.id) continue;
      const ChunkRange range = chunk_range(run.first_chunk, w.pixel_count(), 4);
      const ScreenPixel last = w.screen_pixel(range.first_pixel + range.pixels - 1);
      EXPECT_EQ(r.screens[0].completion_cycles[static_cast<std::size_t>(last.y) * 24 + last.x], run.end.count());
    }
  }
  EXPECT_GT(returned, 0u) << "the test needs a stolen chunk";
}

// Antialiased, the corners are traced and exchanged as statically and the
// subdivision is stolen: the screen is render's, the corner phases are the
// static run's, and each work message carries its pixels' corners.
TEST(Steal, AntialiasedRunsStealTheSubdivision) {
  const PreparedScene scene = balls(30, 22);
  const Tracer tracer(scene, TraceOptions{});
  const AntialiasOptions aa{2, 0.3};
  const Framebuffer rendered = render(tracer, 2, nullptr, nullptr, aa);
  MachineConfig config = steal_config({3, 3}, PixelMode::Block, 3);
  config.aa = aa;
  MachineConfig fixed = config;
  fixed.balance = {};
  const SimulationResult s = simulate_frame(tracer, fixed, 2, false);
  for (const int threads : {1, 2}) {
    const SimulationResult r = simulate_frame(tracer, config, threads, false);
    EXPECT_TRUE(same_floats(r.screens[0].screen.rgba, rendered.rgba)) << threads;
    expect_conserved(r, "antialiased");
    for (std::size_t c = 0; c < r.cells.size(); ++c) {
      EXPECT_EQ(r.cells[c].trace_corners, s.cells[c].trace_corners);
      EXPECT_EQ(r.cells[c].corners_received, s.cells[c].corners_received);
    }
    const std::uint64_t stolen = testing::stolen_pixels(r);
    ASSERT_GT(stolen, 0u);
    std::uint64_t work_bytes = 0;
    for (const LinkMessage& m : r.link_messages)
      if (m.packet.kind == LinkKind::Work) work_bytes += m.bytes;
    EXPECT_EQ(work_bytes, count_kind(r, LinkKind::Work) * kStolenWorkHeaderBytes +
                              stolen * 4 * kScreenSampleBytes);
    // Stealing shortens the frame of this lopsided block split.
    EXPECT_LT(r.frame, s.frame);
  }
}

TEST(Steal, SequencesStealEachFramesChunks) {
  const PreparedScene a = balls(20, 12), b = balls(20, 12);
  const Tracer ta(a, TraceOptions{}), tb(b, TraceOptions{});
  const SimulationResult r = simulate_frames({&ta, &tb}, steal_config({2, 2}, PixelMode::Block, 2), 2, false);
  ASSERT_EQ(r.screens.size(), 2u);
  const Framebuffer rendered = render(ta, 1);
  for (const FrameScreen& s : r.screens) EXPECT_TRUE(same_floats(s.screen.rgba, rendered.rgba));
  expect_conserved(r, "sequence");
}

TEST(Steal, RefusesFrameAveraging) {
  const PreparedScene scene = balls(8, 8);
  const Tracer tracer(scene, TraceOptions{});
  MachineConfig averaged = steal_config({2, 2}, PixelMode::Dot, 4);
  averaged.frame_average = true;
  EXPECT_THROW(simulate_frame(tracer, averaged, 1, false), std::invalid_argument);
}

}  // namespace
}  // namespace capsim::sim
