#include "paper/modes/modes_page.h"

#include "report/html_assets.h"
#include "report/page_data.h"
#include "report/svg_plot.h"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace capsim::sim {

namespace {

// Each distinct value of a run's field, in the order of first appearance.
template <typename T, typename Field>
std::vector<T> distinct(const ModesBench& b, Field field) {
  std::vector<T> out;
  for (const ModeRun& r : b.runs)
    if (std::find(out.begin(), out.end(), field(r)) == out.end()) out.push_back(field(r));
  return out;
}

std::string joined(const std::vector<std::string>& items) {
  std::string s;
  for (std::size_t i = 0; i < items.size(); ++i)
    s += (i == 0 ? "" : i + 1 == items.size() ? " and " : ", ") + items[i];
  return s;
}

std::string moved_table(const std::vector<MovedFigure>& moved) {
  std::string rows;
  for (const MovedFigure& m : moved)
    rows += fmt::format("<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>\n", html_escape(m.run),
                        html_escape(m.metric), html_escape(m.old_value), html_escape(m.new_value),
                        m.ratio > 0 ? fmt::format("{:.6f}", m.ratio) : std::string("-"));
  return "<div class=\"table-box\"><table id=\"moved-table\" class=\"moved\">\n<thead><tr><th>run</th>"
         "<th>metric</th><th>old</th><th>new</th><th>new/old</th></tr></thead>\n<tbody>\n" +
         rows + "</tbody>\n</table></div>\n";
}

// What the page says about the baseline: none, matched, moved, or rewritten.
std::string baseline_text(const ModesBench& b, const BaselineOutcome& o) {
  const std::size_t runs = b.runs.size();
  const std::string path = "<code>" + html_escape(o.path) + "</code>";
  const std::string count = fmt::format("{} figure{}", o.moved.size(), o.moved.size() == 1 ? "" : "s");
  if (!o.rewritten && !o.existed)
    return fmt::format("<p id=\"baseline\" class=\"baseline none\">No baseline for {}x{}: not compared.</p>\n",
                       b.options.width, b.options.height);
  if (o.rewritten) {
    if (!o.existed)
      return fmt::format("<p id=\"baseline\" class=\"baseline rewritten\">The baseline {} was written from this run "
                         "({} runs); there was none to compare with.</p>\n",
                         path, runs);
    if (!o.not_comparable.empty())
      return fmt::format("<p id=\"baseline\" class=\"baseline rewritten\">The baseline {} was rewritten from this "
                         "run (--update); the old one was not comparable: {}.</p>\n",
                         path, html_escape(o.not_comparable));
    if (o.moved.empty())
      return fmt::format("<p id=\"baseline\" class=\"baseline rewritten\">The baseline {} was rewritten from this "
                         "run (--update); nothing moved against the old one.</p>\n",
                         path);
    return fmt::format("<p id=\"baseline\" class=\"baseline rewritten\">The baseline {} was rewritten from this run "
                       "(--update); {} moved against the old one:</p>\n{}",
                       path, count, moved_table(o.moved));
  }
  if (!o.not_comparable.empty())
    return fmt::format("<p id=\"baseline\" class=\"baseline moved\">Not comparable with the baseline {}: {}.</p>\n",
                       path, html_escape(o.not_comparable));
  if (o.moved.empty())
    return fmt::format("<p id=\"baseline\" class=\"baseline matched\">Matched the baseline {}: all {} runs "
                       "identical, to the cycle.</p>\n",
                       path, runs);
  return fmt::format("<p id=\"baseline\" class=\"baseline moved\">Differs from the baseline {}: {} moved, old "
                     "beside new with their ratio. If the change is intended, rerun with --update --baseline "
                     "naming it and commit the baseline with it, saying why.</p>\n{}",
                     path, count, moved_table(o.moved));
}

std::string header_section(const ModesBench& b, const nlohmann::json& summary, const BaselineOutcome& o) {
  std::vector<std::string> models = distinct<std::string>(b, [](const ModeRun& r) { return r.model; });
  std::vector<std::string> grids, aa;
  const std::vector<std::string> schemes = distinct<std::string>(b, [](const ModeRun& r) { return r.scheme(); });
  for (const CellGrid& g : distinct<CellGrid>(b, [](const ModeRun& r) { return r.cells; })) grids.push_back(to_string(g));
  for (int d : distinct<int>(b, [](const ModeRun& r) { return r.aa_depth; }))
    aa.push_back(d == 0 ? std::string("plain") : fmt::format("antialiased (--aa {})", d));
  return fmt::format(
      "<header>\n<h1>CAP pixel modes compared</h1>\n"
      "<p class=\"lead\"><strong id=\"screen-size\">{}</strong> pixels, profile <strong>{}</strong>, "
      "<strong id=\"run-count\">{} runs</strong>: {} shared by {} on {} cells, {}.</p>\n{}"
      "<nav><a href=\"#reading\">Reading the page</a> <a href=\"#plots\">Plots</a> <a href=\"#runs\">Every run</a>"
      "</nav>\n</header>\n",
      summary.at("size").get<std::string>(), html_escape(summary.at("profile").get<std::string>()), b.runs.size(),
      html_escape(joined(models)), joined(schemes), joined(grids), joined(aa), baseline_text(b, o));
}

std::string reading_section(const ModesBench& b) {
  const CellGrid base = modes_bench_grids()[0];
  return fmt::format(
      "<section id=\"reading\">\n<h2>Reading the page</h2>\n"
      "<p>Each run traces one frame of a model on the simulated CAP, as the <code>capsim simulate</code> command "
      "shown when the pointer rests on its row of the table does. The pixel mode shares the screen among the "
      "cells: in block mode each cell traces one rectangle, in line mode every so many rows, in dot mode one pixel "
      "of every square the size of the cell grid. Balanced on demand (<code>demand:64</code>, LINKS-1's scheme), "
      "the host hands out tiles of 8 x 8 pixels over the command bus to the cells that ask, so a cell that "
      "finishes early takes more. Stealing (<code>steal:16</code>) starts from dot mode's windows cut into "
      "chunks of 16 pixels; a cell that has traced its own takes half of a neighbour's unstarted chunks over the "
      "links and sends the pixels back. Each cell sends its &ldquo;done&rdquo; to the host over the "
      "command bus. An antialiased run adds the exchange of corner samples over the neighbour links.</p>\n"
      "<p><strong>d = (Max &minus; Min) / Max</strong> is the paper's measure of how evenly a mode spreads the "
      "work (Table 4-4): Max is the cycle the slowest cell's &ldquo;done&rdquo; reached the host, which is the "
      "frame time, and Min the fastest cell's. At d = 0 % every cell finishes together; at d = 20 % the first "
      "cell to finish stands idle for the last fifth of the frame. Lower is better.</p>\n"
      "<p><strong>Speed-up</strong> is the frame time of the same model, scheme and antialiasing on {} cells ({} "
      "cells) over this run's, the measure Graph 4-3 plots against the number of cells. Perfect scaling would "
      "give the ratio of the cell counts: 2 on 32 cells, 4 on 64, 16 on 256. A large d and the time every cell "
      "spends on the broadcasts and the bus keep it lower. The plots' axes are logarithmic, so perfect scaling "
      "is a straight line.</p>\n"
      "<p>Simulated cycles do not depend on the host or its threads: every figure here is exact, and the "
      "seconds are cycles at the profile's clock (hover over a time in the table for its cycles). This run was "
      "at {}x{} pixels.</p>\n</section>\n",
      to_string(base), base.cell_count(), b.options.width, b.options.height);
}

// The axes' ranges, shared by every model's plots so that they compare at a
// glance: decades around every d, octaves around every speed-up.
struct PlotRanges {
  double d_lo = 0.1, d_hi = 100, speed_lo = 0.5, speed_hi = 32;
};

// A run's d on a logarithmic axis: 0 is drawn at 0.01 %.
double plotted_d(const ModeRun& r) { return std::max(r.figures.spread.deviation_percent, 0.01); }

PlotRanges plot_ranges(const ModesBench& b) {
  if (b.runs.empty()) return {};
  double d_lo = plotted_d(b.runs[0]), d_hi = d_lo, s_lo = b.runs[0].speedup, s_hi = s_lo;
  for (const ModeRun& r : b.runs) {
    d_lo = std::min(d_lo, plotted_d(r));
    d_hi = std::max(d_hi, plotted_d(r));
    s_lo = std::min(s_lo, r.speedup);
    s_hi = std::max(s_hi, r.speedup);
  }
  PlotRanges p;
  p.d_lo = std::pow(10.0, std::floor(std::log10(d_lo)));
  p.d_hi = std::pow(10.0, std::ceil(std::log10(d_hi)));
  if (p.d_hi <= p.d_lo) p.d_hi = p.d_lo * 10;
  p.speed_lo = std::pow(2.0, std::floor(std::log2(std::max(s_lo, 1.0 / 64))));
  p.speed_hi = std::pow(2.0, std::ceil(std::log2(std::max(s_hi, 1.0))));
  if (p.speed_hi <= p.speed_lo) p.speed_hi = p.speed_lo * 2;
  return p;
}

PlotAxes cells_axes(const ModesBench& b, std::string title, std::string y_label) {
  PlotAxes a;
  a.title = std::move(title);
  a.x_label = "cells";
  a.y_label = std::move(y_label);
  a.log_x = a.log_y = true;
  double lo = 0, hi = 0;
  for (const CellGrid& g : distinct<CellGrid>(b, [](const ModeRun& r) { return r.cells; })) {
    const double n = g.cell_count();
    a.x_ticks.push_back(n);
    lo = lo == 0 ? n : std::min(lo, n);
    hi = std::max(hi, n);
  }
  std::sort(a.x_ticks.begin(), a.x_ticks.end());
  a.x_min = std::max(lo, 1.0) * 0.75;
  a.x_max = std::max(hi, 1.0) * 1.25;
  return a;
}

// One model: d and the speed-up against the cell count, a colour per scheme,
// plain frames solid with round markers, antialiased dashed with square ones.
std::string model_figure(const ModesBench& b, const std::string& model, const PlotRanges& p) {
  std::vector<PlotSeries> d_series, speed_series;
  const std::vector<int> depths = distinct<int>(b, [](const ModeRun& r) { return r.aa_depth; });
  const std::vector<std::string> schemes = distinct<std::string>(b, [](const ModeRun& r) { return r.scheme(); });
  for (int aa : depths)
    for (std::size_t k = 0; k < schemes.size(); ++k) {
      PlotSeries d = plot_series(aa == 0 ? schemes[k] : fmt::format("{}, --aa {}", schemes[k], aa),
                                 series_colour(static_cast<int>(k)), aa == 0 ? "" : "6 4", aa != 0);
      PlotSeries speed = d;
      for (const ModeRun& r : b.runs) {
        if (r.model != model || r.scheme() != schemes[k] || r.aa_depth != aa) continue;
        d.points.push_back({static_cast<double>(r.cells.cell_count()), plotted_d(r)});
        speed.points.push_back({static_cast<double>(r.cells.cell_count()), r.speedup});
      }
      if (d.points.empty()) continue;
      const auto by_x = [](const auto& u, const auto& v) { return u.first < v.first; };
      std::sort(d.points.begin(), d.points.end(), by_x);
      std::sort(speed.points.begin(), speed.points.end(), by_x);
      d_series.push_back(std::move(d));
      speed_series.push_back(std::move(speed));
    }
  PlotAxes d = cells_axes(b, fmt::format("{}: d = (Max - Min) / Max", model), "d (%)");
  d.y_min = p.d_lo;
  d.y_max = p.d_hi;
  for (double y = d.y_min; y <= d.y_max * 1.0001; y *= 10) d.y_ticks.push_back(y);
  PlotAxes s = cells_axes(b, fmt::format("{}: speed-up against {} cells", model, to_string(modes_bench_grids()[0])),
                          "speed-up");
  s.y_min = p.speed_lo;
  s.y_max = p.speed_hi;
  for (double y = s.y_min; y <= s.y_max * 1.0001; y *= 2) s.y_ticks.push_back(y);
  const double w = 560, h = 360;
  return fmt::format(
      "<figure class=\"model-plot\" data-model=\"{}\">\n{}<figcaption>{}: d (left) and speed-up (right) against the "
      "number of cells; a colour per scheme, plain frames solid, antialiased dashed with square markers.</figcaption>"
      "\n</figure>\n",
      html_escape(model),
      inline_svg(svg_document(2 * w, h, plot_panel_svg(d, d_series, 0, 0, w, h) +
                                            plot_panel_svg(s, speed_series, w, 0, w, h))),
      html_escape(model));
}

std::string plots_section(const ModesBench& b) {
  const PlotRanges p = plot_ranges(b);
  std::string figures;
  for (const std::string& model : distinct<std::string>(b, [](const ModeRun& r) { return r.model; }))
    figures += model_figure(b, model, p);
  return fmt::format(
      "<section id=\"plots\" class=\"plots\">\n<h2>Plots</h2>\n"
      "<figure class=\"overview-plot\">\n{}<figcaption>Every model's plain frames at once: a colour per model, "
      "solid for block, dashed for line, dotted for dot mode, dash-dotted for demand, finely dotted for steal (the same plot as --plot).</figcaption>\n</figure>\n"
      "<h3>Model by model</h3>\n<p>The same axes for every model, so that they compare at a glance. A d of 0 is "
      "drawn at 0.01 %.</p>\n{}</section>\n",
      inline_svg(modes_bench_svg(b)), figures);
}

// A number exactly as a sort key: the shortest text that reads back the same.
std::string exact(double v) { return fmt::format("{}", v); }

std::string seconds_cell(const RunFigures& f, Cycles c) {
  return fmt::format("<td data-value=\"{}\" title=\"{} cycles\">{:.4f}</td>", c.count(), grouped(c.count()),
                     f.seconds(c));
}

std::string runs_section(const ModesBench& b) {
  struct Column {
    const char* key;
    const char* heading;
    bool number;
  };
  constexpr Column kColumns[] = {
      {"model", "model", false},          {"scheme", "scheme", false},         {"cells", "cells", true},
      {"aa", "aa", true},                 {"frame", "frame s", true},      {"max", "Max s", true},
      {"min", "Min s", true},             {"d", "d %", true},              {"speedup", "speed-up", true},
      {"bus_bytes", "bus bytes", true},   {"link_messages", "link messages", true},
      {"link_bytes", "link bytes", true},
  };
  std::string head;
  for (const Column& c : kColumns)
    head += fmt::format("<th data-key=\"{}\" data-type=\"{}\"{}>{}</th>", c.key, c.number ? "number" : "text",
                        c.number ? "" : " class=\"text\"", c.heading);
  std::string body;
  for (const ModeRun& r : b.runs) {
    const RunFigures& f = r.figures;
    body += fmt::format(
        "<tr title=\"{}\"><td class=\"text\">{}</td><td class=\"text\">{}</td><td data-value=\"{}\">{}</td>"
        "<td>{}</td>{}{}{}<td data-value=\"{}\">{:.2f}</td><td data-value=\"{}\">{:.3f}</td>"
        "<td data-value=\"{}\">{}</td><td data-value=\"{}\">{}</td><td data-value=\"{}\">{}</td></tr>\n",
        html_escape(f.command), html_escape(r.model), r.scheme(), r.cells.cell_count(), to_string(r.cells),
        r.aa_depth, seconds_cell(f, f.frame), seconds_cell(f, f.spread.max_finish),
        seconds_cell(f, f.spread.min_finish), exact(f.spread.deviation_percent), f.spread.deviation_percent,
        exact(r.speedup), r.speedup, f.bus.bytes, grouped(f.bus.bytes), f.links.messages,
        grouped(f.links.messages), f.links.bytes, grouped(f.links.bytes));
  }
  return fmt::format(
      "<section id=\"runs\">\n<h2>Every run</h2>\n<p>One row per run, in the benchmark's order (model, then "
      "antialiasing, then scheme, then cells). Rest the pointer on a row for the <code>capsim simulate</code> "
      "command that repeats it, on a time for its cycles. With JavaScript, a click on a heading sorts by that "
      "column and a second click reverses it. Bus bytes are everything on the command bus: the broadcasts, "
      "every cell's &ldquo;done&rdquo; and, on demand, the requests and grants of tiles; the links carry the "
      "corner exchange of antialiased static and steal runs, and the requests, work and pixels of steal runs.</p>\n"
      "<div class=\"table-box\"><table id=\"runs-table\" class=\"numbers\">\n<caption>{} runs; seconds "
      "simulated</caption>\n<thead><tr>{}</tr></thead>\n<tbody>\n{}</tbody>\n</table></div>\n</section>\n",
      b.runs.size(), head, body);
}

}  // namespace

std::string modes_page(const ModesBench& b, const BaselineOutcome& baseline, const std::string& version) {
  const nlohmann::json summary = modes_bench_json(b);
  const std::string body =
      header_section(b, summary, baseline) + "<main>\n" + reading_section(b) + plots_section(b) + runs_section(b) +
      fmt::format("</main>\n<footer>Written by capsim {} (<code>capsim bench modes --html</code>); "
                  "<code>--json</code> writes the same figures as JSON.</footer>\n",
                  html_escape(version));
  const HtmlAssets& assets = html_assets();
  const std::string title = html_escape(fmt::format("capsim bench modes: {}", summary.at("size").get<std::string>()));
  const std::string style = std::string(assets.style) + std::string(assets.modes_style);
  return fill_template(assets.page, {{"@TITLE@", title},
                                     {"@STYLE@", style},
                                     {"@BODY@", body},
                                     {"@SCRIPT@", assets.modes_script}});
}

}  // namespace capsim::sim
