// capsim: the Cellular Array Processor ray-tracing simulator.

#include "capsim/system/process_heap.h"
#include "capsim/system/temp_file_registry.h"
#include "cli/commands/cli_commands.h"
#include "cli/command_failure.h"
#include "cli/options/cli_usage.h"

#include <fmt/core.h>

#include <csignal>
#include <cstdio>
#include <exception>
#include <string>

namespace {

// An error message on stderr; a stderr that cannot take it has no better
// place to be told, so a failure to write it is let go.
void tell(const std::string& text) { std::fputs((text + "\n").c_str(), stderr); }

}  // namespace

int main(int argc, char** argv) {
  capsim::set_up_process_heap();
  capsim::remove_temp_files_on_signals();  // before TBB starts any thread
  // A reader of stdout that goes away (`capsim ... | head -1`) makes writes
  // fail with EPIPE rather than end the process: the outputs are still written
  // (cli/console.h), and an output that is stdout itself fails with a message.
  std::signal(SIGPIPE, SIG_IGN);
  CLI::App app{
      "capsim: a simulator of Fujitsu's Cellular Array Processor (CAP) running the CSG\n"
      "ray tracer of Murakami, Sato and Hirota. The model charges each operation's cost\n"
      "in integer cycles of the cell's clock inside an event-driven machine."};
  app.require_subcommand(0, 1);  // none is a usage error, reported below in capsim's words
  app.set_version_flag("--version", "capsim " CAPSIM_VERSION);  // the project version in CMakeLists.txt
  const capsim::cli::Command render = capsim::cli::add_render_command(app);
  const capsim::cli::Command simulate = capsim::cli::add_simulate_command(app, {argv, argv + argc});
  const capsim::cli::Command lattice = capsim::cli::add_lattice_command(app);
  const capsim::cli::Command repro = capsim::cli::add_repro_command(app);
  const capsim::cli::Command bench = capsim::cli::add_bench_command(app);
  const capsim::cli::Command calibrate = capsim::cli::add_calibrate_command(app);
  const capsim::cli::Command sweep = capsim::cli::add_sweep_command(app);

  using capsim::cli::UsageError;
  try {
    try {
      app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
      if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);  // --help, --version
      throw UsageError(capsim::cli::describe_parse_error(app, e));
    }
    if (app.got_subcommand("render")) return render();
    if (app.got_subcommand("simulate")) return simulate();
    if (app.got_subcommand("lattice")) return lattice();
    if (app.got_subcommand("repro")) return repro();
    if (app.got_subcommand("bench")) return bench();
    if (app.got_subcommand("calibrate")) return calibrate();
    if (app.got_subcommand("sweep")) return sweep();
    throw UsageError(
        "a command is required (accepted: render, simulate, lattice, repro, bench, calibrate, sweep; capsim --help "
        "describes them)");
  } catch (const std::exception&) {
    const capsim::cli::CommandFailure f =
        capsim::cli::describe_failure(std::current_exception(), capsim::cli::command_name(app));
    tell(f.message);
    return f.status;
  }
}
