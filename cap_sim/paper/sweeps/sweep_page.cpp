#include "paper/sweeps/sweep_page.h"

#include "paper/sweeps/sweep_records.h"
#include "report/html_assets.h"
#include "report/page_data.h"
#include "report/svg_plot.h"

#include <fmt/core.h>

#include <algorithm>
#include <filesystem>

namespace capsim::sim {

namespace {

using nlohmann::json;

// A scene as the page names it: its file's name; a sequence by its first and
// last files; an animated file with its frames. The table's row title gives
// the paths as the sweep file does.
std::string scene_name(const json& scene) {
  const auto file = [](const json& path) {
    return std::filesystem::path(path.get<std::string>()).filename().string();
  };
  if (scene.is_string()) return file(scene);
  if (scene.is_array())
    return scene.size() == 1 ? file(scene[0])
                             : fmt::format("{} to {} ({} files)", file(scene.front()), file(scene.back()),
                                           scene.size());
  return fmt::format("{}, {} frames", file(scene.at("scene")), scene.at("frames").get<int>());
}

// An input's value as the page shows it.
std::string shown(const std::string& key, const json& v) {
  if (key == "scene") return scene_name(v);
  return v.is_string() ? v.get<std::string>() : v.dump();
}

int cell_count(const json& record) {
  const std::string cells = record.at("cells").get<std::string>();
  return std::stoi(cells) * std::stoi(cells.substr(cells.find('x') + 1));
}

// Each distinct value of an input, in the order of first appearance.
std::vector<json> distinct(const std::vector<json>& records, const std::string& key) {
  std::vector<json> out;
  for (const json& r : records)
    if (std::find(out.begin(), out.end(), r.at(key)) == out.end()) out.push_back(r.at(key));
  return out;
}

// The inputs that take more than one value in the sweep, in the CSV's order,
// and the others.
struct Axes {
  std::vector<std::string> varying, fixed;
};

Axes axes_of(const std::vector<json>& records) {
  Axes a;
  for (const std::string& key : sweep_input_keys())
    (distinct(records, key).size() > 1 ? a.varying : a.fixed).push_back(key);
  return a;
}

// "mode dot, aa 2": the values of `keys` in a record.
std::string described(const json& record, const std::vector<std::string>& keys) {
  std::string s;
  for (const std::string& key : keys) s += fmt::format("{}{} {}", s.empty() ? "" : ", ", key, shown(key, record.at(key)));
  return s;
}

std::string header_section(const std::vector<json>& records, const std::string& sweep_file, const Axes& axes) {
  std::string varying;
  for (const std::string& key : axes.varying) {
    std::vector<std::string> values;
    for (const json& v : distinct(records, key)) values.push_back(html_escape(shown(key, v)));
    std::string list;
    for (std::size_t i = 0; i < values.size(); ++i)
      list += (i == 0 ? "" : i + 1 == values.size() ? " and " : ", ") + values[i];
    varying += fmt::format("<li><strong>{}</strong>: {}</li>\n", key, list);
  }
  const std::string fixed = records.empty() ? std::string() : html_escape(described(records[0], axes.fixed));
  return fmt::format(
      "<header>\n<h1>Sweep {}</h1>\n<p class=\"lead\"><strong id=\"point-count\">{} point{}</strong>{}</p>\n"
      "{}<nav><a href=\"#reading\">Reading the page</a> <a href=\"#plots\">Plots</a> <a href=\"#runs\">Every point"
      "</a></nav>\n</header>\n",
      html_escape(sweep_file), records.size(), records.size() == 1 ? "" : "s",
      fixed.empty() ? std::string() : "; the same for every point: " + fixed + ".",
      varying.empty() ? std::string() : "<ul id=\"axes\">\n" + varying + "</ul>\n");
}

std::string reading_section() {
  return "<section id=\"reading\">\n<h2>Reading the page</h2>\n"
         "<p>Each point is one run of <code>capsim simulate</code> with the inputs in its row of the table; rest "
         "the pointer on a row for all of them. The time is the cycle the last cell's &ldquo;done&rdquo; reached "
         "the host, for a sequence the whole sequence's, in seconds at the profile's clock (hover over a time in "
         "the table for its cycles).</p>\n"
         "<p><strong>d = (Max &minus; Min) / Max</strong> is the paper's measure of how evenly the work is spread "
         "(Table 4-4): Max and Min are the slowest and the fastest cell's finish. Lower is better; a d of 0 is "
         "drawn at 0.01 %.</p>\n"
         "<p><strong>Speed-up</strong> is the time of the point with the fewest cells among those equal in every "
         "other input over this point's, the measure Graph 4-3 plots against the number of cells. The axes are "
         "logarithmic, so perfect scaling is a straight line.</p>\n"
         "<p>Simulated cycles do not depend on the host, its threads or the MPI ranks that ran the sweep: every "
         "figure here is exact.</p>\n</section>\n";
}

// d on a logarithmic axis: 0 is drawn at 0.01 %.
double plotted_d(const json& r) { return std::max(r.at("deviation_percent").get<double>(), 0.01); }

struct Range {
  double lo = 0, hi = 0;
  void add(double v) {
    lo = lo == 0 ? v : std::min(lo, v);
    hi = std::max(hi, v);
  }
};

PlotAxes cells_axes(const std::vector<json>& records, std::string title, std::string y_label, const Range& y,
                    double base) {
  PlotAxes a;
  a.title = std::move(title);
  a.x_label = "cells";
  a.y_label = std::move(y_label);
  a.log_x = a.log_y = true;
  Range x;
  for (const json& r : records) {
    const double n = cell_count(r);
    if (std::find(a.x_ticks.begin(), a.x_ticks.end(), n) == a.x_ticks.end()) a.x_ticks.push_back(n);
    x.add(n);
  }
  std::sort(a.x_ticks.begin(), a.x_ticks.end());
  a.x_min = x.lo * 0.75;
  a.x_max = x.hi * 1.25;
  const LogRange r = log_range(y.lo, y.hi, base);
  a.y_min = r.lo;
  a.y_max = r.hi;
  a.y_ticks = r.ticks;
  return a;
}

// One scene's plots: d, the time and the speed-up against the cells, a
// series per combination of the other varying axes (a colour each, dashed
// past the tenth).
std::string scene_figure(const std::vector<json>& records, const json& scene, const Axes& axes, const Range& d_range,
                         const Range& speed_range) {
  std::vector<std::string> others;
  for (const std::string& key : axes.varying)
    if (key != "scene" && key != "cells") others.push_back(key);
  std::vector<json> mine;
  for (const json& r : records)
    if (r.at("scene") == scene) mine.push_back(r);
  const std::string name = scene_name(scene);
  std::vector<std::string> labels;
  for (const json& r : mine)
    if (std::find(labels.begin(), labels.end(), described(r, others)) == labels.end())
      labels.push_back(described(r, others));
  std::vector<PlotSeries> d, time, speed;
  Range time_range;
  for (std::size_t k = 0; k < labels.size(); ++k) {
    const int i = static_cast<int>(k);
    PlotSeries s = plot_series(labels[k].empty() ? name : labels[k], series_colour(i), i < 10 ? "" : "6 4", i >= 10);
    PlotSeries t = s, v = s;
    for (const json& r : mine) {
      if (described(r, others) != labels[k]) continue;
      const double n = cell_count(r);
      s.points.push_back({n, plotted_d(r)});
      t.points.push_back({n, r.at("frame_seconds").get<double>()});
      v.points.push_back({n, r.at("speedup").get<double>()});
      time_range.add(r.at("frame_seconds").get<double>());
    }
    for (PlotSeries* p : {&s, &t, &v}) {
      std::stable_sort(p->points.begin(), p->points.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    }
    d.push_back(std::move(s));
    time.push_back(std::move(t));
    speed.push_back(std::move(v));
  }
  std::string per;
  for (const std::string& key : others) per += (per.empty() ? "; a series per " : ", ") + key;
  const double w = 480, h = 340;
  const std::string panels =
      plot_panel_svg(cells_axes(mine, name + ": d", "d (%)", d_range, 10), d, 0, 0, w, h) +
      plot_panel_svg(cells_axes(mine, name + ": time", "time (s)", time_range, 10), time, w, 0, w, h) +
      plot_panel_svg(cells_axes(mine, name + ": speed-up", "speed-up", speed_range, 2), speed, 2 * w, 0, w, h);
  return fmt::format(
      "<figure class=\"scene-plot\" data-scene=\"{}\" data-series=\"{}\">\n{}<figcaption>{}: d (left), time "
      "(middle) and speed-up (right) against the number of cells{}.</figcaption>\n</figure>\n",
      html_escape(name), labels.size(), inline_svg(svg_document(3 * w, h, panels)), html_escape(name), per);
}

std::string plots_section(const std::vector<json>& records, const Axes& axes) {
  Range d_range, speed_range;
  for (const json& r : records) {
    d_range.add(plotted_d(r));
    speed_range.add(r.at("speedup").get<double>());
  }
  std::string figures;
  for (const json& scene : distinct(records, "scene")) figures += scene_figure(records, scene, axes, d_range, speed_range);
  return fmt::format(
      "<section id=\"plots\" class=\"plots\">\n<h2>Plots</h2>\n<p>A figure per scene; d and the speed-up on the same "
      "axes in every figure, so that they compare at a glance.</p>\n{}</section>\n",
      records.empty() ? "<p>The sweep has no points.</p>\n" : figures);
}

// A number exactly as a sort key: the shortest text that reads back the same.
std::string exact(double v) { return fmt::format("{}", v); }

std::string seconds_cell(const json& r, const std::string& key) {
  const std::uint64_t cycles = r.at(key + "_cycles").get<std::uint64_t>();
  return fmt::format("<td data-value=\"{}\" title=\"{} cycles\">{:.4f}</td>", cycles, grouped(cycles),
                     r.at(key + "_seconds").get<double>());
}

std::string count_cell(const json& r, const std::string& key) {
  const std::uint64_t n = r.at(key).get<std::uint64_t>();
  return fmt::format("<td data-value=\"{}\">{}</td>", n, grouped(n));
}

std::string runs_section(const std::vector<json>& records, const Axes& axes) {
  std::vector<std::string> inputs = axes.varying;
  if (std::find(inputs.begin(), inputs.end(), "cells") == inputs.end()) inputs.push_back("cells");
  std::string head = "<th data-key=\"point\" data-type=\"number\">point</th>";
  for (const std::string& key : inputs) {
    const bool number = key == "cells" || key == "aa";
    head += fmt::format("<th data-key=\"{0}\" data-type=\"{1}\"{2}>{0}</th>", key, number ? "number" : "text",
                        number ? "" : " class=\"text\"");
  }
  for (const auto& [key, heading] : std::vector<std::pair<std::string, std::string>>{
           {"frames", "frames"}, {"frame", "time s"}, {"max", "Max s"}, {"min", "Min s"}, {"d", "d %"},
           {"speedup", "speed-up"}, {"bus_bytes", "bus bytes"}, {"link_messages", "link messages"},
           {"link_bytes", "link bytes"}})
    head += fmt::format("<th data-key=\"{}\" data-type=\"number\">{}</th>", key, heading);
  std::string body;
  for (std::size_t i = 0; i < records.size(); ++i) {
    const json& r = records[i];
    std::string row;
    for (const std::string& key : inputs) {
      if (key == "cells")
        row += fmt::format("<td data-value=\"{}\">{}</td>", cell_count(r), r.at(key).get<std::string>());
      else if (key == "aa")
        row += fmt::format("<td>{}</td>", r.at(key).get<int>());
      else
        row += fmt::format("<td class=\"text\">{}</td>", html_escape(shown(key, r.at(key))));
    }
    const double d = r.at("deviation_percent").get<double>(), speedup = r.at("speedup").get<double>();
    body += fmt::format(
        "<tr title=\"{}\"><td>{}</td>{}<td>{}</td>{}{}{}<td data-value=\"{}\">{:.2f}</td>"
        "<td data-value=\"{}\">{:.3f}</td>{}{}{}</tr>\n",
        html_escape(described(r, sweep_input_keys())), i + 1, row, r.at("frames").get<int>(), seconds_cell(r, "frame"),
        seconds_cell(r, "max"), seconds_cell(r, "min"), exact(d), d, exact(speedup), speedup,
        count_cell(r, "bus_bytes"), count_cell(r, "link_messages"), count_cell(r, "link_bytes"));
  }
  return fmt::format(
      "<section id=\"runs\">\n<h2>Every point</h2>\n<p>One row per point, in the sweep's order (the cells "
      "varying fastest), with the inputs the sweep varies. With JavaScript, a click on a heading sorts by that "
      "column and a second click reverses it.</p>\n"
      "<div class=\"table-box\"><table id=\"runs-table\" class=\"numbers\">\n<caption>{} points; seconds "
      "simulated</caption>\n<thead><tr>{}</tr></thead>\n<tbody>\n{}</tbody>\n</table></div>\n</section>\n",
      records.size(), head, body);
}

}  // namespace

std::string sweep_page(const std::vector<json>& records, const std::string& sweep_file, const std::string& version) {
  const Axes axes = axes_of(records);
  const std::string body =
      header_section(records, sweep_file, axes) + "<main>\n" + reading_section() + plots_section(records, axes) +
      runs_section(records, axes) +
      fmt::format("</main>\n<footer>Written by capsim {} (<code>capsim sweep</code>); the CSV and JSON files beside "
                  "this page hold the same figures.</footer>\n",
                  html_escape(version));
  const HtmlAssets& assets = html_assets();
  return fill_template(assets.page, {{"@TITLE@", html_escape("capsim sweep: " + sweep_file)},
                                     {"@STYLE@", std::string(assets.style) + std::string(assets.modes_style)},
                                     {"@BODY@", body},
                                     {"@SCRIPT@", assets.modes_script}});
}

}  // namespace capsim::sim
