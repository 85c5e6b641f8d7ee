#include "kernel/timeline.h"

namespace capsim::sim {

int Timeline::add_track(std::string name) {
  tracks_.push_back(std::move(name));
  return static_cast<int>(tracks_.size()) - 1;
}

void Timeline::span(int track, std::string name, SpanCategory category, Cycles begin, Cycles end,
                    std::uint64_t bytes) {
  spans_.push_back(TimelineSpan{track, std::move(name), category, begin, end, bytes});
}

}  // namespace capsim::sim
