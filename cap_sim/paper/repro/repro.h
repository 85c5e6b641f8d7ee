#pragma once
// The paper's experiments, run on the simulated machines and set beside the
// published figures (`capsim repro`, docs/reproduction.md): Tables 4-2, 4-3,
// 4-4, 4-5 and 5-1 and Graph 4-3, with the costs the calibration fitted to
// them (paper/calibrate.h).

#include "paper/calibration/calibration.h"
#include "paper/experiment_run.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace capsim::sim {

// Table 4-5's screen: DISB is laid out for 384 x 384 (scenes/disb.scad puts its
// edges on chosen pixel rows and columns), so its runs use it at any --size.
inline constexpr int kDisbSide = 384;

struct ReproOptions {
  // The screens: the paper never gives them (docs/calibration.md chooses
  // them by the fit's error). The CAP's runs (Tables 4-4, 4-5 and 5-1, Graph
  // 4-3; Table 4-5's is kDisbSide) and the M380's (Tables 4-2, 4-3 and 5-1).
  int width = 384, height = 384;
  int m380_width = 512, m380_height = 512;
  // Whether Table 4-2 traced primary rays only (the paper does not say).
  bool table_4_2_primary_only = false;
  // The costs to run with instead of the shipped profiles (a calibration's
  // trial); the commands still name the profiles.
  std::optional<CostProfile> cap_costs, m380_costs;
  int threads = 0;                // host threads; the figures do not depend on them
  std::string scenes_dir = "scenes";
  int table_4_5_frames = 64;  // DISB frames run for Table 4-5 (0: not run)
  // Called before each run with what it is; may be empty.
  std::function<void(const std::string&)> log;
};

struct Table42 {
  std::vector<LatticeShape> shapes;  // one per row
  RunFigures cells[5][7];            // [row][divisions column]
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
  // What the calibration needs of it: every cell's operations and busy time
  // summed, and the host's voxel generation, at `profile`'s costs.
  CostProfile profile;
  int cells = 0;
  WorkCounts cell_work;
  double busy_seconds = 0;
  VoxelGenCounts voxels;
  double voxel_generation_seconds = 0;
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

// Table 4-2 alone: its 35 runs.
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
