#pragma once
// The reports of a simulated frame: a table for people (stdout) and JSON for
// scripts (--report). Both give per-cell times, the paper's Table 4-4 figures
// (Max, Min, d over the cells' finish times) and Table 4-3's breakdown by process.
// docs/simulation.md documents every field.

#include "machine.h"

#include <nlohmann/json.hpp>

#include <string>

namespace capsim::sim {

struct LoadSpread {
  Cycles max_finish, min_finish;
  double deviation_percent = 0;  // (max - min) / max x 100; 0 if max is 0
};
LoadSpread load_spread(const SimulationResult& r);

// The neighbour links' traffic over a frame (antialiasing's corner exchange).
struct LinkTotals {
  std::uint64_t messages = 0, bytes = 0;
  std::uint64_t hops = 0;  // link crossings, summed over the messages
  int max_hops = 0;
  Cycles busiest;       // the most cycles one link direction carried bits
  Cycles longest_wait;  // the longest a message waited for a link
};
LinkTotals link_totals(const SimulationResult& r);

std::string format_report(const SimulationResult& r);
nlohmann::json report_json(const SimulationResult& r);

}  // namespace capsim::sim
