// `capsim bench modes`: the regression benchmarks of the pixel modes, compared
// exactly with a stored baseline (docs/benchmarks.md).

#include "cli_commands.h"
#include "modes_bench.h"
#include "text_output.h"

#include <fmt/core.h>

#include <charconv>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace capsim::cli {

namespace {

struct BenchOptions {
  std::string size = "512x512";
  std::string scenes = "scenes";
  std::string baseline;  // default: bench/baselines/modes[-WxH].json
  std::string json;
  std::string plot;
  bool update = false;
  int threads = 0;
};

void check_parent(const std::string& path) {
  if (path.empty()) return;
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  if (!dir.empty() && !std::filesystem::is_directory(dir))
    throw std::invalid_argument(fmt::format("{}: directory {} does not exist", path, dir.string()));
}

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

int run_modes(const BenchOptions& o) {
  sim::ModesBenchOptions options;
  const auto x = o.size.find('x');
  const char* end = o.size.data() + o.size.size();
  if (x == std::string::npos || std::from_chars(o.size.data(), o.size.data() + x, options.width).ptr != o.size.data() + x ||
      std::from_chars(o.size.data() + x + 1, end, options.height).ptr != end || options.width < 1 ||
      options.height < 1 || options.width > 16384 || options.height > 16384)
    throw std::invalid_argument(fmt::format("--size '{}' is not WxH with sides 1 to 16384", o.size));
  options.scenes_dir = o.scenes;
  options.threads = o.threads;
  const std::string baseline =
      !o.baseline.empty() ? o.baseline
      : (options.width == 512 && options.height == 512)
          ? std::string("bench/baselines/modes.json")
          : fmt::format("bench/baselines/modes-{}x{}.json", options.width, options.height);
  for (const std::string* path : {&o.json, &o.plot, &baseline}) check_parent(*path);
  if (!o.plot.empty() && !o.plot.ends_with(".svg"))
    throw std::invalid_argument(fmt::format("{}: the plot is written as .svg", o.plot));
  const bool have_baseline = std::filesystem::exists(baseline);
  if (!o.update && !have_baseline)
    throw std::runtime_error(fmt::format("{}: no baseline (write one with --update)", baseline));
  const nlohmann::json old = have_baseline ? read_json(baseline) : nlohmann::json();

  options.log = [](const std::string& run) { fmt::print(stderr, "{}\n", run); };
  const sim::ModesBench bench = sim::run_modes_bench(options);
  const nlohmann::json now = sim::modes_bench_json(bench);
  fmt::print("{}\n", sim::modes_bench_table(bench));
  if (!o.json.empty()) sim::write_text_file(o.json, now.dump(2) + "\n");
  if (!o.plot.empty()) sim::write_text_file(o.plot, sim::modes_bench_svg(bench));

  if (o.update) {
    sim::write_text_file(baseline, now.dump(2) + "\n");
    if (!have_baseline) {
      fmt::print("{}: written ({} runs)\n", baseline, bench.runs.size());
      return 0;
    }
    std::vector<sim::MovedFigure> moved;
    try {
      moved = sim::compare_modes_bench(old, now);
    } catch (const std::runtime_error& e) {
      fmt::print("{}: rewritten; the old one was not comparable: {}\n", baseline, e.what());
      return 0;
    }
    if (moved.empty()) {
      fmt::print("{}: rewritten; nothing moved\n", baseline);
    } else {
      fmt::print("{}: rewritten; {} figures moved:\n\n{}", baseline, moved.size(), sim::format_moved(moved));
    }
    return 0;
  }
  const std::vector<sim::MovedFigure> moved = sim::compare_modes_bench(old, now);
  if (moved.empty()) {
    fmt::print("{}: all {} runs identical to the baseline\n", baseline, bench.runs.size());
    return 0;
  }
  fmt::print("{}: {} figures differ from the baseline:\n\n{}\nIf the change is intended, rerun with --update "
             "and commit the baseline with it, saying why.\n",
             baseline, moved.size(), sim::format_moved(moved));
  return 1;
}

}  // namespace

Command add_bench_command(CLI::App& app) {
  auto o = std::make_shared<BenchOptions>();
  CLI::App* bench = app.add_subcommand("bench", "Regression benchmarks of the simulated machine");
  bench->require_subcommand(1);
  CLI::App* modes = bench->add_subcommand(
      "modes",
      "Every shipped model in block, line and dot mode on 4x4, 4x8, 8x8 and 16x16 cells, plain and "
      "antialiased (--aa 2): frame time, Max, Min, d, speed-up against 4x4, bus and link traffic; compared "
      "exactly with a stored baseline (docs/benchmarks.md)");
  modes->add_option("--size", o->size, "Screen of every run, WxH")->default_val("512x512");
  modes->add_option("--scenes", o->scenes, "Directory of the models")->default_val("scenes");
  modes->add_option("--baseline", o->baseline,
                    "Baseline to compare with (default: bench/baselines/modes.json at 512x512, "
                    "bench/baselines/modes-WxH.json at other sizes)");
  modes->add_flag("--update", o->update, "Rewrite the baseline with this run and print what moved");
  modes->add_option("--json", o->json, "Also write the results as JSON to this file");
  modes->add_option("--plot", o->plot, "Also write a plot (.svg): d and speed-up against the cell count");
  modes->add_option("--threads", o->threads, "Host threads (0 = all); the figures do not depend on it")
      ->default_val(0)
      ->check(CLI::NonNegativeNumber);
  return [o, modes] {
    if (modes->parsed()) return run_modes(*o);
    return 2;
  };
}

}  // namespace capsim::cli
