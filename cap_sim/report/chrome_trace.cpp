#include "report/chrome_trace.h"

namespace capsim::sim {

nlohmann::json chrome_trace(const Timeline& timeline, const std::string& process_name, std::uint64_t clock_hz) {
  using nlohmann::json;
  const double us_per_cycle = 1e6 / static_cast<double>(clock_hz);
  json events = json::array();
  events.push_back({{"name", "process_name"}, {"ph", "M"}, {"pid", 1}, {"tid", 0},
                    {"args", {{"name", process_name}}}});
  const std::vector<std::string>& tracks = timeline.tracks();
  for (std::size_t t = 0; t < tracks.size(); ++t) {
    events.push_back({{"name", "thread_name"}, {"ph", "M"}, {"pid", 1}, {"tid", t},
                      {"args", {{"name", tracks[t]}}}});
    events.push_back({{"name", "thread_sort_index"}, {"ph", "M"}, {"pid", 1}, {"tid", t},
                      {"args", {{"sort_index", t}}}});
  }
  for (const TimelineSpan& s : timeline.spans()) {
    json args = {{"begin_cycles", s.begin.count()}, {"end_cycles", s.end.count()}};
    if (s.bytes) args["bytes"] = s.bytes;
    events.push_back({{"name", s.name},
                      {"cat", std::string(to_string(s.category))},
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
