#pragma once
// The mode-comparison page of `capsim bench modes --html` (docs/benchmarks.md):
// one self-contained HTML page comparing block, line and dot mode across the
// models and cell counts. A header with the screen, the profile, the number
// of runs and how the run compared with its baseline (the moved figures, old,
// new and new/old, when it did not match); a note on reading d and the
// speed-up as the paper uses them (Table 4-4, Graph 4-3); inline SVG plots:
// d and the speed-up of the plain frames for every model
// (modes_bench_svg), then per model d and the speed-up against the cell
// count for each mode, plain and antialiased; and one table of every run,
// plain HTML, which the page's script (cap_sim/report/html/modes.js) sorts by
// any column. Nothing on it comes from outside the page, and the same bench
// and outcome give the same bytes.

#include "paper/modes/modes_bench.h"

#include <string>
#include <vector>

namespace capsim::sim {

// How the run stood against its stored baseline.
struct BaselineOutcome {
  std::string path;               // the baseline file as named; empty when there is none
  bool rewritten = false;         // --update: the file now holds this run
  bool existed = true;            // false: there was none before (then rewritten: written now; else: the
                                  // run was not compared)
  std::string not_comparable;     // why the old baseline could not be compared (another screen or
                                  // profile); empty when it could
  std::vector<MovedFigure> moved;  // what differs from the old baseline, in compare_modes_bench's order
};

std::string modes_page(const ModesBench& b, const BaselineOutcome& baseline, const std::string& version);

}  // namespace capsim::sim
