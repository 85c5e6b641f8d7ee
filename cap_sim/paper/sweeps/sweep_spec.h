#pragma once
// A design-space sweep's file (`capsim sweep`, docs/sweeps.md): the axes, each
// a list of values, and their cross product, the points, each one run of
// `capsim simulate`. The file is checked whole before any point runs.

#include "machine/parts/balance.h"
#include "machine/parts/cell_grid.h"
#include "machine/parts/voxel_shares.h"
#include "machine/parts/window_controller.h"

#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>
#include <vector>

namespace capsim::sim {

// "FILE: PATH: message", PATH the JSON path of the bad value (axes.cells[2]).
class SweepSpecError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A scene of the scenes axis: one file, a sequence of files, or one file
// animated over `frames` frames. Paths are resolved against the sweep file's
// directory; `written` is the value as the file gives it, which records name.
struct SweepScene {
  std::vector<std::string> files;
  int frames = 0;  // {"scene": ..., "frames": K}: K; 0 otherwise
  nlohmann::json written;
};

struct SweepPoint {
  SweepScene scene;
  CellGrid cells{8, 8};
  PixelMode mode = PixelMode::Dot;  // static points'; a demand point's tiles decide what a cell shows
  BalanceOptions balance;
  int aa_depth = 0;
  std::string profile = "cap";       // as written
  std::string profile_path = "cap";  // a built-in's name, or the file resolved
  int width = 0, height = 0;         // 0 x 0 = the scene camera's
  int grid = 0;                      // 0 = auto
  bool primary_only = false;
  bool frame_average = false;
  VoxelGeneration voxel_generation = VoxelGeneration::Host;
};

// Points of the cross product that are left out, by why.
struct LeftOutPoints {
  int frame_average_outside_dot = 0;  // the dot pattern turns only in dot mode
  int frame_average_balanced = 0;     // demand and steal share one frame's work at a time
  int demand_per_mode = 0;            // demand takes no mode: one point stands for every mode
  int total() const { return frame_average_outside_dot + frame_average_balanced + demand_per_mode; }
  // "3 left out: 1 frame_average outside dot mode, 2 demand points repeated
  // per mode"; empty when none is.
  std::string summary() const;
};

struct SweepSpec {
  std::vector<SweepPoint> points;  // the cross product, in order
  LeftOutPoints left_out;
};

// The points of a sweep file's text. Axes vary in the order scenes, sizes,
// profiles, grid, primary_only, aa, frame_average, balance, modes, cells, the
// last fastest (the cell counts a speed-up compares are neighbours); a missing
// axis takes simulate's default. Points simulate would refuse (frame_average
// outside dot mode, on demand or stealing) are left out, and so are the repeats of a
// demand point over the modes axis: it is kept at the axis's first mode and
// recorded with the mode "tiles". Throws SweepSpecError naming `file` and the
// value at fault.
SweepSpec parse_sweep_spec(const std::string& text, const std::string& file);
// The same, reading the file.
SweepSpec read_sweep_spec(const std::string& file);
// The file's text; throws SweepSpecError when it cannot be read.
std::string read_sweep_text(const std::string& file);

// A point's inputs as its record gives them.
nlohmann::json sweep_inputs(const SweepPoint& p);

}  // namespace capsim::sim
