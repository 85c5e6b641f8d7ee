// The mode-comparison page of `capsim bench modes --html` (modes_page.h), read
// back as a file from the whole benchmark at 16x16 pixels: one document with
// no external reference; every run's figures and command in a plain-HTML
// table; the plots inline SVG; the baseline's verdict in each of its forms;
// the same bytes for the same figures, whichever the host threads.

#include "paper/modes/modes_bench.h"
#include "paper/modes/modes_page.h"

#include <fmt/core.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

namespace capsim::sim {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// The text between the first `open` at or after `from` and the next `close`.
std::string between(const std::string& text, const std::string& open, const std::string& close,
                    std::size_t from = 0) {
  const std::size_t begin = text.find(open, from);
  if (begin == std::string::npos) return "";
  const std::size_t start = begin + open.size();
  return text.substr(start, text.find(close, start) - start);
}

// &, <, >, " and ' as the page escapes them in an attribute.
std::string attribute(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '"') out += "&quot;";
    else if (c == '\'') out += "&#39;";
    else out += c;
  }
  return out;
}

ModesBench small_bench(int threads) {
  ModesBenchOptions o;
  o.width = o.height = 16;
  o.threads = threads;
  o.scenes_dir = std::string(CAPSIM_SOURCE_DIR) + "/scenes";
  return run_modes_bench(o);
}

class ModesPage : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { bench_ = new ModesBench(small_bench(1)); }
  static void TearDownTestSuite() {
    delete bench_;
    bench_ = nullptr;
  }
  static const ModesBench& bench() { return *bench_; }
  static BaselineOutcome matched() { return {"bench/baselines/modes-16x16.json", false, true, "", {}}; }

 private:
  static ModesBench* bench_;
};

ModesBench* ModesPage::bench_ = nullptr;

TEST_F(ModesPage, IsOneDocumentWithNoExternalReference) {
  const std::string page = modes_page(bench(), matched(), "0.1.0");
  EXPECT_TRUE(page.starts_with("<!DOCTYPE html>\n"));
  EXPECT_TRUE(page.ends_with("</html>\n"));
  const std::string text = lower(page);
  for (const char* outside : {"http:", "https:", "ftp:", "file:", "<link", "<iframe", "<object", "<embed", "<base",
                              "@import", "srcset", "xlink:href", "<form", "<img", "url(", "src=\"//", "href=\"//"})
    EXPECT_EQ(text.find(outside), std::string::npos) << outside;
  for (std::size_t at = text.find("src="); at != std::string::npos; at = text.find("src=", at + 1))
    ADD_FAILURE() << "a src: " << text.substr(at, 40);
  for (std::size_t at = text.find("href="); at != std::string::npos; at = text.find("href=", at + 1))
    EXPECT_EQ(text.compare(at, 7, "href=\"#"), 0) << text.substr(at, 40);
  // The page's own script and nothing else runs.
  EXPECT_EQ(count(text, "<script"), 1u);
  EXPECT_NE(page.find("getElementById('runs-table')"), std::string::npos);
}

TEST_F(ModesPage, PlotsAreInlineSvgOnePerModelAfterTheOverview) {
  const std::string page = modes_page(bench(), matched(), "0.1.0");
  const std::string plots = between(page, "<section id=\"plots\"", "</section>");
  // The overview (modes_bench_svg) and one figure per model, all inside the page.
  EXPECT_EQ(count(plots, "<svg "), 1u + modes_bench_models().size());
  EXPECT_EQ(count(plots, "</svg>"), 1u + modes_bench_models().size());
  EXPECT_EQ(count(page, "<svg "), count(plots, "<svg "));
  for (const char* model : {"balls", "chess", "piston", "cad", "disb/f00000"}) {
    const std::string figure = between(plots, fmt::format("<figure class=\"model-plot\" data-model=\"{}\">", model),
                                       "</figure>");
    ASSERT_FALSE(figure.empty()) << model;
    EXPECT_NE(figure.find(fmt::format(">{}: d = (Max - Min) / Max</text>", model)), std::string::npos) << model;
    EXPECT_NE(figure.find(fmt::format(">{}: speed-up against 4x4 cells</text>", model)), std::string::npos) << model;
    // Three modes, demand and steal, plain and antialiased, in both panels' legends.
    for (const char* series : {">block</text>", ">line</text>", ">dot</text>", ">demand:64</text>",
                               ">steal:16</text>", ">block, --aa 2</text>", ">line, --aa 2</text>",
                               ">dot, --aa 2</text>", ">demand:64, --aa 2</text>", ">steal:16, --aa 2</text>"})
      EXPECT_EQ(count(figure, series), 2u) << model << " " << series;
    // Four cell counts per series: 10 series x 2 panels, 4 points each; the
    // antialiased ones with square markers.
    EXPECT_EQ(count(figure, "<circle "), 5u * 2 * 4) << model;
    EXPECT_EQ(count(figure, "width=\"6\" height=\"6\""), 5u * 2 * 4) << model;
  }
}

TEST_F(ModesPage, HoldsEveryRunsFiguresAndCommandInAPlainTable) {
  const std::string page = modes_page(bench(), matched(), "0.1.0");
  const std::string table = between(page, "<table id=\"runs-table\"", "</table>");
  ASSERT_FALSE(table.empty());
  for (const char* heading : {">model</th>", ">scheme</th>", ">cells</th>", ">aa</th>", ">frame s</th>", ">Max s</th>",
                              ">Min s</th>", ">d %</th>", ">speed-up</th>", ">bus bytes</th>",
                              ">link messages</th>", ">link bytes</th>"})
    EXPECT_NE(table.find(heading), std::string::npos) << heading;
  const std::string body = between(table, "<tbody>", "</tbody>");
  ASSERT_EQ(count(body, "<tr "), bench().runs.size());
  ASSERT_EQ(bench().runs.size(), 200u);
  std::size_t at = 0;
  for (const ModeRun& r : bench().runs) {
    const RunFigures& f = r.figures;
    const std::string row = between(body, "<tr ", "</tr>", at);
    at = body.find("</tr>", body.find("<tr ", at)) + 5;
    const std::string name = fmt::format("{} {} {} aa{}", r.model, r.scheme(), to_string(r.cells), r.aa_depth);
    EXPECT_TRUE(row.starts_with("title=\"" + attribute(f.command) + "\"")) << name << ": " << row;
    EXPECT_NE(f.command.find("capsim simulate"), std::string::npos);
    EXPECT_NE(row.find(fmt::format("<td class=\"text\">{}</td><td class=\"text\">{}</td>", r.model, r.scheme())),
              std::string::npos)
        << name;
    EXPECT_NE(row.find(fmt::format("<td data-value=\"{}\">{}</td><td>{}</td>", r.cells.cell_count(),
                                   to_string(r.cells), r.aa_depth)),
              std::string::npos)
        << name;
    for (const Cycles c : {f.frame, f.spread.max_finish, f.spread.min_finish})
      EXPECT_NE(row.find(fmt::format("<td data-value=\"{}\"", c.count())), std::string::npos) << name;
    EXPECT_NE(row.find(fmt::format(">{:.4f}</td>", f.frame_seconds())), std::string::npos) << name;
    EXPECT_NE(row.find(fmt::format("<td data-value=\"{}\">{:.2f}</td>", f.spread.deviation_percent,
                                   f.spread.deviation_percent)),
              std::string::npos)
        << name;
    EXPECT_NE(row.find(fmt::format("<td data-value=\"{}\">{:.3f}</td>", r.speedup, r.speedup)), std::string::npos)
        << name;
    for (const std::uint64_t n : {f.bus.bytes, f.links.messages, f.links.bytes})
      EXPECT_NE(row.find(fmt::format("<td data-value=\"{}\">", n)), std::string::npos) << name;
    // Antialiased static and steal runs exchange corners over the links;
    // plain static ones do not, nor does demand, whose tiles trace their own
    // corners; steal runs send requests for work (and on 16x16 pixels,
    // whatever the grid, some are refused at least).
    EXPECT_EQ(f.links.messages > 0, (r.aa_depth > 0 && !r.balance.on_demand()) || r.balance.stealing()) << name;
    EXPECT_EQ(f.command.find("--balance " + r.scheme()) != std::string::npos, !r.balance.is_static()) << name;
  }
}

TEST_F(ModesPage, HeaderGivesTheScreenProfileRunsAndAMatchedBaseline) {
  const std::string page = modes_page(bench(), matched(), "0.1.0");
  const std::string header = between(page, "<header>", "</header>");
  EXPECT_NE(header.find("<strong id=\"screen-size\">16x16</strong> pixels, profile <strong>cap</strong>"),
            std::string::npos)
      << header;
  EXPECT_NE(header.find("<strong id=\"run-count\">200 runs</strong>"), std::string::npos) << header;
  EXPECT_NE(header.find("<p id=\"baseline\" class=\"baseline matched\">Matched the baseline "
                        "<code>bench/baselines/modes-16x16.json</code>: all 200 runs identical"),
            std::string::npos)
      << header;
  EXPECT_EQ(page.find("moved-table"), std::string::npos);
  // The note on reading d and the speed-up, as the paper uses them.
  const std::string reading = between(page, "<section id=\"reading\">", "</section>");
  EXPECT_NE(reading.find("Table 4-4"), std::string::npos);
  EXPECT_NE(reading.find("Graph 4-3"), std::string::npos);
}

TEST_F(ModesPage, ListsTheMovedFiguresOldNewAndRatio) {
  BaselineOutcome o = matched();
  o.moved = {{"balls dot 8x8 aa0", "frame_cycles", "200", "100", 0.5},
             {"chess <line> 4x4 aa2", "(run)", "present", "absent", 0}};
  const std::string page = modes_page(bench(), o, "0.1.0");
  const std::string header = between(page, "<header>", "</header>");
  EXPECT_NE(header.find("class=\"baseline moved\">Differs from the baseline "
                        "<code>bench/baselines/modes-16x16.json</code>: 2 figures moved"),
            std::string::npos)
      << header;
  const std::string moved = between(header, "<table id=\"moved-table\"", "</table>");
  EXPECT_NE(moved.find("<tr><td>balls dot 8x8 aa0</td><td>frame_cycles</td><td>200</td><td>100</td>"
                       "<td>0.500000</td></tr>"),
            std::string::npos)
      << moved;
  EXPECT_NE(moved.find("<tr><td>chess &lt;line&gt; 4x4 aa2</td><td>(run)</td><td>present</td><td>absent</td>"
                       "<td>-</td></tr>"),
            std::string::npos)
      << moved;

  // --update: rewritten, and what moved against the old one.
  o.rewritten = true;
  const std::string updated = between(modes_page(bench(), o, "0.1.0"), "<header>", "</header>");
  EXPECT_NE(updated.find("was rewritten from this run (--update); 2 figures moved against the old one:"),
            std::string::npos)
      << updated;
  EXPECT_NE(updated.find("<td>0.500000</td>"), std::string::npos);
  o.moved.clear();
  EXPECT_NE(modes_page(bench(), o, "0.1.0").find("nothing moved against the old one"), std::string::npos);
  o.existed = false;
  EXPECT_NE(modes_page(bench(), o, "0.1.0").find("was written from this run (200 runs)"), std::string::npos);
  // No baseline for the screen: the run stands alone.
  o = BaselineOutcome{"", false, false, "", {}};
  EXPECT_NE(between(modes_page(bench(), o, "0.1.0"), "<header>", "</header>")
                .find("<p id=\"baseline\" class=\"baseline none\">No baseline for 16x16: not compared.</p>"),
            std::string::npos);
  o = matched();
  o.not_comparable = "the baseline's size is \"48x48\" where this run's is \"16x16\"";
  EXPECT_NE(modes_page(bench(), o, "0.1.0")
                .find("Not comparable with the baseline <code>bench/baselines/modes-16x16.json</code>: the "
                      "baseline&#39;s size is &quot;48x48&quot; where this run&#39;s is &quot;16x16&quot;."),
            std::string::npos);
}

TEST_F(ModesPage, IsTheSameBytesForTheSameFiguresOnAnyThreadCount) {
  const std::string page = modes_page(bench(), matched(), "0.1.0");
  EXPECT_EQ(page, modes_page(bench(), matched(), "0.1.0"));
  EXPECT_EQ(page, modes_page(small_bench(2), matched(), "0.1.0"));
}

}  // namespace
}  // namespace capsim::sim
