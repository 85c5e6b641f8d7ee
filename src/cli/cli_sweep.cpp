// `capsim sweep`: a design-space sweep on this host (docs/sweeps.md): every
// point of a sweep file's axes simulated, the points in parallel, into one
// CSV and one JSON file and a page of plots (PREFIX.html), resumable from
// that JSON.

#include "cli/cli_commands.h"
#include "cli/cli_options.h"
#include "cli/cli_outputs.h"
#include "cli/cli_usage.h"
#include "cli/console.h"
#include "cli/sweep_run.h"
#include "paper/sweep_page.h"
#include "paper/sweep_records.h"
#include "report/text_output.h"

#include "capsim/host_threads.h"

#include <fmt/core.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>

namespace capsim::cli {

namespace {

struct SweepOptions {
  OptionText<> spec;
  // Default: the sweep file's stem and "-results", in the current directory
  // (the stem alone would make STEM.json the sweep file when run beside it).
  std::string prefix;
  OptionText<> threads{"0"};
  bool resume = false;
  bool quiet = false;
};

// The JSON of an earlier run of the sweep, to resume from; null if none.
nlohmann::json earlier_run(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return nullptr;
  std::ostringstream text;
  text << in.rdbuf();
  try {
    return nlohmann::json::parse(text.str());
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(fmt::format("{}: cannot resume from it: {}", path, e.what()));
  }
}

// How a progress line names a point: its inputs, as the record gives them.
std::string point_name(const sim::SweepPoint& p) {
  const nlohmann::json in = sim::sweep_inputs(p);
  std::string name;
  for (const auto& [key, value] : in.items())
    name += fmt::format("{}{}={}", name.empty() ? "" : " ", key, value.is_string() ? value.get<std::string>() : value.dump());
  return name;
}

int run_sweep(const SweepOptions& o) {
  const int threads = whole_value(checked(o.threads));
  const std::string& file = o.spec.text;
  sim::SweepSpec spec;
  try {
    spec = sim::read_sweep_spec(file);
  } catch (const sim::SweepSpecError& e) {
    std::fputs((std::string(e.what()) + "\n").c_str(), stderr);  // FILE: PATH: message, as a scene's errors
    return 1;
  }
  const std::string prefix = !o.prefix.empty() ? o.prefix : std::filesystem::path(file).stem().string() + "-results";
  const std::string csv = prefix + ".csv", json = prefix + ".json", html = prefix + ".html";
  // The earlier JSON is read here and replaced only once every point is done.
  const nlohmann::json earlier = o.resume ? earlier_run(json) : nlohmann::json();
  std::vector<std::string> inputs = {file};
  for (const sim::SweepPoint& p : spec.points) {
    inputs.insert(inputs.end(), p.scene.files.begin(), p.scene.files.end());
    if (std::filesystem::is_regular_file(p.profile_path)) inputs.push_back(p.profile_path);
  }
  // The three files are -o's; its names tell them apart in messages.
  StagedOutputs outputs({{"--output", csv}, {"-o", json}, {"-o/--output", html}}, inputs);
  Console console(o.quiet);
  if (outputs.stdout_taken()) console.divert_to_stderr();

  const std::size_t n = spec.points.size();
  std::vector<nlohmann::json> records(n);
  std::vector<std::size_t> to_run;
  for (std::size_t i = 0; i < n; ++i) {
    std::optional<nlohmann::json> kept;
    if (!earlier.is_null()) {
      try {
        kept = sim::find_sweep_record(earlier, sim::sweep_inputs(spec.points[i]));
      } catch (const std::runtime_error& e) {
        throw std::runtime_error(fmt::format("{}: cannot resume from it: {}", json, e.what()));
      }
    }
    if (kept) {
      kept->erase("speedup");  // recomputed below, over this sweep's points
      records[i] = *kept;
    } else {
      to_run.push_back(i);
    }
  }
  // Points run in parallel, each on one thread; a sweep of one point gives it all.
  const int point_threads = to_run.size() > 1 ? 1 : threads;
  std::mutex log;
  std::atomic<std::size_t> done{0};
  tbb::task_arena arena(host_arena_concurrency(threads));
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, to_run.size(), 1), [&](const auto& range) {
      for (std::size_t k = range.begin(); k != range.end(); ++k) {
        const std::size_t i = to_run[k];
        const sim::SweepPoint& p = spec.points[i];
        records[i] = sim::sweep_record(p, run_sweep_point(p, point_threads), CAPSIM_VERSION);
        const std::lock_guard<std::mutex> hold(log);
        console.progress(fmt::format("ran {}/{}: point {}: {}: {:.6f} s simulated\n", ++done, to_run.size(), i + 1,
                                     point_name(p), records[i].at("frame_seconds").get<double>()));
      }
    });
  });
  sim::add_speedups(records);
  const std::string sweep_name = std::filesystem::path(file).filename().string();
  sim::write_text_file(outputs["--output"], sim::sweep_csv(records));
  sim::write_text_file(outputs["-o"], sim::sweep_json(records, sweep_name, CAPSIM_VERSION));
  sim::write_text_file(outputs["-o/--output"], sim::sweep_page(records, sweep_name, CAPSIM_VERSION));
  outputs.commit();
  console.summary(fmt::format("{}, {}, {}: {} points ({} run, {} kept from the earlier run){}\n", csv, json, html, n,
                              to_run.size(), n - to_run.size(),
                              spec.skipped ? fmt::format("; {} left out: frame_average outside dot mode", spec.skipped)
                                           : std::string()));
  return 0;
}

}  // namespace

Command add_sweep_command(CLI::App& app) {
  auto o = std::make_shared<SweepOptions>();
  CLI::App* cmd = app.add_subcommand(
      "sweep",
      "Simulate every point of a design-space sweep (a JSON file of axes: scenes, cells, modes, aa, profiles, "
      "sizes, grid, primary_only, frame_average) into PREFIX.csv, PREFIX.json and a page of plots, PREFIX.html "
      "(docs/sweeps.md)");
  accepts(cmd->add_option("SPEC", o->spec.text, "The sweep file (.json)")->required(),
          CLI::Validator("a sweep file"));
  accepts(cmd->add_option("-o,--output", o->prefix,
                          "Prefix of the outputs PREFIX.csv, PREFIX.json and PREFIX.html (default: the sweep file's name without "
                          ".json and with -results, in the current directory)"),
          CLI::Validator("a path prefix"));
  add_option(*cmd, "--threads", o->threads,
             "Host threads (0 = all); points run in parallel, and the outputs do not depend on it",
             host_threads_check())
      ->default_val("0");
  accepts(cmd->add_flag("--resume", o->resume,
                        "Keep the records of points already in PREFIX.json (the same inputs) and run only the others"),
          flag_values());
  add_quiet_flag(*cmd, o->quiet, "the line naming the outputs and the points run");
  return [o] { return run_sweep(*o); };
}

}  // namespace capsim::cli
