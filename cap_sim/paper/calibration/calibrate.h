#pragma once
// The calibration (`capsim calibrate`, docs/calibration.md): every experiment
// run, the fitted costs chosen by the joint fit over all published times, the
// experiments run again at those costs, and so on for a few rounds; the
// round whose runs meet the paper best wins. Runs, not the fit's linear
// model, decide: a Max is a different cell, or a cost rounds to whole cycles,
// once the costs move.

#include "paper/repro/published_figures.h"
#include "paper/repro/repro.h"

#include <functional>
#include <string>
#include <vector>

namespace capsim::sim {

struct CalibrationOptions {
  ReproOptions repro;  // screens, scenes, threads; its cap_costs / m380_costs are the start
  Exclusions exclusions = Exclusions::Table44ChessCad;
  int rounds = 3;  // fits, each followed by a run of every experiment
};

struct CalibrationRound {
  std::vector<double> x;      // the costs the round ran with (M380 microseconds, fit_parameters() order)
  double simulated_rms = 0;   // rms of ln(ours / paper) over the fitted times, from the runs
  double model_rms = 0;       // the fit's own prediction for its x (nothing for the start)
};

struct Calibration {
  std::vector<CalibrationRound> rounds;  // the start, then one per fit
  std::size_t best = 0;                  // the round with the least simulated_rms
  const std::vector<double>& x() const { return rounds[best].x; }
  std::vector<TableError> best_tables;   // per table, at the best round's runs
};

// Throws what the runs throw. log: progress lines, may be empty.
Calibration calibrate(const CalibrationOptions& options, const std::function<void(const std::string&)>& log);

// One alternative assumption and how well the calibration meets the paper
// with it.
struct Alternative {
  std::string name;
  CalibrationOptions options;
};
struct AlternativeResult {
  std::string name;
  Calibration calibration;
};
// The alternatives the calibration has been tried with: screens, Table 4-2
// primary rays only or not, which figures of the paper's contradictions are
// left out. base: the shipped choice.
std::vector<Alternative> calibration_alternatives(const CalibrationOptions& base);
// A Markdown table: per alternative the overall and per-table rms.
std::string alternatives_markdown(const std::vector<AlternativeResult>& results);

}  // namespace capsim::sim
