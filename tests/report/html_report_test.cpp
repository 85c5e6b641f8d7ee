// The HTML report (html_report.h) read back as a file: one document with no
// external reference, for small and large grids and screens in every mode; its
// data blocks are the --report and --trace JSON byte for byte and cannot end
// early; its completion data unpacks to the run's completion cycles; its
// images are the run's; its essentials are plain HTML; its size.

#include "support/html_page.h"

#include "machine/machine.h"
#include "report/heatmap.h"
#include "report/html_report.h"
#include "report/page_data.h"
#include "report/sim_report.h"
#include "support/sequence_builders.h"

#include "capsim/image/image_io.h"
#include "capsim/scene/parser.h"

#include <fmt/core.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>

namespace capsim::sim {
namespace {

using capsim::testing::data_block_text;
using capsim::testing::from_base64;
using capsim::testing::image_data_uri;
using capsim::testing::unescape_block;
using capsim::testing::unpack_completion;

PreparedScene balls(int width, int height) {
  PrepareOptions prep;
  prep.width = width;
  prep.height = height;
  return prepare_scene(parse_scene_file(std::string(CAPSIM_SOURCE_DIR) + "/scenes/balls.csg"), prep);
}

MachineConfig config_of(CellGrid grid, PixelMode mode, int aa = 0, ScreenFormat screen = ScreenFormat::Srgb8) {
  MachineConfig c;
  c.cells = grid;
  c.mode = mode;
  c.profile = load_cost_profile("cap");
  c.aa = {aa, 0.3};
  c.screen = screen;
  c.completion_cycles = true;
  return c;
}

const RunFacts kFacts{{"scenes/balls.csg"},
                      "capsim simulate scenes/balls.csg -o s.png", 1.5, "0.1.0",
                      std::nullopt};


// A frame-averaged, antialiased run of five frames on 2x2 cells: every part of
// the page at once.
SimulationResult sequence_run() {
  const testing::FrameTracers frames = testing::moving_frames(5, 24, 20);
  const std::vector<const Tracer*>& list = frames.list;
  MachineConfig config = config_of({2, 2}, PixelMode::Dot, 1);
  config.frame_average = true;
  return simulate_frames(list, config, 2, false);
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// One whole document; nothing it shows or runs comes from outside it.
void expect_self_contained(const std::string& page, const std::string& what) {
  EXPECT_TRUE(page.starts_with("<!DOCTYPE html>\n")) << what;
  EXPECT_TRUE(page.ends_with("</html>\n")) << what;
  const std::string text = lower(page);
  for (const char* outside : {"http:", "https:", "ftp:", "file:", "<link", "<iframe", "<object", "<embed", "<base",
                              "@import", "srcset", "xlink:href", "<form", "<audio", "<video", "<source"})
    EXPECT_EQ(text.find(outside), std::string::npos) << what << ": " << outside;
  // Every src is a data URI, every href an anchor in the page, every CSS url()
  // one of the page's own SVG definitions (the script's URL.createObjectURL,
  // for the save buttons, is not one).
  const std::pair<const char*, std::vector<const char*>> allowed[] = {
      {"src=", {"\"data:"}}, {"href=", {"\"#"}}, {"url(", {"#", "data:"}}};
  for (const auto& [attribute, starts] : allowed)
    for (std::size_t at = text.find(attribute); at != std::string::npos; at = text.find(attribute, at + 1)) {
      if (attribute == std::string("url(") && page.compare(at, 4, "url(") != 0) continue;
      const std::string value = text.substr(at + std::string(attribute).size(), 6);
      EXPECT_TRUE(std::any_of(starts.begin(), starts.end(), [&](const char* s) { return value.starts_with(s); }))
          << what << ": " << attribute << value;
    }
  // Three data blocks and the page's own script, nothing loaded.
  EXPECT_EQ(count(text, "<script"), 4u) << what;
  EXPECT_EQ(count(text, "</script"), 4u) << what;
  EXPECT_EQ(count(text, "<script type=\"application/json\" id="), 3u) << what;
  EXPECT_EQ(count(text, "<script>\n"), 1u) << what;
}

TEST(HtmlReport, IsOneDocumentWithNoExternalReferenceOnEveryGridScreenAndMode) {
  const PreparedScene small = balls(16, 16);
  const Tracer small_tracer(small, TraceOptions{});
  for (PixelMode mode : {PixelMode::Dot, PixelMode::Line, PixelMode::Block})
    for (CellGrid grid : {CellGrid{1, 1}, CellGrid{8, 8}, CellGrid{32, 32}})
      for (int aa : {0, 1}) {
        const SimulationResult r = simulate_frame(small_tracer, config_of(grid, mode, aa), 2, false);
        expect_self_contained(html_report(r, kFacts),
                              fmt::format("16x16 {} {} aa {}", to_string(mode), to_string(grid), aa));
      }
  const PreparedScene large = balls(1024, 1024);
  const Tracer large_tracer(large, TraceOptions{});
  for (PixelMode mode : {PixelMode::Dot, PixelMode::Line, PixelMode::Block}) {
    const SimulationResult r = simulate_frame(large_tracer, config_of({8, 8}, mode), 2, false);
    expect_self_contained(html_report(r, kFacts), fmt::format("1024x1024 {}", to_string(mode)));
  }
  expect_self_contained(html_report(sequence_run(), kFacts), "sequence");
}

TEST(HtmlReport, EmbedsTheReportAndTheTraceJsonByteForByte) {
  const PreparedScene scene = balls(40, 30);
  const Tracer tracer(scene, TraceOptions{});
  const SimulationResult runs[] = {simulate_frame(tracer, config_of({3, 4}, PixelMode::Line), 2, false),
                                   simulate_frame(tracer, config_of({2, 3}, PixelMode::Dot, 2), 2, false),
                                   sequence_run()};
  for (const SimulationResult& r : runs) {
    const std::string page = html_report(r, kFacts);
    EXPECT_EQ(unescape_block(data_block_text(page, "report-data")), report_json(r).dump(2) + "\n");
    EXPECT_EQ(unescape_block(data_block_text(page, "trace-data")), chrome_trace_text(r));
  }
}

// Given a provenance, the page's report data is the --report JSON with it, and
// the run's table shows it, a path in it escaped as HTML.
TEST(HtmlReport, CarriesAndShowsTheProvenance) {
  const PreparedScene scene = balls(16, 12);
  const Tracer tracer(scene, TraceOptions{});
  const SimulationResult r = simulate_frame(tracer, config_of({2, 2}, PixelMode::Dot), 1, false);
  Provenance p;
  p.argv = {"capsim", "simulate", "a&b.csg"};
  p.version = "0.1.0";
  p.scenes = {{"a&b.csg", std::string(64, '0')}};
  p.profile = p.profile_name = "cap";
  p.profile_sha256 = r.config.profile.text_sha256;
  p.options = {{"cells", "2x2"}};
  RunFacts facts = kFacts;
  facts.provenance = p;
  const std::string page = html_report(r, facts);
  const std::string report = unescape_block(data_block_text(page, "report-data"));
  EXPECT_EQ(report, report_json_text(r, &p));
  EXPECT_EQ(nlohmann::json::parse(report)["provenance"], provenance_json(p));
  EXPECT_NE(page.find("<th>Command as typed</th><td><code>capsim simulate &#39;a&amp;b.csg&#39;</code></td>"),
            std::string::npos);
  EXPECT_NE(page.find("<th>SHA-256 of a&amp;b.csg</th><td><code>" + std::string(64, '0') + "</code></td>"),
            std::string::npos);
  EXPECT_NE(page.find("<th>Options</th><td>cells 2x2</td>"), std::string::npos);
  EXPECT_FALSE(nlohmann::json::parse(unescape_block(data_block_text(html_report(r, kFacts), "report-data")))
                   .contains("provenance"));
}

TEST(HtmlReport, DataBlocksCannotEndTheirElementEarly) {
  const PreparedScene scene = balls(16, 12);
  const Tracer tracer(scene, TraceOptions{});
  MachineConfig config = config_of({2, 2}, PixelMode::Dot);
  const std::string name = "x</script><!--<script>y</SCRIPT>";
  config.profile.name = name;
  const SimulationResult r = simulate_frame(tracer, config, 1, false);
  const std::string page = html_report(r, kFacts);
  for (const char* id : {"report-data", "trace-data", "page-data"}) {
    const std::string block = data_block_text(page, id);
    EXPECT_EQ(block.find("</"), std::string::npos) << id;
    EXPECT_EQ(block.find("<!--"), std::string::npos) << id;
    // Still valid JSON, holding the same value.
    EXPECT_TRUE(nlohmann::json::accept(block)) << id;
  }
  EXPECT_EQ(nlohmann::json::parse(data_block_text(page, "report-data"))["profile"], name);
  EXPECT_EQ(unescape_block(data_block_text(page, "report-data")), report_json(r).dump(2) + "\n");
  EXPECT_EQ(count(lower(page), "</script"), 4u);
  EXPECT_EQ(page.find("x</script><!--"), std::string::npos);  // in the HTML it is escaped text too
}

TEST(HtmlReport, CompletionDataUnpacksToTheRunsCompletionCycles) {
  const PreparedScene scene = balls(45, 38);
  const Tracer tracer(scene, TraceOptions{});
  std::vector<SimulationResult> runs;
  for (PixelMode mode : {PixelMode::Dot, PixelMode::Line, PixelMode::Block})
    runs.push_back(simulate_frame(tracer, config_of({3, 5}, mode), 2, false));
  runs.push_back(simulate_frame(tracer, config_of({4, 4}, PixelMode::Block, 1), 2, false));
  runs.push_back(sequence_run());
  for (const SimulationResult& r : runs) {
    const std::string page = html_report(r, kFacts);
    for (std::size_t f = 0; f < r.screens.size(); ++f)
      EXPECT_EQ(unpack_completion(page, static_cast<int>(f), r.width, r.height), r.screens[f].completion_cycles)
          << to_string(r.config.mode) << " frame " << f;
  }
}

TEST(HtmlReport, ImagesAreTheRunsScreenAndCompletionPicturesAsPng) {
  const PreparedScene scene = balls(33, 21);
  const Tracer tracer(scene, TraceOptions{});
  const SimulationResult bytes = simulate_frame(tracer, config_of({2, 2}, PixelMode::Dot), 2, false);
  const SimulationResult floats =
      simulate_frame(tracer, config_of({2, 2}, PixelMode::Dot, 0, ScreenFormat::Float), 2, false);
  const std::string page = html_report(bytes, kFacts);
  const std::string screen = image_data_uri(page, "screen-0");
  EXPECT_EQ(from_base64(screen), encode_png_rgb8(33, 21, bytes.screens[0].screen_srgb8));
  // A float screen (an EXR run) shows the same 8-bit screen.
  EXPECT_EQ(image_data_uri(html_report(floats, kFacts), "screen-0"), screen);
  const auto [first, last] = std::minmax_element(bytes.screens[0].completion_cycles.begin(),
                                                 bytes.screens[0].completion_cycles.end());
  const RgbImage map = render_completion_map(bytes.screens[0].completion_cycles, 33, 21, Cycles(*first), Cycles(*last));
  EXPECT_EQ(from_base64(image_data_uri(page, "completion-map-0")), encode_png_rgb8(33, 21, map.rgb));
  const RgbImage heat = render_heatmap(bytes);
  EXPECT_EQ(from_base64(image_data_uri(page, "cell-heatmap")), encode_png_rgb8(heat.width, heat.height, heat.rgb));
}

TEST(HtmlReport, EssentialsArePlainHtml) {
  const PreparedScene scene = balls(40, 30);
  const Tracer tracer(scene, TraceOptions{});
  const SimulationResult plain = simulate_frame(tracer, config_of({3, 4}, PixelMode::Block), 2, false);
  const SimulationResult aa = simulate_frame(tracer, config_of({2, 3}, PixelMode::Dot, 1), 2, false);
  const SimulationResult sequence = sequence_run();
  MachineConfig demand_config = config_of({2, 2}, PixelMode::Dot);
  demand_config.balance = {BalanceScheme::Demand, 16};
  const SimulationResult demand = simulate_frame(tracer, demand_config, 2, false);
  for (const SimulationResult* r : {&plain, &aa, &sequence, &demand}) {
    const std::string page = html_report(*r, kFacts);
    const std::uint64_t hz = r->config.profile.clock_hz;
    // Outside the data blocks and the script: what a browser without
    // JavaScript shows.
    const std::string html = page.substr(0, page.find("<script type=\"application/json\""));
    EXPECT_EQ(count(html, "<tr data-cell=\""), r->cells.size());
    for (const CellReport& c : r->cells)
      EXPECT_NE(html.find(fmt::format("<tr data-cell=\"{}\"><td>{}</td><td>{}</td><td>{}</td>", c.id, c.id,
                                      c.position.row, c.position.col)),
                std::string::npos);
    const LoadSpread s = load_spread(*r);
    EXPECT_NE(html.find("<tr><th>Max</th><td title=\""), std::string::npos);
    EXPECT_NE(html.find(fmt::format("\">{:.3f} s</td></tr>", s.max_finish.seconds(hz))), std::string::npos);
    EXPECT_NE(html.find(fmt::format("\">{:.3f} s</td></tr>", s.min_finish.seconds(hz))), std::string::npos);
    EXPECT_NE(html.find(fmt::format("<td>{:.2f} %</td>", s.deviation_percent)), std::string::npos);
    EXPECT_EQ(count(html, "<tr data-process=\""), 5u);
    EXPECT_EQ(count(html, "<img id=\"screen-"), r->screens.size());
    EXPECT_EQ(html.find("id=\"antialiasing\"") != std::string::npos, r->config.aa.depth > 0);
    EXPECT_EQ(html.find("id=\"sequence\"") != std::string::npos, r->screens.size() > 1);
    EXPECT_EQ(html.find("id=\"balancing\"") != std::string::npos, r->config.balance.on_demand());
  }
  const std::string demand_page = html_report(demand, kFacts);
  EXPECT_NE(demand_page.find(fmt::format("<tr><th>Grants</th><td>{}</td></tr>", demand.balancing.grants)),
            std::string::npos);
  EXPECT_NE(demand_page.find("<div id=\"tile-map\" class=\"tile-map\"></div>"), std::string::npos);
  const std::string aa_page = html_report(aa, kFacts);
  const std::string links = aa_page.substr(aa_page.find("<table id=\"link-table\""));
  EXPECT_EQ(count(links.substr(0, links.find("</table>")), "<tr><td>"), aa.links.size());
  const std::string seq_page = html_report(sequence, kFacts);
  const std::string frames = seq_page.substr(seq_page.find("<table id=\"frame-table\""));
  EXPECT_EQ(count(frames.substr(0, frames.find("</table>")), "<tr><td>"), 5u);
  EXPECT_NE(seq_page.find(fmt::format("<td>{:.2f} %</td></tr></tbody>", max_deviation_percent(sequence))),
            std::string::npos);
}

TEST(HtmlReport, DoesNotDependOnHostThreads) {
  const PreparedScene scene = balls(40, 30);
  const Tracer tracer(scene, TraceOptions{});
  const MachineConfig config = config_of({3, 3}, PixelMode::Dot, 1);
  EXPECT_EQ(html_report(simulate_frame(tracer, config, 1, false), kFacts),
            html_report(simulate_frame(tracer, config, 2, false), kFacts));
}

TEST(HtmlReport, BallsAt512x512On8x8CellsStaysUnderFiveMegabytes) {
  // docs/report.md gives the sizes.
  const PreparedScene scene = balls(512, 512);
  const Tracer tracer(scene, TraceOptions{});
  for (PixelMode mode : {PixelMode::Dot, PixelMode::Line, PixelMode::Block})
    EXPECT_LT(html_report(simulate_frame(tracer, config_of({8, 8}, mode), 2, false), kFacts).size(), 5'000'000u)
        << to_string(mode);
}

TEST(HtmlReport, RefusesARunWithoutCompletionCycles) {
  const PreparedScene scene = balls(8, 8);
  const Tracer tracer(scene, TraceOptions{});
  MachineConfig config = config_of({2, 2}, PixelMode::Dot);
  config.completion_cycles = false;
  EXPECT_THROW((void)html_report(simulate_frame(tracer, config, 1, false), kFacts), std::logic_error);
}

}  // namespace
}  // namespace capsim::sim
