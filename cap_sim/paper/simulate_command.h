#pragma once
// The command line of one `capsim simulate` run, built from the run's
// settings: the HTML page of a run gives it with every option, the
// reproduction and the mode benchmarks print it with only the options that
// differ from the defaults, and a sweep can print its points the same way.

#include "capsim/trace/antialias.h"
#include "machine/parts/balance.h"
#include "machine/parts/cell_grid.h"
#include "machine/parts/voxel_shares.h"
#include "machine/parts/window_controller.h"

#include <string>
#include <vector>

namespace capsim::sim {

// A run's settings as `capsim simulate` takes them, with its defaults.
struct SimulateSettings {
  std::vector<std::string> scenes;  // scene files (or shell patterns): one, or the frames of a sequence
  std::string output;               // -o: the screen's image file
  int width = 0, height = 0;        // --size; 0 x 0 = the scene camera's (no --size written)
  int grid = 0;                     // --grid: voxel divisions per axis; 0 = auto
  CellGrid cells{8, 8};
  PixelMode mode = PixelMode::Dot;
  std::string profile = "cap";  // a built-in profile's name, or a profile file
  int frames = 0;               // --frames K: the one scene file animated; 0 = not given
  bool primary_only = false;
  AntialiasOptions aa;  // --aa and --aa-threshold
  bool frame_average = false;
  BalanceOptions balance;  // --balance, written only when not static
  VoxelGeneration voxel_generation = VoxelGeneration::Host;  // --voxel-generation, written only for cells
  int threads = 0;  // host threads; 0 = all hardware threads
  std::vector<std::string> defines;  // -D var=value for .scad input, in order
};

enum class CommandForm {
  EveryOption,  // every option that has a value (--grid auto, --cells 8x8, --threads 0, ...)
  NonDefaults,  // only the options whose values differ from the defaults
};

// "capsim simulate SCENES -o OUTPUT ..." for the run: --size when the
// settings give one, --frames when given, each flag that is set and, with
// antialiasing, its depth and threshold (the threshold in NonDefaults only if
// not the default), each -D in single quotes as a shell takes it verbatim;
// the other options as `form` asks; on demand (--balance demand:TILE) no
// --mode, which demand refuses.
std::string simulate_command(const SimulateSettings& settings, CommandForm form);

}  // namespace capsim::sim
