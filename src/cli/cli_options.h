#pragma once
// Options shared by `capsim render` and `capsim simulate`: the scene, the output
// image, the image size, the grid, host threads and primary-only tracing.

#include "capsim/antialias.h"
#include "capsim/prepared_scene.h"
#include "capsim/tracer.h"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace capsim::cli {

// --threads accepts 0 to this; more than the host's hardware threads run as
// many as it has (see host_arena_concurrency).
inline constexpr int kMaxThreadsOption = 1024;

// --frames accepts 1 to this: frame numbers keep OpenSCAD's five digits
// (out00000.png ... out99999.png).
inline constexpr int kMaxFramesOption = 99999;

// The options as typed; check_tracer_options turns them into settings.
struct TracerOptions {
  std::vector<std::string> scenes;  // one scene, or the frames of a sequence
  std::string frames;               // --frames K; empty = not given
  std::string output;
  std::string size;           // "WxH"; empty = the scene camera's size
  std::string grid = "auto";  // divisions per axis, or "auto"
  std::string threads = "0";  // 0 = all hardware threads
  std::string max_memory;     // e.g. "8G"; empty = what the machine and process limits leave
  bool primary_only = false;
  std::string aa = "0";              // antialiasing levels
  std::string aa_threshold = "0.3";  // colour difference that splits a square
};

// The options checked and parsed.
struct TracerSettings {
  std::vector<std::string> scenes;
  // Frames of the run: the scene files' count, or --frames K, which evaluates
  // the one scene file at $t = k / K for k = 0 .. K-1.
  int frames = 1;
  bool animate = false;  // --frames given
  // Outputs numbered as OpenSCAD numbers them (out00000.png, ...): for a
  // sequence of files and for any --frames.
  bool numbered_outputs() const { return animate || frames > 1; }
  std::string output;
  PrepareOptions prepare;  // size (0x0 = the scene camera's) and grid (0 = auto)
  int threads = 0;
  std::uint64_t max_memory = 0;  // 0 = process_memory_limits()
  TraceOptions trace;
  AntialiasOptions aa;
};

// The memory a command's image buffers take for `frames` frames of an image size.
using MemoryNeed = std::function<std::uint64_t(ImageSize, int frames)>;

// Registers the shared options on a subcommand, each with its help text.
void add_tracer_options(CLI::App& cmd, TracerOptions& o);

// Throws UsageError naming the first option that is missing or out of range.
TracerSettings check_tracer_options(const TracerOptions& o);

// A whole number in [lo, hi] for an option; throws UsageError otherwise.
int parse_whole_option(const std::string& option, const std::string& value, int lo, int hi);

// A number in [lo, hi] for an option; throws UsageError otherwise.
double parse_number_option(const std::string& option, const std::string& value, double lo, double hi);

// Two whole numbers in [1, max] written "AxB", for an option (--size, --cells)
// whose form is named `form` ("WxH"); throws UsageError otherwise.
std::pair<int, int> parse_pair_option(const std::string& option, const std::string& value,
                                      const std::string& form, int max);

// Parses the scene files and builds their grids; throws SceneError for scene
// problems. Between the two, once the image size is known (it may come from
// the first scene's camera), refuses with UsageError an image whose buffers
// would need more memory than --max-memory or, by default, the process's
// limits. Several files, or --frames, are the frames of one sequence: every
// frame gets the first one's image size, and frames without a camera statement
// share the camera that frames all of them (frame_sequence).
std::vector<PreparedScene> load_scenes(const TracerSettings& s, const MemoryNeed& need);

// The value of $t in frame k of an animation of `frames` frames, computed as
// OpenSCAD's --animate computes it: k * (1.0 / frames).
double animation_time(int k, int frames);

// The file frame k is written to: `output` itself when not numbered, else
// OpenSCAD's numbering before the extension (out.png -> out00000.png, ...).
std::string frame_output(const std::string& output, int k, bool numbered);
// The name its staged output goes by in messages: "--output", or when
// numbered "--output (frame k)".
std::string frame_output_option(int k, bool numbered);

}  // namespace capsim::cli
