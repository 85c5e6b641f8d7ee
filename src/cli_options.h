#pragma once
// Options shared by `capsim render` and `capsim simulate`: the scene, the output
// image, the image size, the grid, host threads and primary-only tracing.

#include "capsim/antialias.h"
#include "capsim/prepared_scene.h"
#include "capsim/tracer.h"

#include <CLI/CLI.hpp>

#include <string>

namespace capsim::cli {

struct TracerOptions {
  std::string scene;
  std::string output;
  std::string size;         // "WxH"; empty = the scene camera's size
  std::string grid = "auto";  // divisions per axis, or "auto"
  int threads = 0;          // 0 = all hardware threads
  bool primary_only = false;
  int aa_depth = 0;          // antialiasing levels; 0 = one sample at each pixel centre
  double aa_threshold = 0.3;  // colour difference that splits a square
};

// Registers the shared options on a subcommand, each with its help text.
void add_tracer_options(CLI::App& cmd, TracerOptions& o);

// Parses the scene file and builds the grid; throws SceneError for scene
// problems and std::invalid_argument for bad option values. Checks the output
// path first so that a bad -o fails before any work.
PreparedScene load_scene(const TracerOptions& o);

capsim::TraceOptions trace_options(const TracerOptions& o);
capsim::AntialiasOptions antialias_options(const TracerOptions& o);

}  // namespace capsim::cli
