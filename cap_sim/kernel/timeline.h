#pragma once
// The simulation's timeline as the machine records it: spans of simulated time
// on named tracks (the host, the bus, every cell, every link direction that
// carried a message). The report writes it out (report/chrome_trace.h).

#include "kernel/cycles.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace capsim::sim {

// What a span shows. The trace JSON writes its name as the event's "cat", and
// the HTML page colours spans by that name alone.
enum class SpanCategory : std::uint8_t {
  Compute,    // a program's own work: tracing, voxel generation
  Subdivide,  // a cell's antialiasing phase 3, apart from its corner tracing just before
  Broadcast,  // a transfer to every cell over the command bus
  Receive,    // a cell taking in a broadcast
  Message,    // a transfer to one receiver, over the bus or the links
  Wait,       // a program waiting: for the host, the bus, corners, the cells
  Link,       // a message's bits on one link
};

// The one table of categories: each value and its name in the trace JSON, in
// the enum's order.
struct SpanCategoryName {
  SpanCategory category;
  std::string_view name;
};
inline constexpr SpanCategoryName kSpanCategories[] = {
    {SpanCategory::Compute, "compute"}, {SpanCategory::Subdivide, "subdivide"},
    {SpanCategory::Broadcast, "broadcast"}, {SpanCategory::Receive, "receive"},
    {SpanCategory::Message, "message"}, {SpanCategory::Wait, "wait"},
    {SpanCategory::Link, "link"},
};

constexpr std::string_view to_string(SpanCategory c) { return kSpanCategories[static_cast<std::size_t>(c)].name; }

struct TimelineSpan {
  int track = 0;
  std::string name;
  SpanCategory category = SpanCategory::Compute;
  Cycles begin;
  Cycles end;
  std::uint64_t bytes = 0;  // for transfers; 0 = not a transfer

  bool operator==(const TimelineSpan&) const = default;
};

class Timeline {
 public:
  // Tracks are numbered in the order they are added; that is their display order.
  int add_track(std::string name);
  void span(int track, std::string name, SpanCategory category, Cycles begin, Cycles end, std::uint64_t bytes = 0);

  const std::vector<TimelineSpan>& spans() const { return spans_; }
  const std::vector<std::string>& tracks() const { return tracks_; }

  bool operator==(const Timeline&) const = default;

 private:
  std::vector<std::string> tracks_;
  std::vector<TimelineSpan> spans_;
};

}  // namespace capsim::sim
