#pragma once
// One simulated run of an experiment, as `capsim simulate` would do it, with
// the figures the reproduction and the mode benchmarks report and the command
// line that repeats it.

#include "machine/machine.h"
#include "paper/lattice_scene.h"
#include "report/sim_report.h"

#include <optional>
#include <string>

namespace capsim::sim {

struct RunSpec {
  std::string scene;                    // a scene file, or empty for the lattice
  std::optional<LatticeShape> lattice;  // Table 4-2's lattice instead of a file
  int width = 512, height = 512;
  int grid = 0;  // divisions per axis; 0 = auto
  bool primary_only = false;
  CellGrid cells{8, 8};
  PixelMode mode = PixelMode::Dot;
  std::string profile = "cap";
  // The costs to run with instead of the named profile's (a calibration's
  // trial values); the command still names `profile`.
  std::optional<CostProfile> costs;
  int aa_depth = 0;
  BalanceOptions balance;  // static (the paper's) unless set
};

// What one cell did in a run: its operations and when its "done" reached the
// host (the calibration's Max and Min follow each cell's work).
struct CellWork {
  OpCounts ops;
  std::uint64_t pixels = 0;
  Cycles finish;
};

struct RunFigures {
  std::string command;  // the shell command that repeats the run
  CostProfile profile;  // the costs it ran with
  std::uint64_t clock_hz = 0;
  Cycles frame;  // the frame time: the last "done" at the host (= Max)
  LoadSpread spread;
  CostBreakdown breakdown;  // every cell's work and the host's voxel generation
  OpCounts ops;             // summed over the cells
  std::uint64_t pixels = 0; // written, summed over the cells
  VoxelGenCounts voxels;    // the host's
  std::vector<CellWork> cells;
  BusTotals bus;
  LinkTotals links;
  int grid_divisions = 0;  // as used (auto resolved)
  // Balanced on demand: the bus cycles held by balancing messages as a share
  // of the run (balance_bus_percent), and the cells' waits for an answer with
  // nothing to trace, summed; 0 statically.
  double balance_bus_percent = 0;
  Cycles tile_wait;
  // Stealing: the chunks cells took from their neighbours, and the bytes the
  // links carried for stealing; 0 otherwise.
  std::uint64_t chunks_stolen = 0, steal_link_bytes = 0;

  double seconds(Cycles c) const { return c.seconds(clock_hz); }
  double frame_seconds() const { return seconds(frame); }
  double category_seconds(CostCategory c) const { return seconds(breakdown[c]); }  // Table 4-3's row
  double total_seconds() const { return seconds(breakdown.total()); }
};

// The command line of a run, from the repository root: `capsim simulate`
// with only the options that differ from its defaults (simulate_command's
// NonDefaults form; a lattice is first written by `capsim lattice`). The
// screen goes to screen.png.
std::string run_command(const RunSpec& spec);

// The screen of the latest run traced ahead, for the next runs that trace the
// same pixels: the same scene (file or lattice), size, grid, primary_only and
// antialiasing, whatever their cells, mode, balance and costs. The mode
// benchmarks run twenty such in a row; one kept trace (ScreenTrace) spares
// tracing each again.
class ScreenTraces {
 public:
  ScreenTraces();
  ~ScreenTraces();
  // The trace for spec, traced now unless it is the one kept.
  const ScreenTrace& trace(const RunSpec& spec, int threads);

 private:
  struct Kept;
  std::unique_ptr<Kept> kept_;
};

// Runs it. threads: host threads (0 = all); the figures do not depend on it,
// nor on whether `traces` (may be null) held its screen already.
RunFigures run_experiment(const RunSpec& spec, int threads, ScreenTraces* traces = nullptr);

// Runs it from a screen traced ahead. Precondition: `screen` is the trace
// ScreenTraces::trace gives for spec (the same scene, size, grid,
// primary_only and antialiasing). It only reads the screen, so runs of one
// screen may go at once on different threads.
RunFigures run_experiment(const RunSpec& spec, int threads, const ScreenTrace& screen);

}  // namespace capsim::sim
