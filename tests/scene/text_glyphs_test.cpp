// OpenSCAD's text() as capsim draws it (src/scene/regions/text_glyphs.h), against
// OpenSCAD 2021.01's own drawing: its SVG export of the same 2-D text. The
// export prints 6 significant digits and has been through Clipper's union
// (which drops repeated and collinear vertices), so every vertex it prints
// must lie within 1e-4 of one of ours, and the areas agree to 1e-5.

#include "scene/regions/text_glyphs.h"
#include "support/cli_run.h"
#include "support/openscad_svg.h"

#include <fmt/core.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace capsim {
namespace {

using testing::has_openscad;
using testing::read_svg_contours;
using testing::TempDir;

double signed_area(const TextContour& c) {
  double twice = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const glm::dvec2 a = c[i], b = c[(i + 1) % c.size()];
    twice += a.x * b.y - b.x * a.y;
  }
  return twice / 2;
}

// The text's area: its glyphs do not overlap, and each glyph's holes wind
// against its solid, so the contours' signed areas add up to it.
double area(const std::vector<TextContour>& contours) {
  double sum = 0;
  for (const TextContour& c : contours) sum += signed_area(c);
  return std::abs(sum);
}

TEST(TextGlyphs, CurveStepsFollowOpenScadsFragments) {
  EXPECT_EQ(openscad_fragments(10, 0, 2, 12), 30);   // 360 / 12
  EXPECT_EQ(openscad_fragments(1, 0, 2, 12), 5);     // at least 5
  EXPECT_EQ(openscad_fragments(50, 16, 2, 12), 16);  // $fn wins
  EXPECT_EQ(openscad_fragments(50, 2, 2, 12), 3);    // at least 3
  EXPECT_EQ(openscad_fragments(50, 7.9, 2, 12), 7);  // $fn is cut to a whole number
  EXPECT_THROW(openscad_fragments(10, 0, 0, 0), TextError);
  EXPECT_THROW(openscad_fragments(10, 1e12, 2, 12), TextError);
  TextSpec spec;
  EXPECT_EQ(text_curve_segments(spec), 4);  // size 10: 30 fragments / 8 + 1
  spec.size = 50;
  spec.fn = 16;
  EXPECT_EQ(text_curve_segments(spec), 3);
  spec.fn = 3;
  EXPECT_EQ(text_curve_segments(spec), 2);  // never fewer than 2
}

TEST(TextGlyphs, TheDefaultFontIsLiberationSans) {
  EXPECT_NE(text_font_file("").find("LiberationSans-Regular"), std::string::npos) << text_font_file("");
  EXPECT_NE(text_font_file("Liberation Sans:style=Bold").find("LiberationSans-Bold"), std::string::npos);
}

TEST(TextGlyphs, AGlyphWithAHoleWindsItAgainstItsSolid) {
  const TextSpec spec{.text = "O"};
  const std::vector<TextContour> contours = text_contours(spec);
  ASSERT_EQ(contours.size(), 2u);
  EXPECT_LT(signed_area(contours[0]) * signed_area(contours[1]), 0);
  EXPECT_TRUE(text_contours(TextSpec{}).empty());  // no text, no contours
}

TEST(TextGlyphs, AlignmentMovesTheTextAsOpenScadDoes) {
  TextSpec spec;
  spec.text = "capsim";
  auto bounds = [&] {
    glm::dvec2 lo(1e9), hi(-1e9);
    for (const TextContour& c : text_contours(spec))
      for (const glm::dvec2& v : c) lo = glm::min(lo, v), hi = glm::max(hi, v);
    return std::pair(lo, hi);
  };
  const auto [lo, hi] = bounds();
  EXPECT_GE(lo.x, 0);  // left, baseline: starts at the origin
  EXPECT_LT(lo.y, 0);  // "p" descends below the baseline
  spec.halign = "right";
  spec.valign = "top";
  const auto [rlo, rhi] = bounds();
  EXPECT_NEAR(rhi.x - rlo.x, hi.x - lo.x, 1e-12);
  EXPECT_LT(rhi.x, 0.5);  // ends at the origin (less its last glyph's side bearing)
  // OpenSCAD measures the ascent at 1000/1024 of the outlines' scale, so a
  // top-aligned text stands 2.4 % of its ascent above the origin.
  EXPECT_GT(rhi.y, 0);
  EXPECT_LT(rhi.y, 0.03 * (hi.y - lo.y));
  spec.halign = "middle";  // unknown: left, as OpenSCAD takes it
  spec.valign = "baseline";
  EXPECT_NEAR(bounds().first.x, lo.x, 1e-12);
}

TEST(TextGlyphs, MatchesOpenScadsOwnDrawing) {
  if (!has_openscad()) GTEST_SKIP() << "needs openscad on PATH (Debian: openscad)";
  TempDir dir;
  struct Case {
    std::string scad;
    TextSpec spec;
  };
  std::vector<Case> cases;
  TextSpec a;
  a.text = "capsim";
  a.halign = "center";
  cases.push_back({R"(text("capsim", halign = "center");)", a});
  TextSpec b;
  b.text = "Ag%&";
  b.size = 50;
  b.fn = 16;
  b.font = "Liberation Serif:style=Bold";
  b.valign = "center";
  b.spacing = 1.5;
  cases.push_back({R"(text("Ag%&", size = 50, font = "Liberation Serif:style=Bold", valign = "center", spacing = 1.5, $fn = 16);)", b});
  TextSpec c;
  c.text = "OpenSCAD";
  c.direction = "ttb";
  c.fs = 0.5;
  c.valign = "top";
  cases.push_back({R"(text("OpenSCAD", direction = "ttb", valign = "top", $fs = 0.5);)", c});
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const std::string scad = dir / fmt::format("t{}.scad", k), svg = dir / fmt::format("t{}.svg", k);
    std::ofstream(scad) << cases[k].scad << "\n";
    const std::string run = fmt::format("openscad -o '{}' '{}' >'{}' 2>&1", svg, scad, dir / "openscad.log");
    ASSERT_EQ(std::system(run.c_str()), 0) << cases[k].scad;
    const std::vector<TextContour> theirs = read_svg_contours(svg);
    const std::vector<TextContour> ours = text_contours(cases[k].spec);
    ASSERT_FALSE(theirs.empty()) << cases[k].scad;
    EXPECT_NEAR(area(ours), area(theirs), 1e-5 * area(theirs)) << cases[k].scad;
    int far = 0;
    for (const TextContour& contour : theirs)
      for (const glm::dvec2& v : contour) {
        double nearest = 1e9;
        for (const TextContour& mine : ours)
          for (const glm::dvec2& w : mine) nearest = std::min(nearest, glm::length(v - w));
        if (nearest > 1e-4 * std::max(1.0, glm::length(v))) ++far;
      }
    EXPECT_EQ(far, 0) << cases[k].scad;
  }
}

}  // namespace
}  // namespace capsim
