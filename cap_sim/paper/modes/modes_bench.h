#pragma once
// Regression benchmarks of the pixel modes (`capsim bench modes`,
// docs/benchmarks.md): every shipped model in block, line and dot mode, and
// balanced on demand and stealing (docs/balancing.md), on 4x4, 4x8, 8x8 and 16x16 cells,
// plain and antialiased, with the simulated figures that matter for them. Simulated cycles are deterministic, so a
// stored baseline is compared exactly: any change is a regression or an
// intended change to be recorded.

#include "paper/experiment_run.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <vector>

namespace capsim::sim {

struct ModesBenchOptions {
  int width = 512, height = 512;
  int threads = 0;
  std::string scenes_dir = "scenes";
  std::function<void(const std::string&)> log;  // before each run; may be empty
};

// The models, as paths under the scenes directory, and the matrix.
const std::vector<std::string>& modes_bench_models();  // "balls.csg", ..., "disb/f00000.csg"
const std::vector<CellGrid>& modes_bench_grids();       // 4x4, 4x8, 8x8, 16x16
const std::vector<int>& modes_bench_aa_depths();        // 0 (plain) and 2
// How the runs share the screen: the three pixel modes (static, the paper's),
// demand at its default tile and stealing at its default chunk from dot mode.
const std::vector<std::string>& modes_bench_schemes();  // "block", "line", "dot", "demand:64", "steal:16"

struct ModeRun {
  std::string model;  // the file's name without .csg ("balls", "disb/f00000")
  PixelMode mode = PixelMode::Dot;  // static runs'; demand runs keep the default, steal runs start from dot
  BalanceOptions balance;
  CellGrid cells;
  int aa_depth = 0;
  RunFigures figures;
  double speedup = 0;  // the same model, scheme and antialiasing on 4x4 cells over this

  // The mode's name when static, else the balance scheme's ("demand:64").
  std::string scheme() const;
};

struct ModesBench {
  ModesBenchOptions options;
  std::vector<ModeRun> runs;  // model, then antialiasing, then scheme, then grid
};

ModesBench run_modes_bench(const ModesBenchOptions& options);

// The results as JSON (the baseline format, docs/benchmarks.md: a static
// run has a "mode", a demand or steal run a "balance" and its balancing
// figures), as a
// table for people, and as an SVG plot (d and speed-up against the cell count).
nlohmann::json modes_bench_json(const ModesBench& b);
std::string modes_bench_table(const ModesBench& b);
std::string modes_bench_svg(const ModesBench& b);

// A figure that differs between a baseline and a run (or a run only one has).
struct MovedFigure {
  std::string run;     // "balls dot 8x8 aa0", "balls demand:64 8x8 aa0"
  std::string metric;  // "frame_cycles", ..., or "(run)" when the run is in one only
  std::string old_value, new_value;
  double ratio = 0;  // new / old; 0 when not both numbers
};
// Every difference, in the baseline's order (then the new runs). Throws
// std::runtime_error when the two are for different screens or profiles.
std::vector<MovedFigure> compare_modes_bench(const nlohmann::json& baseline, const nlohmann::json& now);
std::string format_moved(const std::vector<MovedFigure>& moved);

}  // namespace capsim::sim
