#include "report/svg_plot.h"

#include <fmt/core.h>

#include <array>
#include <cmath>

namespace capsim::sim {

namespace {

constexpr double kLegendWidth = 190;
constexpr double kMarginLeft = 62, kMarginRight = 12, kMarginTop = 30, kMarginBottom = 46;

std::string escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else out += c;
  }
  return out;
}

// Maps data to the plot area, linearly or logarithmically.
struct Scale {
  double lo, hi, from, to;
  bool log;
  double operator()(double v) const {
    const double t = log ? (std::log(v) - std::log(lo)) / (std::log(hi) - std::log(lo)) : (v - lo) / (hi - lo);
    return from + t * (to - from);
  }
};

}  // namespace

const std::string& series_colour(int i) {
  static const std::array<std::string, 10> colours = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                                                      "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};
  return colours[static_cast<std::size_t>(i) % colours.size()];
}

std::string plot_panel_svg(const PlotAxes& a, const std::vector<PlotSeries>& series, double left, double top,
                           double width, double height) {
  const double x0 = left + kMarginLeft, x1 = left + width - kLegendWidth - kMarginRight;
  const double y0 = top + height - kMarginBottom, y1 = top + kMarginTop;
  const Scale sx{a.x_min, a.x_max, x0, x1, a.log_x};
  const Scale sy{a.y_min, a.y_max, y0, y1, a.log_y};
  std::string s;
  s += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"14\" text-anchor=\"middle\">{}</text>\n",
                   (x0 + x1) / 2, top + 18, escape(a.title));
  s += fmt::format("<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" fill=\"none\" stroke=\"#444\"/>\n",
                   x0, y1, x1 - x0, y0 - y1);
  for (double t : a.x_ticks) {
    const double x = sx(t);
    s += fmt::format("<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{0:.1f}\" y2=\"{2:.1f}\" stroke=\"#ddd\"/>\n", x, y0, y1);
    s += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"11\" text-anchor=\"middle\">{:g}</text>\n", x,
                     y0 + 15, t);
  }
  for (double t : a.y_ticks) {
    const double y = sy(t);
    s += fmt::format("<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" stroke=\"#ddd\"/>\n", x0, y, x1);
    s += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"11\" text-anchor=\"end\">{:g}</text>\n", x0 - 4,
                     y + 4, t);
  }
  s += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"12\" text-anchor=\"middle\">{}</text>\n",
                   (x0 + x1) / 2, y0 + 34, escape(a.x_label));
  s += fmt::format(
      "<text x=\"{0:.1f}\" y=\"{1:.1f}\" font-size=\"12\" text-anchor=\"middle\" "
      "transform=\"rotate(-90 {0:.1f} {1:.1f})\">{2}</text>\n",
      left + 16, (y0 + y1) / 2, escape(a.y_label));

  for (std::size_t i = 0; i < series.size(); ++i) {
    const PlotSeries& p = series[i];
    const std::string dash = p.dash.empty() ? "" : fmt::format(" stroke-dasharray=\"{}\"", p.dash);
    std::string path;
    for (const auto& [x, y] : p.points) path += fmt::format("{}{:.1f},{:.1f}", path.empty() ? "" : " ", sx(x), sy(y));
    if (p.points.size() > 1)
      s += fmt::format("<polyline points=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"1.6\"{}/>\n", path,
                       p.colour, dash);
    for (const auto& [x, y] : p.points) {
      if (p.square_markers)
        s += fmt::format("<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"6\" height=\"6\" fill=\"white\" stroke=\"{}\"/>\n",
                         sx(x) - 3, sy(y) - 3, p.colour);
      else
        s += fmt::format("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"3\" fill=\"{}\"/>\n", sx(x), sy(y), p.colour);
    }
    // Legend entry.
    const double ly = y1 + 8 + 18 * static_cast<double>(i), lx = x1 + 16;
    s += fmt::format("<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"{}\" stroke-width=\"1.6\"{}/>\n",
                     lx, ly, lx + 26, ly, p.colour, dash);
    s += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"11\">{}</text>\n", lx + 32, ly + 4, escape(p.label));
  }
  return s;
}

LogRange log_range(double lo, double hi, double base) {
  LogRange r;
  r.lo = std::pow(base, std::floor(std::log(lo) / std::log(base) + 1e-9));
  r.hi = std::pow(base, std::ceil(std::log(hi) / std::log(base) - 1e-9));
  if (r.hi <= r.lo) r.hi = r.lo * base;
  for (double t = r.lo; t <= r.hi * 1.0001; t *= base) r.ticks.push_back(t);
  return r;
}

std::string inline_svg(std::string svg) {
  const std::string xmlns = " xmlns=\"http://www.w3.org/2000/svg\"";
  const std::size_t at = svg.find(xmlns);
  if (at != std::string::npos) svg.erase(at, xmlns.size());
  return svg;
}

std::string svg_document(double width, double height, const std::string& body) {
  return fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0:.0f}\" height=\"{1:.0f}\" viewBox=\"0 0 {0:.0f} "
      "{1:.0f}\" font-family=\"sans-serif\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n{2}</svg>\n",
      width, height, body);
}

}  // namespace capsim::sim
