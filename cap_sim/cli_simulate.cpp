// `capsim simulate`: the CAP machine running the tracer, cycle by cycle.

#include "cli_commands.h"
#include "cli_options.h"
#include "cli_outputs.h"
#include "cli_usage.h"
#include "heatmap.h"
#include "machine.h"
#include "capsim/progress.h"
#include "sim_report.h"
#include "text_output.h"

#include "capsim/image_io.h"

#include <fmt/core.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>

namespace capsim::cli {

namespace {

struct SimulateOptions {
  std::string cells = "8x8";
  std::string mode = "dot";
  std::string profile = "cap";
  std::string report;   // JSON report path; empty = none
  std::string trace;    // Chrome trace-event JSON path; empty = none
  std::string heatmap;  // PNG path; empty = none
};

bool is_builtin_profile(const std::string& value) {
  const std::vector<std::string> builtin = sim::builtin_profile_names();
  return std::find(builtin.begin(), builtin.end(), value) != builtin.end();
}

// A built-in profile's name, or a profile file that can be opened; throws
// UsageError otherwise. The file's content is checked as it loads (a bad file
// is an input error, like a bad scene).
void check_profile_option(const std::string& value) {
  if (is_builtin_profile(value)) return;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(value, ec) || !std::ifstream(value))
    refuse("--profile", value, "is neither a built-in profile nor a readable file");
}

sim::MachineConfig check_simulate_options(const SimulateOptions& o) {
  sim::MachineConfig config;
  const auto [rows, cols] = parse_pair_option("--cells", o.cells, "RxC", sim::kMaxGridSide);
  config.cells = sim::CellGrid{rows, cols};
  const std::optional<sim::PixelMode> mode = sim::parse_pixel_mode(o.mode);
  if (!mode) refuse("--mode", o.mode, "is not a pixel mode");
  config.mode = *mode;
  check_profile_option(o.profile);
  if (!o.heatmap.empty() && !is_png_path(o.heatmap)) refuse("--heatmap", o.heatmap, "is not a .png path");
  return config;
}

}  // namespace

Command add_simulate_command(CLI::App& app) {
  auto opts = std::make_shared<TracerOptions>();
  auto sim = std::make_shared<SimulateOptions>();
  CLI::App* cmd = app.add_subcommand(
      "simulate",
      "Simulate the Cellular Array Processor running the tracer: the screen its video bus shows, "
      "per-cell times and the load spread (an .exr output also carries a 'cycles' channel)");
  add_tracer_options(*cmd, *opts);
  cmd->add_option("--cells", sim->cells, fmt::format("Cell grid RxC, 1x1 to {0}x{0}", sim::kMaxGridSide))
      ->default_val("8x8");
  cmd->add_option("--mode", sim->mode,
                  "Pixel mode of the window controllers: block (a rectangle per cell), line (every "
                  "(R*C)-th row) or dot (one pixel of every RxC square)")
      ->default_val("dot");
  cmd->add_option("--profile", sim->profile,
                  "Cost profile: cap (a CAP cell), m380 (the mainframe; use with --cells 1x1) or a "
                  "profile JSON file (docs/simulation.md)")
      ->default_val("cap");
  cmd->add_option("--report", sim->report, "Write the report as JSON to this file");
  cmd->add_option("--trace", sim->trace,
                  "Write the timeline as Chrome trace-event JSON (opens in ui.perfetto.dev)");
  cmd->add_option("--heatmap", sim->heatmap, "Write a PNG of per-cell busy time on the cell grid");

  return [opts, sim] {
    const TracerSettings settings = check_tracer_options(*opts);
    sim::MachineConfig config = check_simulate_options(*sim);
    std::vector<std::string> inputs = {settings.scene};
    if (!is_builtin_profile(sim->profile)) inputs.push_back(sim->profile);
    StagedOutputs outputs({{"--output", settings.output},
                           {"--report", sim->report},
                           {"--trace", sim->trace},
                           {"--heatmap", sim->heatmap}},
                          inputs);
    config.profile = sim::load_cost_profile(sim->profile);

    const std::string screen = settings.output;
    const PreparedScene scene = load_scene(settings, [screen](ImageSize size) {
      // The frame's peak, or the result with the written screen's working
      // memory (and, for an EXR, the copy of the cycles it carries).
      const std::size_t extra = is_png_path(screen) ? 0 : 1;
      const std::uint64_t writing = sim::simulation_result_memory(size.width, size.height) +
                                    extra * size.pixels() * sizeof(float) +
                                    write_image_memory(screen, size.width, size.height, extra);
      return std::max(sim::simulate_frame_memory(size.width, size.height), writing);
    });
    const Tracer tracer(scene, settings.trace);
    const sim::SimulationResult result =
        sim::simulate_frame(tracer, config, settings.threads, Progress::stderr_is_terminal());

    std::vector<ExtraChannel> extra;
    if (!is_png_path(settings.output)) extra.push_back({"cycles", result.pixel_cycles});
    write_image(outputs["--output"], result.screen, extra);
    if (!sim->report.empty())
      sim::write_text_file(outputs["--report"], sim::report_json(result).dump(2) + "\n");
    if (!sim->trace.empty()) {
      const std::string name = fmt::format("CAP {} cells, {} mode, profile {}", sim::to_string(config.cells),
                                           sim::to_string(config.mode), config.profile.name);
      sim::write_text_file(outputs["--trace"],
                           result.timeline.to_chrome_trace(name, config.profile.clock_hz).dump() + "\n");
    }
    if (!sim->heatmap.empty())
      write_image(outputs["--heatmap"], sim::to_framebuffer(sim::render_heatmap(result)));
    outputs.commit();
    fmt::print("{}", sim::format_report(result));
    return 0;
  };
}

}  // namespace capsim::cli
