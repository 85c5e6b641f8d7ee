// Tests of the errors the parser gives for a whole file: every module outside
// the subset listed at once in file order, and a file cut short reported as
// ending early.

#include "capsim/scene/parser.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>
#include <string_view>

#include "capsim/scene/scene.h"
#include "support/cli_run.h"

namespace capsim {
namespace {

const std::string kFile = "t.csg";

// what() of the error parsing `text` gives, or "" if it parses.
std::string error_of(std::string_view text) {
  try {
    parse_scene(text, kFile);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

// Each line of `text`, without its message: "t.csg:LINE:COL".
std::vector<std::string> places(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(start, end - start);
    const std::size_t colon = line.find(": ");
    out.push_back(colon == std::string::npos ? line : line.substr(0, colon));
    start = end + 1;
  }
  return out;
}

TEST(ParserErrorList, EveryUnsupportedModuleIsNamedInFileOrder) {
  // The constructs of OpenSCAD's GEB example, as its CSG export nests them.
  const std::string text =
      "color(\"Ivory\") intersection() {\n"
      "  linear_extrude(height = 20) import_dxf(file = \"B.dxf\");\n"
      "  sphere(1);\n"
      "}\n"
      "translate([0, 0, -20]) linear_extrude(height = 1) difference() {\n"
      "  square(size = [40, 40], center = true);\n"
      "  children(0);\n"
      "}\n"
      "sphree(1);\n";
  const std::string what = error_of(text);
  EXPECT_EQ(places(what), (std::vector<std::string>{"t.csg:2:31", "t.csg:7:3", "t.csg:9:1"})) << what;
  EXPECT_NE(what.find("t.csg:2:31: 'import_dxf' is not supported"), std::string::npos) << what;
  EXPECT_NE(what.find("t.csg:9:1: unknown module 'sphree' (did you mean 'sphere'?)"), std::string::npos) << what;
  // The error's own place and message are the first's.
  try {
    parse_scene(text, kFile);
  } catch (const SceneError& e) {
    EXPECT_EQ(e.loc().line, 2);
    EXPECT_EQ(e.loc().col, 31);
    EXPECT_EQ(e.message().rfind("'import_dxf' is not supported", 0), 0u) << e.message();
  }
}

TEST(ParserErrorList, AnotherErrorAfterThemEndsTheList) {
  const std::string what = error_of("children(0);\nchildren(1);\nsphere(r = -1);\ncircle(1);\n");
  const std::vector<std::string> at = places(what);
  ASSERT_EQ(at.size(), 3u) << what;
  EXPECT_EQ(at[0], "t.csg:1:1");
  EXPECT_EQ(at[1], "t.csg:2:1");
  EXPECT_EQ(at[2].rfind("t.csg:3:", 0), 0u) << what;  // the bad radius; circle() is not reached
  EXPECT_EQ(what.find("t.csg:4:"), std::string::npos) << what;
}

TEST(ParserErrorList, AnErrorBeforeThemIsTheOnlyOne) {
  const std::string what = error_of("sphere(r = -1);\nchildren(0);\n");
  EXPECT_EQ(places(what).size(), 1u) << what;
  EXPECT_EQ(what.rfind("t.csg:1:", 0), 0u) << what;
}

TEST(ParserErrorList, TheListStopsAtFiftyAndCountsTheRest) {
  std::string text;
  for (int i = 0; i < 53; ++i) text += "children(0);\n";
  const std::string what = error_of(text);
  const std::vector<std::string> at = places(what);
  ASSERT_EQ(at.size(), kMaxListedSceneErrors + 1) << what;
  EXPECT_EQ(at[49], "t.csg:50:1");
  EXPECT_EQ(at[50], "and 3 more errors");
}

// ---------------------------------------------------------------- truncation

TEST(ParserTruncated, ACutShortFileSaysItEndsEarly) {
  EXPECT_EQ(error_of("cylinder(h = 2, r1 = 1, cen"), "t.csg:1:28: unexpected end of file after 'cen'");
  EXPECT_EQ(error_of("cylinder(h"), "t.csg:1:11: unexpected end of file after 'h'");
  EXPECT_EQ(error_of("cube(size = [1, 2"),
            "t.csg:1:18: unexpected end of file: missing ']': expected ',' or ']'");
  EXPECT_EQ(error_of("sphere(r = 1"), "t.csg:1:13: unexpected end of file: missing ')': expected ',' or ')'");
  EXPECT_EQ(error_of("sphere(r = -"), "t.csg:1:13: unexpected end of file: expected a value");
  EXPECT_EQ(error_of("sphere"), "t.csg:1:7: unexpected end of file: expected '(' after 'sphere'");
  // A name that is not the last token is still what it is.
  EXPECT_EQ(error_of("cube(h);"), "t.csg:1:6: unknown variable 'h': expressions may use only $t (the animation time) and PI");
}

// Every prefix of a real scene either parses (a cut between statements) or
// says the file ends early, except a cut inside a string or a comment, which
// the lexer reports as unterminated, and a cut between the two '/' of a
// comment, which leaves a '/' where a statement should start; none is taken
// for an unknown name.
TEST(ParserTruncated, EveryCutOfARealSceneSaysTheFileEnds) {
  const std::string text = testing::read_file(std::string(CAPSIM_SOURCE_DIR) + "/scenes/balls.csg");
  ASSERT_GT(text.size(), 1000u);
  int refused = 0;
  for (std::size_t n = 1; n < text.size(); ++n) {
    const std::string what = error_of(std::string_view(text).substr(0, n));
    if (what.empty()) continue;
    ++refused;
    const bool ends_early = what.find("unexpected end of file") != std::string::npos;
    const bool unterminated = what.find("unterminated") != std::string::npos;
    const bool no_objects = what.find("no objects") != std::string::npos;  // cut in the header
    const bool half_comment = text.compare(n - 1, 2, "//") == 0 && what.find("got '/'") != std::string::npos;
    EXPECT_TRUE(ends_early || unterminated || no_objects || half_comment) << "cut at " << n << ": " << what;
    EXPECT_EQ(what.find("unknown"), std::string::npos) << "cut at " << n << ": " << what;
  }
  EXPECT_GT(refused, 8000);
}

}  // namespace
}  // namespace capsim
