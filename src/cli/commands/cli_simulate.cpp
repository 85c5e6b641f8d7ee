// `capsim simulate`: the CAP machine running the tracer. The model charges each
// operation's cost in integer cycles of the cell's clock inside an
// event-driven machine.

#include "cli/commands/cli_commands.h"
#include "cli/options/cli_options.h"
#include "cli/cli_outputs.h"
#include "cli/options/cli_usage.h"
#include "cli/console.h"
#include "machine/machine.h"
#include "paper/simulate_command.h"
#include "report/heatmap.h"
#include "report/html_report.h"
#include "report/sim_report.h"
#include "report/text_output.h"

#include "capsim/image/image_io.h"
#include "capsim/system/sha256.h"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>

namespace capsim::cli {

namespace {

struct SimulateOptions {
  OptionText<> cells{"8x8"};
  OptionText<> mode{"dot"};
  OptionText<> profile{"cap"};
  OptionText<> balance{"static"};
  OptionText<> voxel_generation{"host"};
  std::string report;    // JSON report path; empty = none
  std::string trace;     // Chrome trace-event JSON path; empty = none
  OptionText<> heatmap;  // PNG path; empty = none
  std::string html;      // HTML report path; empty = none
  bool frame_average = false;
  bool quiet = false;
};

// The run's settings, for the command line the HTML report gives.
sim::SimulateSettings run_settings(const TracerSettings& t, const sim::MachineConfig& config,
                                   const std::string& profile, int width, int height) {
  sim::SimulateSettings s;
  s.scenes = t.scenes;
  s.output = t.output;
  s.width = width;
  s.height = height;
  s.grid = t.prepare.grid;
  s.cells = config.cells;
  s.mode = config.mode;
  s.profile = profile;
  s.frames = t.animate ? t.frames : 0;
  s.primary_only = t.trace.primary_only;
  s.aa = t.aa;
  s.frame_average = config.frame_average;
  s.balance = config.balance;
  s.voxel_generation = config.voxel_generation;
  s.threads = t.threads;
  s.defines = t.defines;
  return s;
}

// OpenSCAD's camera options as the run took them: null when none was given.
nlohmann::json view_options(const std::optional<OpenScadCameraOptions>& v) {
  if (!v) return nullptr;
  return {{"camera", v->camera}, {"viewall", v->viewall}, {"autocenter", v->autocenter},
          {"projection", to_string(v->projection)}};
}

// Where the run came from (report/provenance.h): every option with the value
// the run used, each named as on the command line.
sim::Provenance run_provenance(const std::vector<std::string>& argv, const TracerSettings& t,
                               const SimulateOptions& o, const sim::MachineConfig& config,
                               const sim::SimulationResult& result, const std::vector<PreparedScene>& scenes) {
  using nlohmann::json;
  const auto path_or_null = [](const std::string& path) { return path.empty() ? json() : json(path); };
  sim::Provenance p;
  p.argv = argv;
  p.version = CAPSIM_VERSION;
  for (const std::string& scene : t.scenes) p.scenes.push_back({scene, file_sha256_hex(scene)});
  p.profile = o.profile.text;
  p.profile_name = config.profile.name;
  p.profile_sha256 = config.profile.text_sha256;
  json divisions = json::array();
  for (const PreparedScene& s : scenes) divisions.push_back(s.grid.n);
  p.options = {{"scenes", t.scenes},
               {"frames", t.animate ? json(t.frames) : json()},
               {"output", t.output},
               {"size", fmt::format("{}x{}", result.width, result.height)},
               {"grid", t.prepare.grid > 0 ? json(t.prepare.grid) : json("auto")},
               {"grid_divisions", divisions},
               {"threads", t.threads},
               {"max_memory", t.max_memory > 0 ? json(t.max_memory) : json()},
               {"primary_only", t.trace.primary_only},
               {"aa", t.aa.depth},
               {"aa_threshold", t.aa.threshold},
               {"cells", sim::to_string(config.cells)},
               {"mode", sim::to_string(config.mode)},
               {"profile", o.profile.text},
               {"report", path_or_null(o.report)},
               {"trace", path_or_null(o.trace)},
               {"heatmap", path_or_null(o.heatmap.text)},
               {"html", path_or_null(o.html)},
               {"frame_average", config.frame_average},
               {"defines", t.defines},
               {"camera", view_options(t.prepare.openscad)},
               {"view", scenes.empty() ? json() : json(camera_arguments(scenes.front().camera))},
               {"view_statement", scenes.empty() ? json() : json(camera_statement(scenes.front().camera))},
               {"verbose", t.verbose},
               {"quiet", o.quiet}};
  // Only a run that is not static records it, so that a static run's reports
  // stay as they were before balancing could be chosen.
  if (!config.balance.is_static()) p.options["balance"] = sim::to_string(config.balance);
  if (config.voxel_generation == sim::VoxelGeneration::Cells)
    p.options["voxel_generation"] = sim::to_string(config.voxel_generation);
  return p;
}

bool is_builtin_profile(const std::string& value) {
  const std::vector<std::string> builtin = sim::builtin_profile_names();
  return std::find(builtin.begin(), builtin.end(), value) != builtin.end();
}

// A regular file that opens for reading. (CLI::ExistingFile would also take
// a device or a pipe.)
bool is_readable_file(const std::string& path) {
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec) && std::ifstream(path);
}

// The costs that rounding to whole cycles of the profile's clock moved by more
// than 1 %: the run charges the rounded cycles, so each is named on stderr (a
// 1 kHz clock makes the 3DDDA's steps free).
void warn_of_rounding(const sim::CostProfile& p) {
  for (const sim::ProfileTime& t : p.rounding())
    fmt::print(stderr,
               "capsim: warning: cost profile {}: {} = {} us becomes {} cycles at clock_hz {} ({:.4g} exactly, "
               "{:.1f} % off); the run charges {} cycles\n",
               p.source, t.key, t.us, t.cycles.count(), p.clock_hz, t.exact_cycles, 100 * t.rounding_error(),
               t.cycles.count());
}

sim::MachineConfig check_simulate_options(const SimulateOptions& o) {
  sim::MachineConfig config;
  const auto [rows, cols] = pair_value(checked(o.cells));
  config.cells = sim::CellGrid{rows, cols};
  config.mode = *sim::parse_pixel_mode(checked(o.mode));
  // A profile file's content is checked as it loads (a bad file is an input
  // error, like a bad scene).
  checked(o.profile);
  if (!o.heatmap.text.empty()) checked(o.heatmap);
  config.frame_average = o.frame_average;
  config.balance = sim::parse_balance(checked(o.balance));
  config.voxel_generation = *sim::parse_voxel_generation(checked(o.voxel_generation));
  if (config.balance.on_demand()) {
    if (o.mode.option->count() > 0)
      throw UsageError(fmt::format("--balance {} hands out tiles, which the window controllers show where the host "
                                   "says: it takes no --mode",
                                   o.balance.text));
    if (o.frame_average)
      throw UsageError(fmt::format("--balance {} hands out the tiles of one frame at a time: it cannot be "
                                   "frame averaged (--frame-average)",
                                   o.balance.text));
  }
  if (config.balance.stealing() && o.frame_average)
    throw UsageError(fmt::format("--balance {} takes chunks of one frame at a time: it cannot be frame averaged "
                                 "(--frame-average)",
                                 o.balance.text));
  if (o.frame_average && config.mode != sim::PixelMode::Dot)
    throw UsageError(fmt::format("--frame-average turns the dot pattern from frame to frame: it needs --mode dot, "
                                 "not {}",
                                 o.mode.text));
  return config;
}

}  // namespace

Command add_simulate_command(CLI::App& app, const std::vector<std::string>& argv) {
  auto opts = std::make_shared<TracerOptions>();
  auto sim = std::make_shared<SimulateOptions>();
  CLI::App* cmd = app.add_subcommand(
      "simulate",
      "Simulate the Cellular Array Processor running the tracer: the screen its video bus shows, "
      "per-cell times and the load spread (an .exr output also carries a 'cycles' channel)");
  add_tracer_options(*cmd, *opts);
  add_option(*cmd, "--cells", sim->cells, fmt::format("Cell grid RxC, 1x1 to {0}x{0}", sim::kMaxGridSide),
             whole_number_pair("RxC", sim::kMaxGridSide)
                 .description(fmt::format("RxC, R and C whole numbers from 1 to {}, e.g. 8x8", sim::kMaxGridSide)))
      ->default_val("8x8");
  const std::vector<std::string> modes = {sim::to_string(sim::PixelMode::Block), sim::to_string(sim::PixelMode::Line),
                                          sim::to_string(sim::PixelMode::Dot)};
  add_option(*cmd, "--mode", sim->mode,
             "Pixel mode of the window controllers: block (a rectangle per cell), line (every (R*C)-th row) or dot "
             "(one pixel of every RxC square)",
             refusing(CLI::IsMember(modes), "is not a pixel mode").description("block, line or dot"))
      ->default_val("dot");
  add_option(*cmd, "--profile", sim->profile,
             "Cost profile: cap (a CAP cell), m380 (the mainframe; use with --cells 1x1) or a profile JSON file "
             "(docs/simulation.md)",
             refusing(CLI::IsMember(sim::builtin_profile_names()) |
                          satisfying(is_readable_file, "is not a readable file"),
                      "is neither a built-in profile nor a readable file")
                 .description("cap, m380 or a profile JSON file as docs/simulation.md describes"))
      ->default_val("cap");
  add_option(*cmd, "--balance", sim->balance,
             "Load balancing: static (each cell traces what its window shows, the paper's), demand[:TILE] (the "
             "host hands out square tiles of TILE pixels, 64 by default, to the cells that ask over the command "
             "bus) or steal[:CHUNK] (the windows of --mode cut into chunks of CHUNK pixels, 16 by default, which "
             "idle cells take from their neighbours over the links); docs/balancing.md",
             satisfying(
                 [](const std::string& text) {
                   try {
                     (void)sim::parse_balance(text);
                     return true;
                   } catch (const std::invalid_argument&) {
                     return false;
                   }
                 },
                 "is not a balance scheme")
                 .description(fmt::format("static, demand, demand:TILE (TILE a square number of pixels from 1 to "
                                          "{}, e.g. demand:64), steal or steal:CHUNK (CHUNK from 1 to {})",
                                          sim::kMaxTilePixels, sim::kMaxChunkPixels)))
      ->default_val("static");
  add_option(*cmd, "--voxel-generation", sim->voxel_generation,
             "Who generates each frame's voxel grid (Algorithm-3): host (the paper's: the host generates it and "
             "broadcasts it) or cells (each cell places a share of the primitives and builds a share of the "
             "voxels, exchanged over the command bus; docs/balancing.md)",
             refusing(CLI::IsMember(std::vector<std::string>{"host", "cells"}), "is not host or cells")
                 .description("host or cells"))
      ->default_val("host");
  accepts(cmd->add_option("--report", sim->report, "Write the report as JSON to this file"),
          CLI::Validator("a file path"));
  accepts(cmd->add_option("--trace", sim->trace,
                          "Write the timeline as Chrome trace-event JSON (opens in ui.perfetto.dev)"),
          CLI::Validator("a file path"));
  add_option(*cmd, "--heatmap", sim->heatmap, "Write a PNG of per-cell busy time on the cell grid",
             satisfying(is_png_path, "is not a .png path").description("a path ending in .png"));
  cmd->add_option("--html", sim->html,
                  "Write one self-contained HTML page of the run: the screen filling over simulated time, "
                  "the cells, the timeline and the tables (docs/report.md)");
  accepts(cmd->add_flag("--frame-average", sim->frame_average,
                        "Frame-averaged distribution (dot mode): the dot pattern turns every frame, and the cells "
                        "run through groups of RxC frames without waiting for each other (docs/animation.md)"),
          flag_values());
  add_quiet_flag(*cmd, sim->quiet,
                 "the summary (the header's first line, Max, Min and d, the frame time and, for a sequence, the "
                 "Table 4-5 form)");

  return [opts, sim, argv] {
    const TracerSettings settings = check_tracer_options(*opts);
    sim::MachineConfig config = check_simulate_options(*sim);
    config.aa = settings.aa;
    const bool png = is_png_path(settings.output);
    config.screen = png ? sim::ScreenFormat::Srgb8 : sim::ScreenFormat::Float;
    const int frames = settings.frames;
    const bool numbered = settings.numbered_outputs();
    std::vector<std::string> inputs = settings.scenes;
    if (!is_builtin_profile(sim->profile.text)) inputs.push_back(sim->profile.text);
    std::vector<OutputOption> staged;
    for (int k = 0; k < frames; ++k)
      staged.push_back({frame_output_option(k, numbered), frame_output(settings.output, k, numbered)});
    for (const OutputOption& o : std::vector<OutputOption>{{"--report", sim->report},
                                                           {"--trace", sim->trace},
                                                           {"--heatmap", sim->heatmap.text},
                                                           {"--html", sim->html}})
      staged.push_back(o);
    StagedOutputs outputs(staged, inputs);
    Console console(sim->quiet);
    if (outputs.stdout_taken()) console.divert_to_stderr();
    config.profile = sim::load_cost_profile(sim->profile.text);
    warn_of_rounding(config.profile);
    config.completion_cycles = !sim->html.empty();

    const auto started = std::chrono::steady_clock::now();
    const std::vector<PreparedScene> scenes = load_scenes(settings, [config](ImageSize size, int count) {
      return sim::simulation_memory_until_written(config, size.width, size.height, count);
    });
    print_cameras(settings, scenes);
    std::vector<std::unique_ptr<Tracer>> tracers;
    std::vector<const Tracer*> frame_tracers;
    for (const PreparedScene& scene : scenes) {
      tracers.push_back(std::make_unique<Tracer>(scene, settings.trace));
      frame_tracers.push_back(tracers.back().get());
    }
    const sim::SimulationResult result =
        sim::simulate_frames(frame_tracers, config, settings.threads, console.progress_bar());
    // Reading the scenes, tracing and simulating: what the HTML report gives as the host's time.
    const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - started;

    for (int k = 0; k < frames; ++k) {
      const sim::FrameScreen& screen = result.screens[k];
      PendingFile& out = outputs[frame_output_option(k, numbered)];
      if (png) {
        write_png_rgb8(out, result.width, result.height, screen.screen_srgb8);
      } else {
        std::vector<ExtraChannel> extra = {{"cycles", screen.pixel_cycles}};
        if (config.aa.depth > 0) extra.push_back({"samples", screen.pixel_samples});
        write_image(out, screen.screen, extra);
      }
    }
    const sim::Provenance provenance = run_provenance(argv, settings, *sim, config, result, scenes);
    if (!sim->report.empty())
      sim::write_text_file(outputs["--report"], sim::report_json_text(result, &provenance));
    if (!sim->trace.empty()) sim::write_text_file(outputs["--trace"], sim::chrome_trace_text(result));
    if (!sim->heatmap.text.empty())
      write_image(outputs["--heatmap"], sim::to_framebuffer(sim::render_heatmap(result)));
    if (!sim->html.empty()) {
      const sim::RunFacts facts{settings.scenes,
                                sim::simulate_command(run_settings(settings, config, sim->profile.text, result.width,
                                                                   result.height),
                                                      sim::CommandForm::EveryOption),
                                wall.count(),
                                CAPSIM_VERSION,
                                provenance};
      sim::write_text_file(outputs["--html"], sim::html_report(result, facts));
    }
    outputs.commit();
    if (sim->quiet)
      console.summary(sim::format_summary(result));
    else
      console.summary(sim::format_report(result, &provenance));
    return 0;
  };
}

}  // namespace capsim::cli
