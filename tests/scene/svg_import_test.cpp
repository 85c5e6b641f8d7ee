// import() of SVG files (src/scene/regions/svg_import.h): each shape and path
// command against outlines computed by hand, the page's units, viewBox, dpi
// and center, the transforms composed down the tree; OpenSCAD 2021.01's own
// drawings of the files in tests/data/svg_import (its SVG exports, stored,
// and made again when openscad is installed); every refusal at its
// FILE:LINE, and the command line's exit with nothing written.

#include "scene/regions/svg_import.h"

#include "capsim/scene/parser.h"
#include "support/cli_run.h"
#include "support/openscad_svg.h"
#include "support/polygon2d_area.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>

namespace capsim {
namespace {

using scene_file::Polygon2d;
using testing::area;
using scene_file::read_svg;
using scene_file::SvgError;
using scene_file::SvgOptions;
using testing::TempDir;

const std::string kData = std::string(CAPSIM_SOURCE_DIR) + "/tests/data/svg_import/";

std::string page(const std::string& attributes, const std::string& body) {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\"" + (attributes.empty() ? "" : " " + attributes) + ">\n" + body +
         "\n</svg>\n";
}

Polygon2d svg(const std::string& text, SvgOptions o = {}) { return read_svg(text, o); }

std::size_t vertex_count(const Polygon2d& p) {
  std::size_t n = 0;
  for (const auto& o : p.outlines) n += o.vertices.size();
  return n;
}

// A coordinate on Clipper's grid of 2^-16, truncated as the clipping truncates.
double grid(double v) { return std::trunc(v * 65536) / 65536; }

// The vertices, sorted, to compare with corners given in any order.
std::vector<std::pair<double, double>> corners(const Polygon2d& p) {
  std::vector<std::pair<double, double>> all;
  for (const auto& o : p.outlines)
    for (const glm::dvec2& v : o.vertices) all.emplace_back(v.x, v.y);
  std::sort(all.begin(), all.end());
  return all;
}
std::vector<std::pair<double, double>> gridded(std::vector<std::pair<double, double>> points) {
  for (auto& [x, y] : points) x = grid(x), y = grid(y);
  std::sort(points.begin(), points.end());
  return points;
}

bool has_vertex(const Polygon2d& p, glm::dvec2 v) {
  for (const auto& o : p.outlines)
    for (const glm::dvec2& w : o.vertices)
      if (std::abs(w.x - grid(v.x)) <= 1.0 / 65536 && std::abs(w.y - grid(v.y)) <= 1.0 / 65536) return true;
  return false;
}

std::string refusal(const std::string& what, SvgOptions o = {}) {
  try {
    read_svg(what, o);
  } catch (const SvgError& e) {
    return e.what();
  }
  return "read without error";
}

void write(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

const std::string kRect = "<rect x=\"10\" y=\"5\" width=\"20\" height=\"10\"/>";

TEST(SvgImport, PageUnitsDpiAndViewBoxPlaceARectangle) {
  // Width and height without a viewBox: user units are millimetres, and y
  // turns about the page's height, 50 units at the dpi (import_svg.cc).
  for (const double dpi : {72.0, 96.0}) {
    const double h = 50 * 25.4 / dpi;
    EXPECT_EQ(corners(svg(page("width=\"100\" height=\"50\"", kRect), {.dpi = dpi})),
              gridded({{10, h - 15}, {10, h - 5}, {30, h - 15}, {30, h - 5}}))
        << dpi;
  }
  // No size at all: y = -y.
  EXPECT_EQ(corners(svg(page("", kRect))), gridded({{10, -15}, {10, -5}, {30, -15}, {30, -5}}));
  // A viewBox scales user units to the page: 200 units over 100 mm.
  EXPECT_EQ(corners(svg(page("width=\"100mm\" height=\"50mm\" viewBox=\"0 0 200 100\"", kRect))),
            gridded({{5, 42.5}, {5, 47.5}, {15, 42.5}, {15, 47.5}}));
  // A viewBox alone takes its size at the dpi: 144 units at 72 dpi are 2 in.
  for (const double dpi : {72.0, 144.0}) {
    const double s = 25.4 / dpi, h = 72 * s;
    EXPECT_EQ(corners(svg(page("viewBox=\"0 0 144 72\"", kRect), {.dpi = dpi})),
              gridded({{10 * s, h - 15 * s}, {10 * s, h - 5 * s}, {30 * s, h - 15 * s}, {30 * s, h - 5 * s}}))
        << dpi;
  }
  // Units of the page: in, cm, pt, pc, px (96 per inch), and % (the viewBox's size).
  const std::pair<std::string, double> units[] = {{"1in", 25.4},        {"2.54cm", 25.4},     {"72pt", 25.4},
                                                  {"6pc", 25.4},        {"96px", 25.4},       {"100%", 100},
                                                  {"25.4mm", 25.4}};
  for (const auto& [size, mm] : units) {
    const Polygon2d p = svg(page(fmt::format("width=\"{0}\" height=\"{0}\" viewBox=\"0 0 100 100\"", size),
                                 "<rect width=\"100\" height=\"100\"/>"));
    EXPECT_NEAR(area(p), mm * mm, 1e-6 * mm * mm) << size;
  }
  // preserveAspectRatio: the smaller scale (meet) and its alignment; none
  // scales x and y apart.
  const std::string box = "width=\"100mm\" height=\"50mm\" viewBox=\"0 0 100 100\"";
  EXPECT_EQ(corners(svg(page(box, "<rect width=\"100\" height=\"100\"/>"))),
            gridded({{25, 0}, {25, 50}, {75, 0}, {75, 50}}));
  EXPECT_EQ(corners(svg(page(box + " preserveAspectRatio=\"xMinYMin meet\"", "<rect width=\"100\" height=\"100\"/>"))),
            gridded({{0, 0}, {0, 50}, {50, 0}, {50, 50}}));
  EXPECT_EQ(corners(svg(page(box + " preserveAspectRatio=\"none\"", "<rect width=\"100\" height=\"100\"/>"))),
            gridded({{0, 0}, {0, 50}, {100, 0}, {100, 50}}));
  // slice: the larger scale, 1, centred in y: the page's 50 mm less 100.
  EXPECT_EQ(corners(svg(page(box + " preserveAspectRatio=\"xMidYMid slice\"", "<rect width=\"100\" height=\"100\"/>"))),
            gridded({{0, -25}, {0, 75}, {100, -25}, {100, 75}}));
  // A viewBox's x moves the drawing left; its y moves it up, as OpenSCAD
  // 2021.01 adds it where SVG subtracts it.
  EXPECT_EQ(corners(svg(page("width=\"100mm\" height=\"100mm\" viewBox=\"5 7 100 100\"", kRect))),
            gridded({{5, 78}, {5, 88}, {25, 78}, {25, 88}}));
}

TEST(SvgImport, CenterPutsTheDrawingsBoxOnTheOrigin) {
  const Polygon2d p = svg(page("width=\"100\" height=\"50\"", kRect + "<rect x=\"50\" y=\"20\" width=\"6\" height=\"6\"/>"),
                          {.center = true});
  // The box: x from 10 to 56 and y from 5 to 26 in the file.
  glm::dvec2 lo(1e9), hi(-1e9);
  for (const auto& o : p.outlines)
    for (const glm::dvec2& v : o.vertices) lo = glm::min(lo, v), hi = glm::max(hi, v);
  EXPECT_EQ(lo, glm::dvec2(-23, -10.5));
  EXPECT_EQ(hi, glm::dvec2(23, 10.5));
}

TEST(SvgImport, TransformsComposeDownTheTree) {
  const std::string box = "width=\"100mm\" height=\"100mm\" viewBox=\"0 0 100 100\"";  // y = 100 - y
  // translate(10, 20) of rotate(90) of scale(2, 1) of the rect (0, 0)-(4, 2).
  EXPECT_EQ(corners(svg(page(box, "<g transform=\"translate(10,20)\"><rect width=\"4\" height=\"2\" "
                                  "transform=\"rotate(90) scale(2,1)\"/></g>"))),
            gridded({{8, 72}, {8, 80}, {10, 72}, {10, 80}}));
  // rotate about a centre, nested groups, skewX(45) (tan exactly 1), matrix().
  EXPECT_EQ(corners(svg(page(box, "<g transform=\"rotate(180, 5, 5)\"><g><rect width=\"2\" height=\"2\"/></g></g>"))),
            gridded({{8, 90}, {8, 92}, {10, 90}, {10, 92}}));
  EXPECT_EQ(corners(svg(page(box, "<rect width=\"2\" height=\"2\" transform=\"skewX(45)\"/>"))),
            gridded({{0, 100}, {2, 98}, {2, 100}, {4, 98}}));
  EXPECT_EQ(corners(svg(page(box, "<rect width=\"2\" height=\"2\" transform=\"matrix(1 0 0 1 3 4) skewY(45)\"/>"))),
            gridded({{3, 94}, {3, 96}, {5, 92}, {5, 94}}));
  // An unknown element is transparent: its transform is not read, its
  // shapes are (as libsvg reads them).
  EXPECT_EQ(corners(svg(page(box, "<a transform=\"translate(50,0)\"><rect width=\"2\" height=\"2\"/></a>"))),
            gridded({{0, 98}, {0, 100}, {2, 98}, {2, 100}}));
}

TEST(SvgImport, StraightShapesAreExact) {
  // polygon (closed), the even-odd rule inside one shape, and the union of shapes.
  EXPECT_EQ(area(svg(page("", "<polygon points=\"0,0 10,0 10,10\"/>"))), 50);
  EXPECT_EQ(area(svg(page("", "<polygon points=\"0,0 10,0 10,10 0,10 0,0 2,2 8,2 8,8 2,8 2,2\"/>"))), 64);
  EXPECT_EQ(area(svg(page("", "<rect width=\"10\" height=\"10\"/><rect x=\"5\" width=\"10\" height=\"10\"/>"))), 150);
  // A line and a polyline are stroked: square caps by default, a stroke of
  // width 1 unless given (or less than 0.01).
  EXPECT_EQ(area(svg(page("", "<line x1=\"0\" y1=\"0\" x2=\"10\" y2=\"0\"/>"))), 11);
  EXPECT_EQ(area(svg(page("", "<line x1=\"0\" y1=\"0\" x2=\"10\" y2=\"0\" stroke-width=\"0.001\"/>"))), 11);
  EXPECT_EQ(area(svg(page("", "<line x1=\"0\" y1=\"0\" x2=\"10\" y2=\"0\" stroke-width=\"4\" "
                              "stroke-linecap=\"butt\"/>"))),
            40);
  EXPECT_EQ(area(svg(page("", "<polyline points=\"0,0 10,0 10,10\" style=\"stroke-width:2;stroke-linecap:butt\"/>"))),
            40);
  // A path that does not come back to its start is stroked too; one that
  // does is filled.
  EXPECT_EQ(area(svg(page("", "<path d=\"M0,0 H10\" stroke-linecap=\"butt\"/>"))), 10);
  EXPECT_NEAR(area(svg(page("", "<path d=\"M0,0 H10 V10 L0,0.05\"/>"))), 50.25, 1e-4);
}

TEST(SvgImport, PathCommandsAndNumberForms) {
  // The same square by absolute and relative commands, implicit line-tos
  // after a move, repeated coordinates, exponents and "-.5.5".
  for (const std::string d : {"M10,10 L30,10 30,30 10,30 Z", "m10 10 20 0 0 20 -20 0 z", "M10,10 h20 v20 h-20 z",
                              "M10,10 H30 V30 H10 V10 z", "M1e1,10 h2e+1 v.2e2 h-20 v-.5.5-20z"}) {
    const Polygon2d p = svg(page("", "<path d=\"" + d + "\"/>"));
    EXPECT_EQ(corners(p), gridded({{10, -30}, {10, -10}, {30, -30}, {30, -10}})) << d;
  }
  // A cubic, its smooth continuation (the control point reflected), a
  // quadratic and its smooth continuation: 20 segments each, the middle
  // points of Bernstein's formula.
  const Polygon2d c = svg(page("", "<path d=\"M0,0 C0,10 10,10 10,0 S20,-10 20,0 Q30,10 40,0 T60,0 L60,-20 L0,-20 z\"/>"));
  // 4 curves of 20 segments and the corners (0, 0), (60, -20), (0, -20), but
  // for (10, 0) and (40, 0): each smooth continuation is the point
  // reflection of the curve before it, so the join lies on the line of its
  // neighbours, and Clipper drops it.
  EXPECT_EQ(vertex_count(c), 4u * 20 + 3 - 2);
  EXPECT_TRUE(has_vertex(c, {5, -7.5}));    // (P0 + 3 P1 + 3 P2 + P3) / 8
  EXPECT_TRUE(has_vertex(c, {15, 7.5}));    // S: first control point (10, -10)
  EXPECT_TRUE(has_vertex(c, {30, -5}));     // (P0 + 2 P1 + P2) / 4
  EXPECT_TRUE(has_vertex(c, {50, 5}));      // T: control point (50, -10)
  // Relative forms of the same curve.
  EXPECT_EQ(corners(svg(page("", "<path d=\"m0,0 c0,10 10,10 10,0 s10,-10 10,0 q10,10 20,0 t20,0 l0,-20 l-60,0 z\"/>"))),
            corners(c));
  // An arc of 180 degrees: 4 + 10 segments, a polygon of 14 triangles of
  // the centre; the large-arc and sweep flags pick the half.
  const Polygon2d half = svg(page("", "<path d=\"M0,0 A10,10 0 0,1 20,0 z\"/>"));
  EXPECT_EQ(vertex_count(half), 15u);
  EXPECT_NEAR(area(half), 14 * 50 * std::sin(std::numbers::pi / 14), 1e-3);  // vertices on the 2^-16 grid
  EXPECT_TRUE(has_vertex(half, {10, 10}));  // y up: sweep 1 runs through SVG's (10, -10)
  EXPECT_TRUE(has_vertex(svg(page("", "<path d=\"M0,0 a10,10 0 0,0 20,0 z\"/>")), {10, -10}));
  // A radius too small for the chord grows to half of it.
  EXPECT_NEAR(area(svg(page("", "<path d=\"M0,0 A1,1 0 0,1 20,0 z\"/>"))), area(half), 1e-8);
  // A 270-degree arc (large) takes 4 + 15 segments.
  EXPECT_EQ(vertex_count(svg(page("", "<path d=\"M10,0 A10,10 0 1,1 0,-10 L0,0 z\"/>"))), 21u);
}

TEST(SvgImport, CurvedShapesAreCutAsOpenScadCutsThem) {
  // 40 points for a circle or an ellipse, whatever its size.
  for (const double r : {1.0, 100.0}) {
    const Polygon2d p = svg(page("", fmt::format("<circle cx=\"0\" cy=\"0\" r=\"{}\"/>", r)));
    EXPECT_EQ(vertex_count(p), 40u);
    EXPECT_NEAR(area(p), 20 * r * r * std::sin(2 * std::numbers::pi / 40), 1e-4 * r * r);
  }
  const Polygon2d e = svg(page("", "<ellipse cx=\"0\" cy=\"0\" rx=\"20\" ry=\"10\"/>"));
  EXPECT_EQ(vertex_count(e), 40u);
  EXPECT_NEAR(area(e), 20 * 200 * std::sin(2 * std::numbers::pi / 40), 1e-3);
  // Round corners: 4 quarter arcs of 9 segments each; ry takes rx when not
  // given, and both are cut to half the side.
  const Polygon2d r = svg(page("", "<rect width=\"20\" height=\"10\" rx=\"3\"/>"));
  EXPECT_EQ(vertex_count(r), 40u);
  EXPECT_EQ(corners(r).front(), std::make_pair(0.0, grid(-7.0)));
  EXPECT_EQ(vertex_count(svg(page("", "<rect width=\"20\" height=\"10\" rx=\"30\" ry=\"30\"/>"))), 36u);
}

TEST(SvgImport, WhatOpenScadIgnoresIsIgnored) {
  const std::string shapes = "<rect width=\"10\" height=\"10\"/>";
  const Polygon2d plain = svg(page("", shapes));
  for (const std::string other :
       {"<text x=\"0\" y=\"0\">words<tspan>more</tspan></text>", "<defs><rect width=\"99\" height=\"99\"/></defs>",
        "<image href=\"x.png\" width=\"50\" height=\"50\"/>", "<use href=\"#r\"/>", "<title>t</title>",
        "<style>rect { fill: none }</style>"}) {
    EXPECT_EQ(corners(svg(page("", shapes + other))), corners(plain)) << other;
  }
  // Colours and fill="none" change nothing: every shape is filled.
  EXPECT_EQ(corners(svg(page("", "<rect width=\"10\" height=\"10\" fill=\"none\" stroke=\"red\"/>"))), corners(plain));
}

// OpenSCAD 2021.01's SVG export of import(file, args), stored beside the file.
struct OracleCase {
  std::string file, args, expected;
  SvgOptions options;
};

const OracleCase kOracleCases[] = {
    {"shapes.svg", "", "shapes.openscad.svg", {}},
    {"paths.svg", "", "paths.openscad.svg", {}},
    {"transforms.svg", "", "transforms.openscad.svg", {}},
    {"page.svg", ", dpi = 96", "page.dpi96.openscad.svg", {.dpi = 96}},
    {"page.svg", ", dpi = 300, center = true", "page.dpi300-center.openscad.svg", {.dpi = 300, .center = true}},
};

// Every contour OpenSCAD drew is one of ours, vertex for vertex to its 6
// printed digits, and there are as many.
void expect_same_contours(const std::vector<std::vector<glm::dvec2>>& theirs, const Polygon2d& ours,
                          const std::string& what) {
  ASSERT_EQ(theirs.size(), ours.outlines.size()) << what;
  std::vector<bool> used(ours.outlines.size(), false);
  for (const auto& contour : theirs) {
    bool found = false;
    for (std::size_t k = 0; k < ours.outlines.size() && !found; ++k) {
      const auto& mine = ours.outlines[k].vertices;
      if (used[k] || mine.size() != contour.size()) continue;
      bool same = true;
      for (std::size_t i = 0; i < mine.size() && same; ++i)
        same = glm::length(mine[i] - contour[i]) <= 1e-5 * std::max(1.0, glm::length(contour[i]));
      if (same) used[k] = found = true;
    }
    EXPECT_TRUE(found) << what << ": OpenSCAD's contour of " << contour.size() << " vertices from (" << contour[0].x
                       << ", " << contour[0].y << ") is not capsim's";
  }
}

TEST(SvgImport, MatchesOpenScadsStoredDrawings) {
  for (const OracleCase& c : kOracleCases) {
    const Polygon2d ours = read_svg(testing::read_file(kData + c.file), c.options);
    expect_same_contours(testing::read_svg_contours(kData + c.expected), ours, c.expected);
  }
}

TEST(SvgImport, StoredDrawingsAreOpenScadsOwn) {
  if (!testing::has_openscad()) GTEST_SKIP() << "needs openscad on PATH (Debian: openscad)";
  TempDir dir;
  for (const OracleCase& c : kOracleCases) {
    const std::string scad = dir / "t.scad", out = dir / "t.svg";
    std::ofstream(scad) << fmt::format("import(\"{}\"{});\n", kData + c.file, c.args);
    ASSERT_EQ(std::system(fmt::format("openscad -o '{}' '{}' >'{}' 2>&1", out, scad, dir / "log").c_str()), 0);
    const auto fresh = testing::read_svg_contours(out), stored = testing::read_svg_contours(kData + c.expected);
    ASSERT_EQ(fresh.size(), stored.size()) << c.expected;
    for (std::size_t k = 0; k < fresh.size(); ++k) EXPECT_EQ(fresh[k], stored[k]) << c.expected;
  }
}

TEST(SvgImport, RefusalsNameTheLine) {
  auto starts = [](const std::string& message, const std::string& prefix) {
    return message.rfind(prefix, 0) == 0 ? ::testing::AssertionSuccess()
                                         : ::testing::AssertionFailure() << message;
  };
  EXPECT_TRUE(starts(refusal(page("", "<rect width=\"1\" height=\"1\">\n")), "4: the file is not well-formed XML: "));
  EXPECT_TRUE(starts(refusal(""), "1: the file is empty"));
  EXPECT_TRUE(starts(refusal(page("", "<text>x</text>")), "1: the file draws nothing"));
  EXPECT_TRUE(starts(refusal(page("", "<defs><rect width=\"1\" height=\"1\"/></defs>")), "1: the file draws nothing"));
  EXPECT_TRUE(starts(refusal(page("", "\n<path d=\"M0,0 L1,1x\"/>")), "3: the path's number '1x' is not a number"));
  EXPECT_TRUE(starts(refusal(page("", "<path d=\"M0,0 X1,1\"/>")), "2: the path command 'X' is not one of"));
  EXPECT_TRUE(starts(refusal(page("", "<path d=\"0,0 L1,1\"/>")), "2: the path data starts with a number"));
  EXPECT_TRUE(starts(refusal(page("", "<path d=\"M0,0 L1\"/>")), "2: the path's 'L' command lacks numbers"));
  EXPECT_TRUE(starts(refusal(page("", "<path d=\"M0,0 L1,1 z 5\"/>")), "2: the path data has a number after z"));
  EXPECT_TRUE(starts(refusal(page("", "<path d=\"M0,0 A5,5 0 2 1 10,0\"/>")), "2: the arc's flag 2 is not 0 or 1"));
  EXPECT_TRUE(starts(refusal(page("", "<path d=\"M0,0 A0,5 0 0 1 10,0 z\"/>")), "2: the arc from (0, 0) to (10, 0) has a "
                                                                                  "zero radius"));
  EXPECT_TRUE(starts(refusal(page("", "<path d=\"M0,0 L1E-3,1\"/>")), "2: the path's number '1E' is not a number"));
  EXPECT_TRUE(starts(refusal(page("", "<rect width=\"10px\" height=\"1\"/>")), "2: the rect's width '10px' is not a "
                                                                              "number"));
  EXPECT_TRUE(starts(refusal(page("", "<polygon points=\"0,0 1,0 1\"/>")), "2: the polygon's points are 5 numbers"));
  EXPECT_TRUE(starts(refusal(page("", "<rect width=\"1\" height=\"1\" transform=\"rotate(1, 2)\"/>")),
                     "2: rotate() in the transform 'rotate(1, 2)' takes 1 or 3 numbers"));
  EXPECT_TRUE(starts(refusal(page("", "<rect width=\"1\" height=\"1\" transform=\"foo(1)\"/>")),
                     "2: the transform 'foo(1)' does not start with matrix"));
  EXPECT_TRUE(starts(refusal(page("width=\"10 furlongs\"", "<rect width=\"1\" height=\"1\"/>")),
                     "1: the svg element's width '10 furlongs' is not a length"));
  EXPECT_TRUE(starts(refusal(page("viewBox=\"0 0 0 10\"", "<rect width=\"1\" height=\"1\"/>")),
                     "1: the viewBox '0 0 0 10' has no area"));
  EXPECT_TRUE(starts(refusal(page("viewBox=\"0 0 10\"", "<rect width=\"1\" height=\"1\"/>")),
                     "1: the viewBox '0 0 10' is not 4 numbers"));
  EXPECT_TRUE(starts(refusal(page("preserveAspectRatio=\"middle\"", "<rect width=\"1\" height=\"1\"/>")),
                     "1: the preserveAspectRatio 'middle' is not read"));
  EXPECT_TRUE(starts(refusal(page("", "<rect width=\"1e31\" height=\"1\"/>")), "2: the rect's width '1e31' is not a "
                                                                              "number within 1e+30"));
  EXPECT_TRUE(starts(refusal(page("", "<line x2=\"1\" stroke-width=\"2px\"/>")), "2: the stroke-width '2px' is not a "
                                                                                "number"));
  EXPECT_TRUE(starts(refusal(page("", "<line x2=\"1\" stroke-width=\"1e12\" stroke-linecap=\"round\"/>")),
                     "2: the stroke's round joins and caps would make more than 1000000 points"));
  EXPECT_TRUE(starts(refusal(page("", "<rect width=\"1\" height=\"1\" transform=\"scale(1e30) scale(1e30)\"/>")),
                     "2: the shape reaches"));
  // More than kMaxSvgPoints points: circles of 40 each.
  std::string circles;
  for (std::size_t k = 0; k <= scene_file::kMaxSvgPoints / 40; ++k) circles += "<circle r=\"1\"/>\n";
  EXPECT_TRUE(starts(refusal(page("", circles)), fmt::format("{}: more than 1000000 points", scene_file::kMaxSvgPoints / 40 + 2)));
}

TEST(SvgImport, EntitiesAreNotExpandedAndOtherFilesNotRead) {
  TempDir dir;
  write(dir / "shape.xml", "<rect width=\"10\" height=\"10\"/>");
  const std::string external = "<?xml version=\"1.0\"?>\n<!DOCTYPE svg [ <!ENTITY ext SYSTEM \"" + (dir / "shape.xml") +
                               "\"> ]>\n" + page("", "&ext;");
  EXPECT_EQ(refusal(external).rfind("3: the entity reference '&ext;'", 0), 0u) << refusal(external);
  // An entity that would grow beyond libxml2's bounds is malformed XML.
  std::string laughs = "<?xml version=\"1.0\"?>\n<!DOCTYPE svg [\n<!ENTITY a0 \"aaaaaaaaaaaaaaaa\">\n";
  for (int k = 1; k < 10; ++k)
    laughs += fmt::format("<!ENTITY a{} \"{}\">\n", k, fmt::format("&a{};", k - 1) + fmt::format("&a{};", k - 1) +
                                                         fmt::format("&a{};&a{};&a{};&a{};&a{};&a{};&a{};&a{};", k - 1,
                                                                     k - 1, k - 1, k - 1, k - 1, k - 1, k - 1, k - 1));
  laughs += "]>\n" + page("", "<path id=\"&a9;\" d=\"M0,0 h5 v5 z\"/>");
  EXPECT_NE(refusal(laughs).find("the file is not well-formed XML"), std::string::npos) << refusal(laughs).substr(0, 200);
  // The five predefined entities and character references are read.
  EXPECT_EQ(area(svg(page("", "<rect width=\"&#49;0\" height=\"10\" id=\"&lt;&amp;&gt;\"/>"))), 100);
}

TEST(SvgImport, SceneRefusalsAreLocatedAndTheCommandLineWritesNothing) {
  TempDir dir;
  write(dir / "bad.svg", page("", "<path d=\"M0,0 L1,1x\"/>"));
  write(dir / "good.svg", page("", "<rect width=\"10\" height=\"10\"/>"));
  const std::string scene = dir / "t.csg";
  std::string message = "parsed without error";
  try {
    parse_scene("linear_extrude(1) import(\"bad.svg\");", scene);
  } catch (const SceneError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find(scene + ":1:26:"), std::string::npos) << message;
  EXPECT_NE(message.find("cannot import 'bad.svg': "), std::string::npos) << message;
  EXPECT_NE(message.find("bad.svg:2: the path's number '1x' is not a number"), std::string::npos) << message;
  // A good file extrudes to a scene; a 2-D design alone too.
  EXPECT_FALSE(parse_scene("linear_extrude(2) import(\"good.svg\");", scene).primitives.empty());
  EXPECT_FALSE(parse_scene("import(\"good.svg\", center = true, dpi = 96);", scene).primitives.empty());
  write(scene, "linear_extrude(1) import(\"bad.svg\");\n");
  const testing::RunResult r = testing::run_capsim("render " + scene + " -o " + (dir / "out.png") + " --size 8x8", dir);
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("bad.svg:2: the path's number '1x' is not a number"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
}

}  // namespace
}  // namespace capsim
