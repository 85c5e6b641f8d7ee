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
#include "report/provenance.h"

#include <optional>
#include <string>
#include <vector>

namespace capsim::sim {

// What the page says about the run beyond the simulation's result.
struct RunFacts {
  std::vector<std::string> scenes;  // the scene files as given
  std::string command;  // the command line that ran it
  // The host's wall time for the run, in seconds; negative: not measured. The
  // only part of the page that changes from one run to the next.
  double host_seconds = -1;
  std::string version;  // capsim's
  // Given, the page shows it and its report data carries it, as --report does.
  std::optional<Provenance> provenance;
};

// What the page's title and heading call the run: the scene file's name
// ("balls.csg"); for --frames K, "model.scad (K frames)"; for a sequence of
// files, the first and last "f00000.csg ... f00003.csg (4 frames)".
std::string run_name(const std::vector<std::string>& scenes, std::size_t frames);

// Precondition: r was run with MachineConfig::completion_cycles.
std::string html_report(const SimulationResult& r, const RunFacts& facts);

}  // namespace capsim::sim
