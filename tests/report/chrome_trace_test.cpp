// The timeline as Chrome trace-event JSON: each span's category by its name,
// and a colour for each in the HTML page's timeline.

#include "report/chrome_trace.h"
#include "report/html_assets.h"

#include <gtest/gtest.h>

namespace capsim::sim {
namespace {

TEST(ChromeTrace, WritesEachSpanWithItsCategorysName) {
  Timeline t;
  const int track = t.add_track("cell[0,0]");
  for (const SpanCategoryName& c : kSpanCategories) t.span(track, "span", c.category, Cycles(0), Cycles(10));
  const nlohmann::json trace = chrome_trace(t, "run", 1'000'000);
  std::vector<std::string> cats;
  for (const nlohmann::json& e : trace["traceEvents"])
    if (e["ph"] == "X") cats.push_back(e["cat"].get<std::string>());
  ASSERT_EQ(cats.size(), std::size(kSpanCategories));
  for (std::size_t i = 0; i < cats.size(); ++i) EXPECT_EQ(cats[i], kSpanCategories[i].name);
}

TEST(ChromeTrace, ThePagesTimelineHasAColourForEveryCategory) {
  // report.js colours a span by its "cat" alone, from its table of colours.
  const std::string_view script = html_assets().script;
  const std::size_t begin = script.find("const kCategoryColours = {");
  ASSERT_NE(begin, std::string_view::npos);
  const std::string_view table = script.substr(begin, script.find("};", begin) - begin);
  for (const SpanCategoryName& c : kSpanCategories)
    EXPECT_NE(table.find(std::string(c.name) + ": '#"), std::string_view::npos) << c.name;
}

}  // namespace
}  // namespace capsim::sim
