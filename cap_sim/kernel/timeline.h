#pragma once
// The simulation's timeline as the machine records it: spans of simulated time
// on named tracks (the host, the bus, every cell, every link direction that
// carried a message). The report writes it out (report/chrome_trace.h).

#include "kernel/cycles.h"

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

  bool operator==(const TimelineSpan&) const = default;
};

class Timeline {
 public:
  // Tracks are numbered in the order they are added; that is their display order.
  int add_track(std::string name);
  void span(int track, std::string name, std::string category, Cycles begin, Cycles end,
            std::uint64_t bytes = 0);

  const std::vector<TimelineSpan>& spans() const { return spans_; }
  const std::vector<std::string>& tracks() const { return tracks_; }

  bool operator==(const Timeline&) const = default;

 private:
  std::vector<std::string> tracks_;
  std::vector<TimelineSpan> spans_;
};

}  // namespace capsim::sim
