// The page of a sweep's plots: a figure per scene with a series per
// combination of the other axes the sweep varies, a row per point, nothing
// from outside the page, and the same bytes from the same records.

#include "paper/sweeps/sweep_page.h"
#include "paper/sweeps/sweep_records.h"

#include <fmt/core.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace capsim::sim {
namespace {

using nlohmann::json;

int count_of(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// A record as sweep_record writes it, with made-up figures: the time falls as
// the cells grow.
json record(const json& scene, const std::string& cells, const std::string& mode, int aa, std::uint64_t cycles,
            double d) {
  return {{"scene", scene},          {"cells", cells},        {"mode", mode},            {"balance", "static"},
          {"aa", aa},                {"profile", "cap"},      {"size", "16x16"},
          {"grid", "auto"},          {"primary_only", false}, {"frame_average", false},
          {"voxel_generation", "host"},
          {"frames", 1},             {"width", 16},           {"height", 16},
          {"clock_hz", 1000},        {"frame_cycles", cycles}, {"frame_seconds", cycles / 1000.0},
          {"max_cycles", cycles},    {"min_cycles", cycles / 2}, {"max_seconds", cycles / 1000.0},
          {"min_seconds", cycles / 2000.0}, {"deviation_percent", d}, {"busy_deviation_percent", d},
          {"bus_transfers", 4},      {"bus_bytes", 1234567},  {"bus_cycles", 10},
          {"bus_seconds", 0.01},     {"link_messages", 0},    {"link_bytes", 0},
          {"balance_bus_percent", 0.0}, {"tile_wait_cycles", 0},
          {"chunks_stolen", 0},      {"steal_link_bytes", 0}, {"capsim_version", "0.1.0"}};
}

// 2 scenes (one a sequence) x 2 modes x 2 aa x 3 cell grids.
std::vector<json> records() {
  std::vector<json> out;
  for (const json& scene : {json("../scenes/balls.csg"), json::array({"d/f0.csg", "d/f1.csg"})})
    for (int aa : {0, 2})
      for (const char* mode : {"line", "dot"})
        for (const auto& [cells, cycles] : {std::pair<const char*, int>{"2x2", 8000}, {"4x4", 3000}, {"8x8", 1200}})
          out.push_back(record(scene, cells, mode, aa, static_cast<std::uint64_t>(cycles * (aa + 1)),
                               std::string(mode) == "dot" ? 0.0 : 12.5));
  add_speedups(out);
  return out;
}

TEST(SweepPage, AFigurePerSceneWithASeriesPerCombinationOfTheOtherAxes) {
  const std::string page = sweep_page(records(), "small.json", "0.1.0");
  EXPECT_EQ(count_of(page, "<figure class=\"scene-plot\""), 2);
  EXPECT_NE(page.find("data-scene=\"balls.csg\" data-series=\"4\""), std::string::npos);
  EXPECT_NE(page.find("data-scene=\"f0.csg to f1.csg (2 files)\" data-series=\"4\""), std::string::npos);
  // Three panels each: d, time and speed-up, each with the four series' legend.
  EXPECT_EQ(count_of(page, ">balls.csg: d</text>"), 1);
  EXPECT_EQ(count_of(page, ">balls.csg: time</text>"), 1);
  EXPECT_EQ(count_of(page, ">balls.csg: speed-up</text>"), 1);
  EXPECT_EQ(count_of(page, ">aa 2, mode dot</text>"), 0) << "labels follow the CSV's order of the inputs";
  EXPECT_EQ(count_of(page, ">mode dot, aa 2</text>"), 6);
  EXPECT_NE(page.find("a series per mode, aa."), std::string::npos);
  // The cells as ticks of the x axis.
  EXPECT_EQ(count_of(page, "text-anchor=\"middle\">64</text>"), 6);
}

TEST(SweepPage, HeaderNamesTheVaryingAxesAndTheFixedOnes) {
  const std::string page = sweep_page(records(), "small.json", "0.1.0");
  EXPECT_NE(page.find("<title>capsim sweep: small.json</title>"), std::string::npos);
  EXPECT_NE(page.find("<strong id=\"point-count\">24 points</strong>; the same for every point: balance static, "
                      "profile cap, size 16x16, grid auto, primary_only false, frame_average false, "
                      "voxel_generation host."),
            std::string::npos);
  EXPECT_NE(page.find("<li><strong>cells</strong>: 2x2, 4x4 and 8x8</li>"), std::string::npos);
  EXPECT_NE(page.find("<li><strong>aa</strong>: 0 and 2</li>"), std::string::npos);
}

TEST(SweepPage, TableHasARowPerPointAndTheVaryingInputsAsColumns) {
  const std::vector<json> r = records();
  const std::string page = sweep_page(r, "small.json", "0.1.0");
  const std::size_t body = page.find("<tbody>", page.find("id=\"runs-table\""));
  ASSERT_NE(body, std::string::npos);
  EXPECT_EQ(count_of(page.substr(body, page.find("</tbody>", body) - body), "<tr "), 24);
  EXPECT_NE(page.find("<th data-key=\"scene\" data-type=\"text\" class=\"text\">scene</th><th data-key=\"cells\" "
                      "data-type=\"number\">cells</th><th data-key=\"mode\""),
            std::string::npos);
  EXPECT_EQ(page.find("data-key=\"profile\""), std::string::npos) << "profile does not vary";
  // The last point: 8x8 against 2x2 in dot mode at --aa 2, a speed-up of 8000/1200.
  EXPECT_NE(page.find("<td data-value=\"64\">8x8</td><td class=\"text\">dot</td><td>2</td><td>1</td>"
                      "<td data-value=\"3600\" title=\"3,600 cycles\">3.6000</td>"),
            std::string::npos);
  EXPECT_NE(page.find(fmt::format("<td data-value=\"{}\">6.667</td>", r.back().at("speedup").get<double>())),
            std::string::npos);
  EXPECT_NE(page.find("<td data-value=\"1234567\">1,234,567</td>"), std::string::npos);
}

TEST(SweepPage, SelfContainedAndTheSameBytesFromTheSameRecords) {
  const std::string page = sweep_page(records(), "small.json", "0.1.0");
  EXPECT_EQ(page, sweep_page(records(), "small.json", "0.1.0"));
  EXPECT_EQ(page.find("http:"), std::string::npos);
  EXPECT_EQ(page.find("https:"), std::string::npos);
  EXPECT_EQ(page.find(" src="), std::string::npos);
  EXPECT_EQ(page.find("<link"), std::string::npos);
  EXPECT_NE(page.find("Written by capsim 0.1.0"), std::string::npos);
}

TEST(SweepPage, AnEmptySweepSaysSo) {
  const std::string page = sweep_page({}, "none.json", "0.1.0");
  EXPECT_NE(page.find("<strong id=\"point-count\">0 points</strong>"), std::string::npos);
  EXPECT_NE(page.find("<p>The sweep has no points.</p>"), std::string::npos);
}

}  // namespace
}  // namespace capsim::sim
