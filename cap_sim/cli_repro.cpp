// `capsim repro`: every experiment of the paper beside its published figures,
// written as docs/reproduction.md with its plots.

#include "cli_commands.h"
#include "repro.h"
#include "text_output.h"

#include <fmt/core.h>

#include <charconv>
#include <chrono>
#include <filesystem>
#include <memory>
#include <stdexcept>

namespace capsim::cli {

namespace {

struct ReproCliOptions {
  std::string output = "docs/reproduction.md";
  std::string images;  // default: images/ beside the output
  std::string size = "512x512";
  std::string scenes = "scenes";
  int threads = 0;
  int frames = 64;
};

void check_directory(const std::filesystem::path& dir, const std::string& what) {
  if (!dir.empty() && !std::filesystem::is_directory(dir))
    throw std::invalid_argument(fmt::format("{}: directory {} does not exist", what, dir.string()));
}

}  // namespace

Command add_repro_command(CLI::App& app) {
  auto o = std::make_shared<ReproCliOptions>();
  CLI::App* cmd = app.add_subcommand(
      "repro",
      "Run every experiment of the paper (Tables 4-2 to 4-5 and 5-1, Graph 4-3) and write them beside the "
      "published figures, with the fit of the cost constants, as a Markdown report with SVG plots");
  cmd->add_option("-o,--output", o->output, "The report")->default_val("docs/reproduction.md");
  cmd->add_option("--images", o->images,
                  "Directory for the plots table-4-2.svg and graph-4-3.svg (default: images/ beside the report)");
  cmd->add_option("--size", o->size, "Screen of every run, WxH (the paper's is 512x512)")->default_val("512x512");
  cmd->add_option("--scenes", o->scenes, "Directory of the models (balls.csg, chess.csg, ..., disb/)")
      ->default_val("scenes");
  cmd->add_option("--frames", o->frames, "DISB frames to run for Table 4-5, 0 to 64 (0: leave it not run)")
      ->default_val(64)
      ->check(CLI::Range(0, 64));
  cmd->add_option("--threads", o->threads, "Host threads (0 = all); the report does not depend on it")
      ->default_val(0)
      ->check(CLI::NonNegativeNumber);
  return [o] {
    sim::ReproOptions options;
    const auto x = o->size.find('x');
    int w = 0, h = 0;
    if (x == std::string::npos ||
        std::from_chars(o->size.data(), o->size.data() + x, w).ptr != o->size.data() + x ||
        std::from_chars(o->size.data() + x + 1, o->size.data() + o->size.size(), h).ptr !=
            o->size.data() + o->size.size() ||
        w < 1 || h < 1 || w > 16384 || h > 16384)
      throw std::invalid_argument(fmt::format("--size '{}' is not WxH with sides 1 to 16384", o->size));
    options.width = w;
    options.height = h;
    options.threads = o->threads;
    options.scenes_dir = o->scenes;
    options.table_4_5_frames = o->frames;
    const std::filesystem::path report(o->output);
    const std::filesystem::path images =
        o->images.empty() ? report.parent_path() / "images" : std::filesystem::path(o->images);
    check_directory(report.parent_path(), o->output);
    check_directory(images, "--images");

    const auto start = std::chrono::steady_clock::now();
    options.log = [start](const std::string& what) {
      const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      fmt::print(stderr, "[{:7.1f} s] {}\n", t, what);
    };
    const sim::ReproResult result = sim::run_reproduction(options);
    // The plots' path as the report links them.
    const std::string link =
        std::filesystem::relative(std::filesystem::absolute(images), std::filesystem::absolute(report).parent_path())
            .generic_string();
    sim::write_text_file((images / "table-4-2.svg").string(), sim::table_4_2_plot_svg(result));
    sim::write_text_file((images / "graph-4-3.svg").string(), sim::graph_4_3_plot_svg(result));
    sim::write_text_file(o->output, sim::reproduction_markdown(result, link.empty() ? "." : link));
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    fmt::print("{}: written ({:.1f} s)\n", o->output, t);
    for (const sim::TargetCheck& c : sim::reproduction_targets(result))
      fmt::print("  {}: {}\n", c.met ? "met   " : "MISSED", c.target);
    return 0;
  };
}

}  // namespace capsim::cli
