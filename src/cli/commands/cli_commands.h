#pragma once
// The subcommands of the capsim command line. Each registers its options (with
// their help text) on the app and returns the function that runs it; that
// function returns the process exit status.

#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

namespace capsim::cli {

using Command = std::function<int()>;

Command add_render_command(CLI::App& app);
// argv: the command line as typed, which the run's provenance records.
Command add_simulate_command(CLI::App& app, const std::vector<std::string>& argv);
Command add_lattice_command(CLI::App& app);
Command add_repro_command(CLI::App& app);
Command add_calibrate_command(CLI::App& app);
Command add_bench_command(CLI::App& app);
Command add_sweep_command(CLI::App& app);

}  // namespace capsim::cli
