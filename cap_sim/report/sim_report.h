#pragma once
// The reports of a simulated frame: a table for people (stdout) and JSON for
// scripts (--report). Both give per-cell times, the paper's Table 4-4 figures
// (Max, Min, d over the cells' finish times) and Table 4-3's breakdown by process.
// docs/simulation.md documents every field.

#include "machine/machine.h"
#include "machine/run_figures.h"

#include <nlohmann/json.hpp>

#include <string>

namespace capsim::sim {

std::string format_report(const SimulationResult& r);
// The lines of format_report that say what the run came to (what --quiet
// prints): the header's first line; Max, Min and d over the finish times and
// over busy time; the frame time; for a sequence, the Table 4-5 form.
std::string format_summary(const SimulationResult& r);
nlohmann::json report_json(const SimulationResult& r);
// The text --report writes: report_json indented by 2, and a newline.
std::string report_json_text(const SimulationResult& r);

// The text --trace writes: the timeline as Chrome trace-event JSON, its process
// named after the grid, mode and profile.
std::string chrome_trace_text(const SimulationResult& r);

}  // namespace capsim::sim
