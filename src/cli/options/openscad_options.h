#pragma once
// OpenSCAD 2021.01's view options as `capsim render` and `capsim simulate`
// take them, spelt as OpenSCAD spells them (docs/openscad.md): --camera,
// --viewall, --autocenter, --projection and --imgsize.

#include "capsim/trace/openscad_camera.h"
#include "cli/options/option_checks.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <utility>

namespace capsim::cli {

struct OpenScadOptions {
  OptionText<> camera;      // 6 or 7 numbers separated by commas; empty = not given
  OptionText<> projection;  // perspective, p, ortho, o, orthogonal; empty = not given
  OptionText<> imgsize;     // "W,H"; empty = not given
  bool viewall = false;
  bool autocenter = false;
};

void add_openscad_options(CLI::App& cmd, OpenScadOptions& o);

// The camera options, if any of --camera, --viewall, --autocenter or
// --projection is given (--imgsize alone only sizes the image); throws
// UsageError for a value they do not accept.
std::optional<OpenScadCameraOptions> check_openscad_camera(const OpenScadOptions& o);

// --imgsize's width and height, if given; throws UsageError for a bad value.
std::optional<std::pair<int, int>> check_imgsize(const OpenScadOptions& o);

}  // namespace capsim::cli
