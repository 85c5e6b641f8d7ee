// `capsim repro`: every experiment of the paper beside its published figures,
// written as a Markdown report (reproduction.md in the current directory by
// default; the project's own is docs/reproduction.md) with its plots.

#include "capsim/trace/prepared_scene.h"
#include "cli/commands/cli_commands.h"
#include "cli/options/cli_options.h"
#include "cli/cli_outputs.h"
#include "cli/console.h"
#include "cli/shipped_data.h"
#include "paper/repro/published_figures.h"
#include "paper/repro/repro.h"
#include "report/text_output.h"

#include <fmt/core.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <system_error>
#include <tuple>
#include <stdexcept>

namespace capsim::cli {

namespace {

struct ReproCliOptions {
  std::string output = "reproduction.md";
  std::string images;  // default: images/ beside the output, made if missing
  std::string json;    // every compared figure; empty = not written
  OptionText<> size;   // both screens
  OptionText<> cap_size{"384x384"};
  OptionText<> m380_size{"512x512"};
  OptionText<> scenes;  // default: the shipped models, found (shipped_data.h)
  OptionText<> threads{"0"};
  OptionText<> frames{"64"};
  bool quiet = false;
};

// The default images directory (images/ beside the report), made when it is
// missing so that a report can be written in any directory; removed again,
// if still empty, when the command fails before putting its files in place.
class MadeDirectory {
 public:
  explicit MadeDirectory(const std::filesystem::path& dir) : dir_(dir) {
    std::error_code ec;
    made_ = std::filesystem::create_directory(dir_, ec) && !ec;  // else the outputs' check reports it
  }
  MadeDirectory(const MadeDirectory&) = delete;
  MadeDirectory& operator=(const MadeDirectory&) = delete;
  ~MadeDirectory() {
    std::error_code ec;
    if (made_ && !kept_) std::filesystem::remove(dir_, ec);
  }
  void keep() { kept_ = true; }

 private:
  std::filesystem::path dir_;
  bool made_ = false, kept_ = false;
};

}  // namespace

Command add_repro_command(CLI::App& app) {
  auto o = std::make_shared<ReproCliOptions>();
  CLI::App* cmd = app.add_subcommand(
      "repro",
      "Run every experiment of the paper (Tables 4-2 to 4-5 and 5-1, Graph 4-3) and write them beside the "
      "published figures, with the fit of the cost constants, as a Markdown report with SVG plots");
  // Its usage errors quote what an image --output accepts, as they always have.
  accepts(cmd->add_option("-o,--output", o->output, "The report")->default_val("reproduction.md"),
          CLI::Validator(image_output_check().get_description()));
  cmd->add_option("--images", o->images,
                  "Directory for the plots table-4-2.svg and graph-4-3.svg (default: images/ beside the report, "
                  "made if missing)");
  cmd->add_option("--json", o->json,
                  "Also write every compared figure, the per-table errors and the assumptions as JSON");
  add_option(*cmd, "--cap-size", o->cap_size,
             "Screen of the CAP's runs, WxH (the paper does not give it; docs/calibration.md)", image_size_check())
      ->default_val("384x384");
  add_option(*cmd, "--m380-size", o->m380_size,
             "Screen of the M380's runs, WxH (the paper does not give it; docs/calibration.md)", image_size_check())
      ->default_val("512x512");
  add_option(*cmd, "--size", o->size, "Screen of every run, WxH (sets --cap-size and --m380-size)",
             image_size_check());
  add_scenes_option(*cmd, o->scenes);
  add_option(*cmd, "--disb-frames", o->frames, "DISB frames to run for Table 4-5, 0 to 64 (0: leave it not run)",
             whole_number(0, 64).description("0 to 64; 0 = leave Table 4-5 not run"))
      ->default_val("64");
  add_option(*cmd, "--threads", o->threads, "Host threads (0 = all); the report does not depend on it",
             host_threads_check())
      ->default_val("0");
  add_quiet_flag(*cmd, o->quiet, "the summary (the report written and each target met or missed)");
  return [o] {
    sim::ReproOptions options;
    std::tie(options.width, options.height) = pair_value(checked(o->cap_size));
    std::tie(options.m380_width, options.m380_height) = pair_value(checked(o->m380_size));
    if (o->size.option->count() > 0) {
      std::tie(options.width, options.height) = pair_value(checked(o->size));
      std::tie(options.m380_width, options.m380_height) = pair_value(checked(o->size));
    }
    options.threads = whole_value(checked(o->threads));
    options.table_4_5_frames = whole_value(checked(o->frames));
    options.scenes_dir = scenes_dir(o->scenes);
    const std::filesystem::path report(o->output);
    const std::filesystem::path images =
        o->images.empty() ? report.parent_path() / "images" : std::filesystem::path(o->images);
    std::vector<OutputOption> files = {
        {"--output", o->output},
        {"--images (table-4-2.svg)", (images / "table-4-2.svg").string()},
        {"--images (graph-4-3.svg)", (images / "graph-4-3.svg").string()}};
    if (!o->json.empty()) files.push_back({"--json", o->json});
    std::optional<MadeDirectory> made;
    if (o->images.empty()) made.emplace(images);
    StagedOutputs outputs(files, {});
    Console console(o->quiet);
    if (outputs.stdout_taken()) console.divert_to_stderr();

    const ElapsedLog log(console);
    options.log = log;
    const sim::ReproResult result = sim::run_reproduction(options);
    // The plots' path as the report links them.
    const std::string link =
        std::filesystem::relative(std::filesystem::absolute(images), std::filesystem::absolute(report).parent_path())
            .generic_string();
    sim::write_text_file(outputs["--images (table-4-2.svg)"], sim::table_4_2_plot_svg(result));
    sim::write_text_file(outputs["--images (graph-4-3.svg)"], sim::graph_4_3_plot_svg(result));
    sim::write_text_file(outputs["--output"], sim::reproduction_markdown(result, link.empty() ? "." : link));
    if (!o->json.empty()) {
      const std::vector<sim::ComparedFigure> figures =
          sim::compared_figures(result, sim::Exclusions::Table44ChessCad);
      sim::write_text_file(outputs["--json"], sim::reproduction_json(result, figures, CAPSIM_VERSION));
    }
    outputs.commit();
    if (made) made->keep();
    console.summary(fmt::format("{}: written ({:.1f} s)\n", o->output, log.seconds()));
    for (const sim::TargetCheck& c : sim::reproduction_targets(result))
      console.summary(fmt::format("  {}: {}\n", c.met ? "met   " : "MISSED", c.target));
    return 0;
  };
}

}  // namespace capsim::cli
