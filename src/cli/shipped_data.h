#pragma once
// Where the commands that read the shipped data (repro, calibrate and bench
// modes: the models of scenes/, the baselines of bench/baselines/) find it
// when no option names it, so that they run from any directory:
//
//   1. DIR/../share/capsim/scenes and .../baselines, DIR being the directory
//      of the running program (read from /proc/self/exe): an installed capsim
//      (`cmake --install build --prefix P` puts them under P/share/capsim;
//      "../share/capsim" is the data directory seen from the program's, as
//      CMAKE_INSTALL_BINDIR and CMAKE_INSTALL_DATADIR place them);
//   2. the source tree's scenes/ and bench/baselines/, when the running
//      program is the one in the build directory it was built in (CMake
//      gives this file both directories).
//
// An explicit --scenes DIR or --baseline FILE is used as given instead.

#include "cli/options/option_checks.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace capsim::cli {

enum class ShippedData { Scenes, Baselines };

// The directories searched, in order, whether or not they exist.
std::vector<std::filesystem::path> shipped_data_candidates(ShippedData what);

// The first candidate that is a directory, written relative to the current
// directory when it lies inside it (so that commands run from the
// repository root print `scenes/balls.csg` as they always have), else
// absolute; nullopt when none is.
std::optional<std::string> find_shipped_data(ShippedData what);

// Registers --scenes DIR on cmd: the directory of the models, checked by
// shipped_models_check.
void add_scenes_option(CLI::App& cmd, OptionText<>& scenes);

// The models' directory: the --scenes option's, checked, when given; else the
// one found. Throws UsageError naming where it looked when there is none.
std::string scenes_dir(const OptionText<>& scenes);

}  // namespace capsim::cli
