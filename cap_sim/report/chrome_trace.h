#pragma once
// The timeline as Chrome trace-event JSON (opens in Perfetto, ui.perfetto.dev,
// and chrome://tracing). Times are simulated microseconds; every span also
// carries its exact cycles in "args".

#include "kernel/timeline.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>

namespace capsim::sim {

// {"displayTimeUnit": "ms", "traceEvents": [...]}: metadata naming the process and
// each track, then one complete ("X") event per span, in recording order.
nlohmann::json chrome_trace(const Timeline& timeline, const std::string& process_name, std::uint64_t clock_hz);

}  // namespace capsim::sim
