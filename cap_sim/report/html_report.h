#pragma once
// The HTML report of a run (--html): one page that holds the whole run and
// needs nothing beside it: the run's facts, the screen, the screen filling over
// simulated time, the cells' heat map and table, the load spread (Table 4-4),
// the timeline, the time by process (Table 4-3) and, for antialiasing and
// sequences, the phases, the link traffic and the per-frame spread (Table 4-5).
// docs/report.md describes every part.
//
// The page's data is the --report JSON and the --trace JSON, byte for byte,
// each in a <script type="application/json"> element (script_safe_json), plus
// the images as PNG data URIs and each frame's completion cycles
// (pack_completion_cycles). The essentials are plain HTML; the page's own
// script (cap_sim/report/html/report.js) adds the player, the heat maps' hover, the
// sortable table, the timeline and the charts.

#include "machine/machine.h"

#include <string>

namespace capsim::sim {

// What the page says about the run beyond the simulation's result.
struct RunFacts {
  std::string scene;    // the scene file as given
  std::string command;  // the command line that ran it
  // The host's wall time for the run, in seconds; negative: not measured. The
  // only part of the page that changes from one run to the next.
  double host_seconds = -1;
  std::string version;  // capsim's
};

// Precondition: r was run with MachineConfig::completion_cycles.
std::string html_report(const SimulationResult& r, const RunFacts& facts);

}  // namespace capsim::sim
