// The HTML report in a real browser: headless Chromium loads the page from a
// file URL, the page's script runs, and the DOM it leaves shows that the
// player, the heat map, the table, the timeline and (for a sequence with
// antialiasing) the per-frame chart and the link map were built from the run's
// numbers; a screenshot is taken. The mode-comparison page of `capsim bench
// modes --html` likewise: its script sorts the table of runs. Three browser
// launches in all. Skipped where Chromium is not installed (Debian package
// chromium; .ci/run installs it).

#include "support/balance_scenes.h"
#include "support/cli_run.h"
#include "support/chromium.h"
#include "support/html_page.h"

#include "machine/machine.h"
#include "report/html_report.h"
#include "report/sim_report.h"
#include "support/sequence_builders.h"

#include "capsim/scene/parser.h"

#include <OpenImageIO/imageio.h>
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <regex>
#include <set>
#include <sstream>

namespace capsim::sim {
namespace {

using capsim::testing::data_attributes;
using capsim::testing::dump_dom;
using capsim::testing::find_chromium;
using capsim::testing::read_file;
using capsim::testing::TempDir;

PreparedScene balls(int width, int height) {
  PrepareOptions prep;
  prep.width = width;
  prep.height = height;
  return prepare_scene(parse_scene_file(std::string(CAPSIM_SOURCE_DIR) + "/scenes/balls.csg"), prep);
}

MachineConfig config_of(CellGrid grid, PixelMode mode, int aa) {
  MachineConfig c;
  c.cells = grid;
  c.mode = mode;
  c.profile = load_cost_profile("cap");
  c.aa = {aa, 0.3};
  c.screen = ScreenFormat::Srgb8;
  c.completion_cycles = true;
  return c;
}

const RunFacts kFacts{{"scenes/balls.csg"},
                      "capsim simulate scenes/balls.csg -o s.png", 0.25, "0.1.0",
                      std::nullopt};

void write(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

std::uint64_t number(const std::map<std::string, std::string>& attributes, const std::string& key) {
  const auto it = attributes.find(key);
  if (it == attributes.end()) throw std::runtime_error("no data-" + key);
  return std::stoull(it->second);
}

// The (data-cell, data-value) pairs of the heat map's rectangles.
std::map<int, std::uint64_t> heat_map_values(const std::string& dom) {
  const std::size_t begin = dom.find("id=\"cell-map\"");
  const std::string map = dom.substr(begin, dom.find("</svg>", begin) - begin);
  std::map<int, std::uint64_t> out;
  const std::regex rect("<rect class=\"cell\"[^>]* data-cell=\"([0-9]+)\" data-value=\"([0-9]+)\"");
  for (auto it = std::sregex_iterator(map.begin(), map.end(), rect); it != std::sregex_iterator(); ++it)
    out[std::stoi((*it)[1])] = std::stoull((*it)[2]);
  return out;
}

TEST(HtmlReportInBrowser, ScriptBuildsThePlayerHeatMapTableAndTimelineFromTheRunsNumbers) {
  const std::string chromium = find_chromium();
  SKIP_WITHOUT_CHROMIUM(chromium);
  TempDir dir;
  const PreparedScene scene = balls(64, 48);
  const Tracer tracer(scene, TraceOptions{});
  const SimulationResult r = simulate_frame(tracer, config_of({4, 4}, PixelMode::Dot, 0), 2, false);
  write(dir / "report.html", html_report(r, kFacts));

  // The player half way through the pixels' completions; the table sorted by
  // busy time, most first.
  const std::vector<std::uint64_t>& done = r.screens[0].completion_cycles;
  const auto [first, last] = std::minmax_element(done.begin(), done.end());
  const double hz = static_cast<double>(r.config.profile.clock_hz);
  const std::uint64_t wanted = (*first + *last) / 2;
  const std::string dom = dump_dom(chromium, dir, dir / "report.html",
                                   fmt::format("#t={:.9f}&sort=-busy_cycles", static_cast<double>(wanted) / hz),
                                   dir / "shot.png", 1200, 1500);

  const auto page = data_attributes(dom, "player");  // id="player" is on the <div>; the root has data-built
  const std::size_t root = dom.find("<html");
  const std::string html_tag = dom.substr(root, dom.find('>', root) - root);
  EXPECT_NE(html_tag.find("data-built=\"player completion cellMap table timeline frameChart linkMap tileMap chunkMap "
                          "save\""),
            std::string::npos)
      << html_tag;
  EXPECT_EQ(html_tag.find("data-failed"), std::string::npos) << html_tag;

  // The player: the completion cycles it unpacked, and the pixels it shows at
  // the time it was given.
  ASSERT_FALSE(page.empty()) << "no player in the DOM";
  EXPECT_EQ(number(page, "pixels"), done.size());
  EXPECT_EQ(number(page, "first-cycles"), *first);
  EXPECT_EQ(number(page, "last-cycles"), *last);
  EXPECT_EQ(number(page, "start-cycles"), 0u);
  EXPECT_EQ(number(page, "end-cycles"), r.frame.count());
  const std::uint64_t time = number(page, "time-cycles");
  EXPECT_LE(time > wanted ? time - wanted : wanted - time, 1u);
  const auto shown =
      static_cast<std::uint64_t>(std::count_if(done.begin(), done.end(), [&](std::uint64_t t) { return t <= time; }));
  EXPECT_EQ(number(page, "shown"), shown);
  EXPECT_GT(shown, 0u);
  EXPECT_LT(shown, done.size());

  // The heat map: one rectangle per cell, coloured by its busy cycles.
  const auto map = data_attributes(dom, "cell-map");
  EXPECT_EQ(number(map, "cells"), r.cells.size());
  EXPECT_EQ(map.at("metric"), "busy_cycles");
  std::map<int, std::uint64_t> busy;
  for (const CellReport& c : r.cells) busy[c.id] = c.busy.count();
  EXPECT_EQ(heat_map_values(dom), busy);
  const auto by_busy = [](auto a, auto b) { return a.second < b.second; };
  EXPECT_EQ(number(map, "min"), std::min_element(busy.begin(), busy.end(), by_busy)->second);
  EXPECT_EQ(number(map, "max"), std::max_element(busy.begin(), busy.end(), by_busy)->second);

  // The table: sorted by busy time, most first, ties by cell id.
  const auto table = data_attributes(dom, "cell-table");
  EXPECT_EQ(number(table, "rows"), r.cells.size());
  EXPECT_EQ(table.at("sort-key"), "busy_cycles");
  EXPECT_EQ(table.at("sort-order"), "descending");
  std::vector<CellReport> sorted = r.cells;
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](const CellReport& a, const CellReport& b) { return a.busy > b.busy; });
  std::string order;
  for (const CellReport& c : sorted) order += fmt::format("{}{}", order.empty() ? "" : " ", c.id);
  EXPECT_EQ(table.at("order"), order);
  const std::size_t rows = dom.find("<tbody>", dom.find("id=\"cell-table\""));
  EXPECT_NE(dom.find(fmt::format("<tr data-cell=\"{}\" data-row=\"{}\" data-col=\"{}\" data-pixels=\"{}\" "
                                 "data-rays=\"{}\" data-busy-cycles=\"{}\"",
                                 sorted[0].id, sorted[0].position.row, sorted[0].position.col, sorted[0].pixels,
                                 sorted[0].rays, sorted[0].busy.count()),
                     rows),
            std::string::npos)
      << "the first row is the busiest cell, with its exact figures";

  // The timeline: every track and span of the trace.
  const auto timeline = data_attributes(dom, "timeline");
  EXPECT_EQ(number(timeline, "tracks"), r.timeline.tracks().size());
  EXPECT_EQ(number(timeline, "spans"), r.timeline.spans().size());
  Cycles end;
  for (const TimelineSpan& s : r.timeline.spans()) end = std::max(end, s.end);
  EXPECT_EQ(number(timeline, "end-cycles"), end.count());
  EXPECT_NE(dom.find("<button type=\"button\" id=\"save-trace\">"), std::string::npos) << "the save button is shown";

  // The screenshot: the page drawn at the size asked for, not blank.
  auto in = OIIO::ImageInput::open(dir / "shot.png");
  ASSERT_TRUE(in) << "no screenshot";
  const OIIO::ImageSpec& spec = in->spec();
  EXPECT_EQ(spec.width, 1200);
  EXPECT_EQ(spec.height, 1500);
  std::vector<unsigned char> pixels(static_cast<std::size_t>(spec.width) * spec.height * 3);
  ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, pixels.data()));
  std::set<std::uint32_t> colours;
  for (std::size_t k = 0; k < pixels.size(); k += 3)
    colours.insert(pixels[k] << 16 | pixels[k + 1] << 8 | pixels[k + 2]);
  EXPECT_GT(colours.size(), 200u);
}


TEST(HtmlReportInBrowser, SequenceWithAntialiasingGetsItsFramesChartLinkMapAndFramePlayer) {
  const std::string chromium = find_chromium();
  SKIP_WITHOUT_CHROMIUM(chromium);
  TempDir dir;
  const testing::FrameTracers frames = testing::moving_frames(5, 32, 24);
  const std::vector<const Tracer*>& list = frames.list;
  MachineConfig config = config_of({2, 2}, PixelMode::Dot, 1);
  config.frame_average = true;
  const SimulationResult r = simulate_frames(list, config, 2, false);
  write(dir / "sequence.html", html_report(r, kFacts));
  const std::string dom = dump_dom(chromium, dir, dir / "sequence.html", "#frame=3");

  const auto player = data_attributes(dom, "player");
  ASSERT_FALSE(player.empty()) << "no player in the DOM";
  EXPECT_EQ(number(player, "frame"), 3u);
  const std::vector<std::uint64_t>& done = r.screens[3].completion_cycles;
  EXPECT_EQ(number(player, "first-cycles"), *std::min_element(done.begin(), done.end()));
  EXPECT_EQ(number(player, "last-cycles"), *std::max_element(done.begin(), done.end()));
  EXPECT_EQ(number(player, "shown"), done.size()) << "at the end of the frame every pixel is on the screen";
  EXPECT_NE(dom.find("<figure class=\"frame other-frame\" data-frame=\"0\">"), std::string::npos);
  EXPECT_NE(dom.find("<figure class=\"frame\" data-frame=\"3\">"), std::string::npos);

  const auto chart = data_attributes(dom, "frame-chart");
  EXPECT_EQ(number(chart, "frames"), 5u);
  const auto links = data_attributes(dom, "link-map");
  EXPECT_EQ(number(links, "links"), r.links.size());
  EXPECT_EQ(number(links, "bytes"), link_totals(r).bytes);
  EXPECT_GT(r.links.size(), 0u);
}

// Balanced on demand, the tile map shows which cell traced each tile of the
// frame chosen: as many tiles as the run had, traced by every cell.
TEST(HtmlReportInBrowser, DemandRunGetsItsTileMap) {
  const std::string chromium = find_chromium();
  SKIP_WITHOUT_CHROMIUM(chromium);
  TempDir dir;
  const PreparedScene scene = balls(40, 30);
  const Tracer tracer(scene, TraceOptions{});
  MachineConfig config = config_of({2, 3}, PixelMode::Dot, 0);
  config.balance = {BalanceScheme::Demand, 16};
  const SimulationResult r = simulate_frame(tracer, config, 2, false);
  write(dir / "demand.html", html_report(r, kFacts));
  const std::string dom = dump_dom(chromium, dir, dir / "demand.html", "");
  const auto tiles = data_attributes(dom, "tile-map");
  ASSERT_FALSE(tiles.empty()) << "no tile map in the DOM";
  EXPECT_EQ(number(tiles, "tiles"), 80u);
  EXPECT_EQ(number(tiles, "cells"), 6u);
  EXPECT_EQ(number(tiles, "frame"), 0u);
  EXPECT_EQ(dom.find("data-failed"), std::string::npos);
}

// Stealing, the chunk map shows which cell traced each pixel, decoded from
// the page's zig-zag coded completion cycles: on a block split of BALLS,
// whose background cells take chunks from their neighbours, it counts as
// traced by another cell exactly the pixels of the chunks stolen.
TEST(HtmlReportInBrowser, StealRunGetsItsChunkMap) {
  const std::string chromium = find_chromium();
  SKIP_WITHOUT_CHROMIUM(chromium);
  TempDir dir;
  const PreparedScene scene = balls(40, 30);
  const Tracer tracer(scene, TraceOptions{});
  MachineConfig config = config_of({2, 3}, PixelMode::Block, 0);
  config.balance.scheme = BalanceScheme::Steal;
  config.balance.chunk_pixels = 4;
  const SimulationResult r = simulate_frame(tracer, config, 2, false);
  const std::uint64_t stolen = testing::stolen_pixels(r);
  ASSERT_GT(stolen, 0u) << "the test needs a stolen chunk";
  write(dir / "steal.html", html_report(r, kFacts));
  const std::string dom = dump_dom(chromium, dir, dir / "steal.html", "");
  const auto chunks = data_attributes(dom, "chunk-map");
  ASSERT_FALSE(chunks.empty()) << "no chunk map in the DOM";
  EXPECT_EQ(number(chunks, "cells"), 6u);
  EXPECT_EQ(number(chunks, "stolen"), stolen);
  EXPECT_EQ(number(chunks, "frame"), 0u);
  EXPECT_EQ(dom.find("data-failed"), std::string::npos);
  EXPECT_NE(dom.find("id=\"stealing\""), std::string::npos);
}

}  // namespace
}  // namespace capsim::sim
