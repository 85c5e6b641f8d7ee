#pragma once
// Options shared by `capsim render` and `capsim simulate`: the scene, the output
// image, the image size, the grid, host threads and primary-only tracing.

#include "capsim/trace/antialias.h"
#include "capsim/trace/prepared_scene.h"
#include "capsim/trace/tracer.h"
#include "cli/options/openscad_options.h"
#include "cli/options/option_checks.h"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace capsim::cli {

class StageTimes;  // console.h

// --threads accepts 0 to this; more than the host's hardware threads run as
// many as it has (see host_arena_concurrency).
inline constexpr int kMaxThreadsOption = 1024;

// --frames accepts 1 to this: frame numbers keep OpenSCAD's five digits
// (out00000.png ... out99999.png).
inline constexpr int kMaxFramesOption = 99999;

// The options as typed, each registered with what it accepts;
// check_tracer_options checks them and turns them into settings.
struct TracerOptions {
  OptionText<std::vector<std::string>> scenes;  // one scene, or the frames of a sequence
  OptionText<> frames;                          // --frames K; empty = not given
  OptionText<> output;
  OptionText<> size;          // "WxH"; empty = the scene camera's size
  OptionText<> grid{"auto"};  // divisions per axis, or "auto"
  OptionText<> threads{"0"};  // 0 = all hardware threads
  OptionText<> max_memory;    // e.g. "8G"; empty = what the machine and process limits leave
  bool primary_only = false;
  OptionText<> aa{"0"};              // antialiasing levels
  OptionText<> aa_threshold{"0.3"};  // colour difference that splits a square
  OpenScadOptions openscad;          // OpenSCAD's view options
  bool verbose = false;              // print the camera each frame is seen by
  OptionText<std::vector<std::string>> defines;  // -D var=value, for OpenSCAD
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
  PrepareOptions prepare;  // size (0x0 = the scene camera's), grid (0 = auto), OpenSCAD's camera
  bool verbose = false;
  int threads = 0;
  std::uint64_t max_memory = 0;  // 0 = process_memory_limits()
  TraceOptions trace;
  AntialiasOptions aa;
  std::vector<std::string> defines;  // -D var=value, passed to openscad for .scad input
};

// The memory a command's image buffers take for `frames` frames of an image size.
using MemoryNeed = std::function<std::uint64_t(ImageSize, int frames)>;

// What --size and --threads accept, for every command that has them: an
// image size WxH and a host thread count.
CLI::Validator image_size_check();
CLI::Validator host_threads_check();

// What an image --output accepts: a path ending in .png or .exr.
CLI::Validator image_output_check();

// What --scenes accepts (repro, bench modes): the directory of the shipped
// models.
CLI::Validator shipped_models_check();

// A flag's values: none, or true or false.
CLI::Validator flag_values();

// Registers the shared options on a subcommand, each with its help text and
// what it accepts.
void add_tracer_options(CLI::App& cmd, TracerOptions& o);

// Throws UsageError naming the first option that is missing or out of range.
TracerSettings check_tracer_options(const TracerOptions& o);

// Parses the scene files and builds their grids; throws SceneError for scene
// problems. Between the two, once the image size is known (it may come from
// the first scene's camera), refuses with UsageError an image whose buffers
// would need more memory than --max-memory or, by default, the process's
// limits. Several files, or --frames, are the frames of one sequence: every
// frame gets the first one's image size, and frames without a camera statement
// share the camera that frames all of them (frame_sequence). `times`, if
// given, ends its stages "read" and "prepare".
std::vector<PreparedScene> load_scenes(const TracerSettings& s, const MemoryNeed& need,
                                       StageTimes* times = nullptr);

// With --verbose, the camera of each frame on stderr as OpenSCAD options
// ("camera: --camera=... --projection=..."): once when all frames share it.
void print_cameras(const TracerSettings& s, const std::vector<PreparedScene>& frames);

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
