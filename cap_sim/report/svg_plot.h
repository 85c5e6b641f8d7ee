#pragma once
// Line plots as SVG text, for the reproduction's and the benchmarks' figures:
// axes (linear or logarithmic) with ticks, series of points joined by solid
// or dashed lines with markers, and a legend. Deterministic: the same data
// give the same bytes.

#include <string>
#include <utility>
#include <vector>

namespace capsim::sim {

struct PlotSeries {
  std::string label;
  std::string colour = "#1f77b4";
  std::string dash;  // SVG stroke-dasharray: "" solid, "6 4" dashed, "2 3" dotted
  bool square_markers = false;  // else circles
  std::vector<std::pair<double, double>> points;  // (x, y), x ascending
};

// A series with no points yet.
inline PlotSeries plot_series(std::string label, std::string colour, std::string dash = "",
                              bool square_markers = false) {
  PlotSeries s;
  s.label = std::move(label);
  s.colour = std::move(colour);
  s.dash = std::move(dash);
  s.square_markers = square_markers;
  return s;
}

struct PlotAxes {
  std::string title, x_label, y_label;
  bool log_x = false, log_y = false;
  double x_min = 0, x_max = 1, y_min = 0, y_max = 1;  // positive for a log axis
  std::vector<double> x_ticks, y_ticks;
};

// A logarithmic axis's range: the whole powers of `base` (10: decades, 2:
// octaves) around [lo, hi], at least one apart, each a tick.
// Precondition: 0 < lo <= hi.
struct LogRange {
  double lo = 1, hi = 10;
  std::vector<double> ticks;
};
LogRange log_range(double lo, double hi, double base);

// One plot panel, drawn in the rectangle at (left, top) of the given size
// (legend included, on its right).
std::string plot_panel_svg(const PlotAxes& axes, const std::vector<PlotSeries>& series, double left, double top,
                           double width, double height);

// A whole SVG document of the given size around panels.
std::string svg_document(double width, double height, const std::string& body);

// An SVG document as an element of an HTML page: inside HTML the SVG
// namespace is implied, and leaving it out keeps the page free of any address.
std::string inline_svg(std::string svg);

// Ten distinct colours for series.
const std::string& series_colour(int i);

}  // namespace capsim::sim
