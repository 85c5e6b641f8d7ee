#pragma once
// The reports of a simulated frame: a table for people (stdout) and JSON for
// scripts (--report). Both give per-cell times, the paper's Table 4-4 figures
// (Max, Min, d over the cells' finish times) and Table 4-3's breakdown by process.
// docs/simulation.md documents every field.

#include "machine/machine.h"
#include "machine/run_figures.h"
#include "report/provenance.h"

#include <nlohmann/json.hpp>

#include <string>

namespace capsim::sim {

// With a provenance, the text ends with its block (provenance_text) and the
// JSON carries it as "provenance".
std::string format_report(const SimulationResult& r, const Provenance* provenance = nullptr);
// The lines of format_report that say what the run came to (what --quiet
// prints): the header's first line; Max, Min and d over the finish times and
// over busy time; the frame time (a sequence's per frame and in all); for a
// sequence, the Table 4-5 form.
std::string format_summary(const SimulationResult& r);
nlohmann::json report_json(const SimulationResult& r, const Provenance* provenance = nullptr);
// The text --report writes: report_json indented by 2, and a newline.
std::string report_json_text(const SimulationResult& r, const Provenance* provenance = nullptr);

// A sequence's simulated time: the whole run's, and its mean per frame and,
// frame averaged, per group of frames (the cells run through a group without
// waiting for each other).
struct SequenceTime {
  std::size_t frames = 0;
  std::size_t groups = 0;  // frame averaged; 0 otherwise
  double total_seconds = 0;
  double frame_seconds = 0;  // total / frames
  double group_seconds = 0;  // total / groups; 0 without groups
};
SequenceTime sequence_time(const SimulationResult& r);
// "frames: 4, time per frame (mean) 13.706 s, total 54.825 s", or frame
// averaged "frames: 16 in 2 groups, time per group (mean) ..., per frame
// (mean) ..., total ...": how the reports label a sequence's time.
std::string sequence_time_text(const SimulationResult& r);

// The text --trace writes: the timeline as Chrome trace-event JSON, its process
// named after the grid, mode and profile.
std::string chrome_trace_text(const SimulationResult& r);

}  // namespace capsim::sim
