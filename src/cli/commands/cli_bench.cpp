// `capsim bench modes`: the regression benchmarks of the pixel modes, compared
// exactly with a stored baseline (docs/benchmarks.md): --baseline FILE, or the
// shipped one for the screen (shipped_data.h), or none.

#include "capsim/trace/prepared_scene.h"
#include "cli/commands/cli_commands.h"
#include "cli/options/cli_options.h"
#include "cli/cli_outputs.h"
#include "cli/options/cli_usage.h"
#include "cli/shipped_data.h"
#include "cli/console.h"
#include "paper/modes/modes_bench.h"
#include "paper/modes/modes_page.h"
#include "report/text_output.h"

#include <fmt/core.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace capsim::cli {

namespace {

struct BenchOptions {
  OptionText<> size{"512x512"};
  OptionText<> scenes;    // default: the shipped models, found
  std::string baseline;  // default: the shipped modes[-WxH].json, found; none at other sizes
  std::string json;
  OptionText<> plot;
  std::string html;
  bool update = false;
  OptionText<> threads{"0"};
  bool quiet = false;
};

nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(fmt::format("{}: cannot read the baseline (write one with --update)", path));
  std::ostringstream text;
  text << in.rdbuf();
  try {
    return nlohmann::json::parse(text.str());
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(fmt::format("{}: not a baseline: {}", path, e.what()));
  }
}

// The shipped baseline for a screen (modes.json at 512x512, modes-WxH.json at
// others), if there is one.
std::string shipped_baseline(int width, int height) {
  const std::optional<std::string> dir = find_shipped_data(ShippedData::Baselines);
  if (!dir) return "";
  const std::filesystem::path file =
      std::filesystem::path(*dir) /
      (width == 512 && height == 512 ? std::string("modes.json") : fmt::format("modes-{}x{}.json", width, height));
  return std::filesystem::is_regular_file(file) ? file.string() : "";
}

int run_modes(const BenchOptions& o) {
  sim::ModesBenchOptions options;
  std::tie(options.width, options.height) = pair_value(checked(o.size));
  options.threads = whole_value(checked(o.threads));
  options.scenes_dir = scenes_dir(o.scenes);
  // --update writes only where --baseline says: never, unasked, into the
  // source tree or an installed share directory.
  if (o.update && o.baseline.empty())
    throw UsageError("--update needs --baseline FILE, the baseline to write");
  const std::string baseline = !o.baseline.empty() ? o.baseline : shipped_baseline(options.width, options.height);
  if (!o.plot.text.empty()) checked(o.plot);
  if (baseline == kStandardOutputPath)
    throw UsageError("--baseline -: the baseline is read as well as written, so it cannot be standard output");
  const bool have_baseline = !baseline.empty() && std::filesystem::exists(baseline);
  if (!o.update && !o.baseline.empty() && !have_baseline)
    throw UsageError(fmt::format("--baseline {}: no such file (write one with --update)", shown(baseline)));
  const nlohmann::json old = have_baseline ? read_json(baseline) : nlohmann::json();
  // The baseline is read above and replaced, when --update asks, only once
  // the whole run is done.
  StagedOutputs outputs({{"--json", o.json},
                         {"--plot", o.plot.text},
                         {"--html", o.html},
                         {"--baseline", o.update ? baseline : std::string()}},
                        have_baseline && !o.update ? std::vector<std::string>{baseline} : std::vector<std::string>{});

  Console console(o.quiet);
  if (outputs.stdout_taken()) console.divert_to_stderr();
  options.log = [&console](const std::string& run) { console.progress(run + "\n"); };
  const sim::ModesBench bench = sim::run_modes_bench(options);
  const nlohmann::json now = sim::modes_bench_json(bench);
  console.detail(sim::modes_bench_table(bench) + "\n");
  // The comparison comes before any output is written, for the page to say
  // how it went; a baseline that is not comparable fails the command only
  // after the outputs are in place, as a moved figure does.
  sim::BaselineOutcome outcome;
  outcome.path = baseline;
  outcome.rewritten = o.update;
  outcome.existed = have_baseline;
  if (have_baseline) {
    try {
      outcome.moved = sim::compare_modes_bench(old, now);
    } catch (const std::runtime_error& e) {
      outcome.not_comparable = e.what();
    }
  }
  // The files (and the baseline --update writes) name the version that wrote
  // them; the comparison reads only the runs, the size and the profile.
  nlohmann::json written = now;
  written["capsim_version"] = CAPSIM_VERSION;
  if (!o.json.empty()) sim::write_text_file(outputs["--json"], written.dump(2) + "\n");
  if (!o.plot.text.empty()) sim::write_text_file(outputs["--plot"], sim::modes_bench_svg(bench));
  if (!o.html.empty()) sim::write_text_file(outputs["--html"], sim::modes_page(bench, outcome, CAPSIM_VERSION));
  if (o.update) sim::write_text_file(outputs["--baseline"], written.dump(2) + "\n");
  outputs.commit();

  const std::vector<sim::MovedFigure>& moved = outcome.moved;
  if (o.update) {
    if (!have_baseline) {
      console.summary(fmt::format("{}: written ({} runs)\n", baseline, bench.runs.size()));
      return 0;
    }
    if (!outcome.not_comparable.empty()) {
      console.summary(
          fmt::format("{}: rewritten; the old one was not comparable: {}\n", baseline, outcome.not_comparable));
      return 0;
    }
    if (moved.empty()) {
      console.summary(fmt::format("{}: rewritten; nothing moved\n", baseline));
    } else {
      console.summary(
          fmt::format("{}: rewritten; {} figures moved:\n\n{}", baseline, moved.size(), sim::format_moved(moved)));
    }
    return 0;
  }
  if (!have_baseline) {
    console.summary(fmt::format("no baseline for {}x{}: not compared\n", options.width, options.height));
    return 0;
  }
  if (!outcome.not_comparable.empty()) throw std::runtime_error(outcome.not_comparable);
  if (moved.empty()) {
    console.summary(fmt::format("{}: all {} runs identical to the baseline\n", baseline, bench.runs.size()));
    return 0;
  }
  console.summary(fmt::format("{}: {} figures differ from the baseline:\n\n{}\nIf the change is intended, rerun "
                              "with --update --baseline {} and commit the baseline with it, saying why.\n",
                              baseline, moved.size(), sim::format_moved(moved), baseline));
  return 1;
}

}  // namespace

Command add_bench_command(CLI::App& app) {
  auto o = std::make_shared<BenchOptions>();
  CLI::App* bench = app.add_subcommand("bench", "Regression benchmarks of the simulated machine");
  CLI::App* modes = bench->add_subcommand(
      "modes",
      "Every shipped model in block, line and dot mode on 4x4, 4x8, 8x8 and 16x16 cells, plain and "
      "antialiased (--aa 2): frame time, Max, Min, d, speed-up against 4x4, bus and link traffic; compared "
      "exactly with a stored baseline (docs/benchmarks.md)");
  add_option(*modes, "--size", o->size, "Screen of every run, WxH", image_size_check())->default_val("512x512");
  add_scenes_option(*modes, o->scenes);
  modes->add_option("--baseline", o->baseline,
                    "Baseline to compare with (default: the shipped modes.json at 512x512, modes-WxH.json at other "
                    "sizes, found as the models are; at a size without one, the run is not compared)");
  modes->add_flag("--update", o->update,
                  "Write this run to the --baseline FILE (required with it) and print what moved against it");
  modes->add_option("--json", o->json, "Also write the results as JSON to this file");
  add_option(*modes, "--plot", o->plot, "Also write a plot (.svg): d and speed-up against the cell count",
             satisfying([](const std::string& path) { return path.ends_with(".svg"); }, "does not end in .svg")
                 .description("a path ending in .svg"));
  modes->add_option("--html", o->html,
                    "Also write one self-contained HTML page comparing the modes: the baseline's verdict, plots of "
                    "d and speed-up per model, and a sortable table of every run");
  add_option(*modes, "--threads", o->threads, "Host threads (0 = all); the figures do not depend on it",
             host_threads_check())
      ->default_val("0");
  add_quiet_flag(*modes, o->quiet, "the verdict (and the figures that moved)");
  return [o, modes] {
    if (modes->parsed()) return run_modes(*o);
    throw UsageError("a benchmark is required (accepted: modes)");
  };
}

}  // namespace capsim::cli
