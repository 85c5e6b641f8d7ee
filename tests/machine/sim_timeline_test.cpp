// The timeline's span categories: one table, in the enum's order.

#include "kernel/timeline.h"

#include <gtest/gtest.h>

#include <set>
#include <string_view>

namespace capsim::sim {
namespace {

TEST(SpanCategories, TheTableNamesEveryCategoryOnceInTheEnumsOrder) {
  std::set<std::string_view> names;
  for (std::size_t i = 0; i < std::size(kSpanCategories); ++i) {
    EXPECT_EQ(static_cast<std::size_t>(kSpanCategories[i].category), i);
    EXPECT_EQ(to_string(kSpanCategories[i].category), kSpanCategories[i].name);
    EXPECT_FALSE(kSpanCategories[i].name.empty());
    names.insert(kSpanCategories[i].name);
  }
  EXPECT_EQ(names.size(), std::size(kSpanCategories));
  EXPECT_EQ(to_string(SpanCategory::Compute), "compute");
  EXPECT_EQ(to_string(SpanCategory::Link), "link");
}

TEST(Timeline, KeepsSpansInRecordingOrderOnTracksInTheOrderAdded) {
  Timeline t;
  EXPECT_EQ(t.add_track("host"), 0);
  EXPECT_EQ(t.add_track("cell[0,0]"), 1);
  t.span(1, "trace 4 pixels", SpanCategory::Compute, Cycles(5), Cycles(9));
  t.span(0, "broadcast scene", SpanCategory::Broadcast, Cycles(0), Cycles(5), 100);
  ASSERT_EQ(t.spans().size(), 2u);
  EXPECT_EQ(t.spans()[0], (TimelineSpan{1, "trace 4 pixels", SpanCategory::Compute, Cycles(5), Cycles(9), 0}));
  EXPECT_EQ(t.spans()[1], (TimelineSpan{0, "broadcast scene", SpanCategory::Broadcast, Cycles(0), Cycles(5), 100}));
}

}  // namespace
}  // namespace capsim::sim
