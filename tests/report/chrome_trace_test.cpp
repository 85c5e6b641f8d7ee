// The timeline as Chrome trace-event JSON: each span's category by its name.

#include "report/chrome_trace.h"

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

}  // namespace
}  // namespace capsim::sim
