#include "timeline.h"

namespace capsim::sim {

int Timeline::add_track(std::string name) {
  tracks_.push_back(std::move(name));
  return static_cast<int>(tracks_.size()) - 1;
}

void Timeline::span(int track, std::string name, std::string category, Cycles begin, Cycles end,
                    std::uint64_t bytes) {
  spans_.push_back(TimelineSpan{track, std::move(name), std::move(category), begin, end, bytes});
}

nlohmann::json Timeline::to_chrome_trace(const std::string& process_name,
                                         std::uint64_t clock_hz) const {
  using nlohmann::json;
  const double us_per_cycle = 1e6 / static_cast<double>(clock_hz);
  json events = json::array();
  events.push_back({{"name", "process_name"}, {"ph", "M"}, {"pid", 1}, {"tid", 0},
                    {"args", {{"name", process_name}}}});
  for (std::size_t t = 0; t < tracks_.size(); ++t) {
    events.push_back({{"name", "thread_name"}, {"ph", "M"}, {"pid", 1}, {"tid", t},
                      {"args", {{"name", tracks_[t]}}}});
    events.push_back({{"name", "thread_sort_index"}, {"ph", "M"}, {"pid", 1}, {"tid", t},
                      {"args", {{"sort_index", t}}}});
  }
  for (const TimelineSpan& s : spans_) {
    json args = {{"begin_cycles", s.begin.count()}, {"end_cycles", s.end.count()}};
    if (s.bytes) args["bytes"] = s.bytes;
    events.push_back({{"name", s.name},
                      {"cat", s.category},
                      {"ph", "X"},
                      {"pid", 1},
                      {"tid", s.track},
                      {"ts", static_cast<double>(s.begin.count()) * us_per_cycle},
                      {"dur", static_cast<double>((s.end - s.begin).count()) * us_per_cycle},
                      {"args", args}});
  }
  return {{"displayTimeUnit", "ms"}, {"traceEvents", events}};
}

}  // namespace capsim::sim
