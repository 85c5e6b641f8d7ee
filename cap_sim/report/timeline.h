#pragma once
// The simulation's timeline: spans of simulated time on named tracks (the host,
// the bus, every cell), written as Chrome trace-event JSON (opens in Perfetto,
// ui.perfetto.dev, and chrome://tracing). Times are simulated microseconds;
// every span also carries its exact cycles in "args".

#include "cycles.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace capsim::sim {

struct TimelineSpan {
  int track = 0;
  std::string name;
  std::string category;  // "compute", "broadcast", "message", "wait", "receive"
  Cycles begin;
  Cycles end;
  std::uint64_t bytes = 0;  // for transfers; 0 = not a transfer
};

class Timeline {
 public:
  // Tracks are numbered in the order they are added; that is their display order.
  int add_track(std::string name);
  void span(int track, std::string name, std::string category, Cycles begin, Cycles end,
            std::uint64_t bytes = 0);

  const std::vector<TimelineSpan>& spans() const { return spans_; }
  const std::vector<std::string>& tracks() const { return tracks_; }

  // {"displayTimeUnit": "ms", "traceEvents": [...]}: metadata naming the process and
  // each track, then one complete ("X") event per span, in recording order.
  nlohmann::json to_chrome_trace(const std::string& process_name, std::uint64_t clock_hz) const;

 private:
  std::vector<std::string> tracks_;
  std::vector<TimelineSpan> spans_;
};

}  // namespace capsim::sim
