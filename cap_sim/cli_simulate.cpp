// `capsim simulate`: the CAP machine running the tracer, cycle by cycle.

#include "cli_commands.h"
#include "cli_options.h"
#include "heatmap.h"
#include "html_report.h"
#include "machine.h"
#include "capsim/progress.h"
#include "sim_report.h"
#include "text_output.h"

#include "capsim/image_io.h"

#include <fmt/core.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <stdexcept>

namespace capsim::cli {

namespace {

struct SimulateOptions {
  std::string cells = "8x8";
  std::string mode = "dot";
  std::string profile = "cap";
  std::string report;   // JSON report path; empty = none
  std::string trace;    // Chrome trace-event JSON path; empty = none
  std::string heatmap;  // PNG path; empty = none
  std::string html;     // HTML report path; empty = none
};

// Fails before any work if an output's directory does not exist.
void check_output_directory(const std::string& path) {
  if (path.empty()) return;
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  if (!dir.empty() && !std::filesystem::is_directory(dir))
    throw std::invalid_argument(fmt::format("{}: directory {} does not exist", path, dir.string()));
}

// The options that decided the run, as a command line (the HTML report shows it).
std::string command_line(const TracerOptions& o, const SimulateOptions& s, int width, int height) {
  std::string line = fmt::format("capsim simulate {} -o {} --size {}x{} --grid {} --cells {} --mode {} --profile {}",
                                 o.scene, o.output, width, height, o.grid, s.cells, s.mode, s.profile);
  if (o.primary_only) line += " --primary-only";
  if (o.aa_depth > 0) line += fmt::format(" --aa {} --aa-threshold {}", o.aa_depth, o.aa_threshold);
  return line + fmt::format(" --threads {}", o.threads);
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
  cmd->add_option("--cells", sim->cells, "Cell grid RxC, 1x1 to 32x32")->default_val("8x8");
  cmd->add_option("--mode", sim->mode,
                  "Pixel mode of the window controllers: block (a rectangle per cell), line (every "
                  "(R*C)-th row) or dot (one pixel of every RxC square)")
      ->default_val("dot")
      ->check(CLI::IsMember({"block", "line", "dot"}));
  cmd->add_option("--profile", sim->profile,
                  "Cost profile: cap (a CAP cell), m380 (the mainframe; use with --cells 1x1) or a "
                  "profile JSON file (docs/simulation.md)")
      ->default_val("cap");
  cmd->add_option("--report", sim->report, "Write the report as JSON to this file");
  cmd->add_option("--trace", sim->trace,
                  "Write the timeline as Chrome trace-event JSON (opens in ui.perfetto.dev)");
  cmd->add_option("--heatmap", sim->heatmap, "Write a PNG of per-cell busy time on the cell grid");
  cmd->add_option("--html", sim->html,
                  "Write one self-contained HTML page of the run: the screen filling over simulated time, "
                  "the cells, the timeline and the tables (docs/report.md)");

  return [opts, sim] {
    sim::MachineConfig config;
    config.cells = sim::parse_cell_grid(sim->cells);
    config.mode = *sim::parse_pixel_mode(sim->mode);
    config.profile = sim::load_cost_profile(sim->profile);
    config.aa = antialias_options(*opts);
    config.screen = is_png_path(opts->output) ? sim::ScreenFormat::Srgb8 : sim::ScreenFormat::Float;
    config.completion_cycles = !sim->html.empty();
    if (!sim->heatmap.empty() && !is_png_path(sim->heatmap))
      throw std::invalid_argument(fmt::format("{}: the heat map is written as .png", sim->heatmap));
    for (const std::string* path : {&sim->report, &sim->trace, &sim->heatmap, &sim->html})
      check_output_directory(*path);

    const auto started = std::chrono::steady_clock::now();
    const PreparedScene scene = load_scene(*opts);
    const Tracer tracer(scene, trace_options(*opts));
    const sim::SimulationResult result =
        sim::simulate_frame(tracer, config, opts->threads, Progress::stderr_is_terminal());
    // Reading the scene, tracing and simulating: what the HTML report gives as the host's time.
    const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - started;

    const sim::FrameScreen& screen = result.screens.at(0);
    if (config.screen == sim::ScreenFormat::Srgb8) {
      write_png_rgb8(opts->output, result.width, result.height, screen.screen_srgb8);
    } else {
      std::vector<ExtraChannel> extra = {{"cycles", screen.pixel_cycles}};
      if (config.aa.depth > 0) extra.push_back({"samples", screen.pixel_samples});
      write_image(opts->output, screen.screen, extra);
    }
    if (!sim->report.empty()) sim::write_text_file(sim->report, sim::report_json_text(result));
    if (!sim->trace.empty()) sim::write_text_file(sim->trace, sim::chrome_trace_text(result));
    if (!sim->heatmap.empty()) write_image(sim->heatmap, sim::to_framebuffer(sim::render_heatmap(result)));
    if (!sim->html.empty()) {
      const sim::RunFacts facts{opts->scene, command_line(*opts, *sim, result.width, result.height), wall.count(),
                                CAPSIM_VERSION};
      sim::write_text_file(sim->html, sim::html_report(result, facts));
    }
    fmt::print("{}", sim::format_report(result));
    return 0;
  };
}

}  // namespace capsim::cli
