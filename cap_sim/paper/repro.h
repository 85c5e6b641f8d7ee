#pragma once
// The paper's experiments, run on the simulated machines and set beside the
// published figures (`capsim repro`, docs/reproduction.md): Tables 4-2, 4-3,
// 4-4, 4-5 and 5-1 and Graph 4-3, and the fit of the cost constants to Table
// 4-2.

#include "paper/calibration_fit.h"
#include "paper/experiment_run.h"

#include <functional>
#include <string>
#include <vector>

namespace capsim::sim {

// Table 4-5's screen: DISB is laid out for 384 x 384 (scenes/disb.scad puts its
// edges on chosen pixel rows and columns), so its runs use it at any --size.
inline constexpr int kDisbSide = 384;

struct ReproOptions {
  int width = 512, height = 512;  // every experiment's screen but Table 4-5's (kDisbSide)
  int threads = 0;                // host threads; the figures do not depend on them
  std::string scenes_dir = "scenes";
  int table_4_5_frames = 64;  // DISB frames run for Table 4-5 (0: not run)
  // Called before each run with what it is; may be empty.
  std::function<void(const std::string&)> log;
};

struct Table42 {
  std::vector<LatticeShape> shapes;  // one per row
  RunFigures cells[5][7];            // [row][divisions column]
  std::vector<FitCell> fit_cells;    // row by row
  FitResult as_shipped;              // the profile's own times
  FitResult shipped_fit;             // the costs the profile fits, fitted again
  FitResult full_fit;                // every fittable cost free
};

struct Table43 {
  RunFigures runs[3];  // PISTON at 2, 16, 32 divisions
};

struct ModeSpread {
  RunFigures line, dot;
};
struct Table44 {
  ModeSpread rows[3];  // BALLS, CHESS, CAD on 8x8 cells
};

struct Graph43 {
  std::vector<CellGrid> grids;         // 4x4, 4x8, 8x8
  std::vector<RunFigures> line, dot;  // CHESS, per grid
};

struct Table45Run {
  std::string command;
  Cycles frame;  // the last group's "done" at the host: the whole run
  double seconds = 0;
  double max_deviation_percent = 0;
};
struct Table45 {
  int frames = 0;  // 0: not run
  int frames_per_unit = 0;  // frame averaged: what a cell's memories hold (frames_per_unit)
  Table45Run runs[3];
};

struct Table51 {
  RunFigures cap[4], m380[4];  // CHESS, BALLS, PISTON, CAD
};

struct ReproResult {
  ReproOptions options;
  Table42 table_4_2;
  Table43 table_4_3;
  Table44 table_4_4;
  Graph43 graph_4_3;
  Table45 table_4_5;
  Table51 table_5_1;
};

// The costs the shipped profiles fit to Table 4-2 (docs/calibration.md says
// why these and not the others).
std::vector<CostTerm> shipped_fitted_costs();

// Table 4-2 alone: its 35 runs and the fits.
Table42 run_table_4_2(const ReproOptions& options);

// Runs every experiment. Throws what the runs throw (a missing scene file, say).
ReproResult run_reproduction(const ReproOptions& options);

// Table 4-2's derived figures for one row.
struct Table42Row {
  int best_column = 0;  // the fastest division count's column (the first of equals)
  double best_seconds = 0, speedup = 0;  // speed-up: 1 division / best
};
Table42Row table_4_2_row(const Table42& t, int row);            // ours
Table42Row table_4_2_paper_row(int row);                        // the paper's

// The targets, each met or missed, with what was measured.
struct TargetCheck {
  std::string target;
  std::string measured;
  bool met = false;
};
std::vector<TargetCheck> reproduction_targets(const ReproResult& r);

// The report: every table beside the paper's, ratios, commands, the fit and
// its residuals, the targets met or missed. images: the path of the plots
// relative to the report (written by the two functions below).
std::string reproduction_markdown(const ReproResult& r, const std::string& images);
std::string table_4_2_plot_svg(const ReproResult& r);
std::string graph_4_3_plot_svg(const ReproResult& r);

}  // namespace capsim::sim
