// The plots' helpers: a logarithmic axis's range in whole decades or octaves,
// and an SVG document made an element of an HTML page.

#include "report/svg_plot.h"

#include <gtest/gtest.h>

namespace capsim::sim {
namespace {

TEST(SvgPlot, LogRangeTakesTheWholePowersAroundTheValues) {
  const LogRange d = log_range(0.5, 37, 10);
  EXPECT_EQ(d.lo, 0.1);
  EXPECT_EQ(d.hi, 100);
  EXPECT_EQ(d.ticks, (std::vector<double>{0.1, 1, 10, 100}));
  const LogRange s = log_range(1, 6.5, 2);
  EXPECT_EQ(s.lo, 1);
  EXPECT_EQ(s.hi, 8);
  EXPECT_EQ(s.ticks, (std::vector<double>{1, 2, 4, 8}));
  // A power itself is an end, not rounded past.
  EXPECT_EQ(log_range(10, 1000, 10).ticks, (std::vector<double>{10, 100, 1000}));
  // One value: one power apart.
  const LogRange one = log_range(4, 4, 2);
  EXPECT_EQ(one.lo, 4);
  EXPECT_EQ(one.hi, 8);
}

TEST(SvgPlot, InlineSvgDropsTheNamespaceAddress) {
  const std::string svg = inline_svg(svg_document(10, 20, "<line/>\n"));
  EXPECT_EQ(svg.find("xmlns"), std::string::npos);
  EXPECT_EQ(svg.rfind("<svg width=\"10\" height=\"20\"", 0), 0u) << svg;
}

}  // namespace
}  // namespace capsim::sim
