// `capsim sweep`: a design-space sweep (docs/sweeps.md): every point of a
// sweep file's axes simulated, the points in parallel on this host's threads
// and, under mpirun, shared among the ranks (sweep_ranks.h), into one CSV and
// one JSON file and a page of plots (PREFIX.html), resumable from that JSON.

#include "cli/commands/cli_commands.h"
#include "cli/options/cli_options.h"
#include "cli/cli_outputs.h"
#include "cli/options/cli_usage.h"
#include "cli/command_failure.h"
#include "cli/console.h"
#include "cli/sweeps/sweep_ranks.h"
#include "cli/sweeps/sweep_run.h"
#include "paper/sweeps/sweep_page.h"
#include "paper/sweeps/sweep_records.h"
#include "report/text_output.h"

#include "capsim/system/host_threads.h"

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

// What rank 0 settles before any point runs: the sweep file's points, the
// outputs, the records kept from an earlier run and the points left to run.
struct SweepPlan {
  std::string text;  // the sweep file's, which every rank parses alike
  sim::SweepSpec spec;
  std::string csv, json, html;
  std::optional<StagedOutputs> outputs;
  std::vector<nlohmann::json> records;  // the kept ones; null for those to run
  std::vector<std::size_t> to_run;
};

std::unique_ptr<SweepPlan> plan_sweep(const SweepOptions& o) {
  auto plan = std::make_unique<SweepPlan>();
  const std::string& file = o.spec.text;
  plan->text = sim::read_sweep_text(file);
  plan->spec = sim::parse_sweep_spec(plan->text, file);
  const std::string prefix = !o.prefix.empty() ? o.prefix : std::filesystem::path(file).stem().string() + "-results";
  plan->csv = prefix + ".csv";
  plan->json = prefix + ".json";
  plan->html = prefix + ".html";
  // The earlier JSON is read here and replaced only once every point is done.
  const nlohmann::json earlier = o.resume ? earlier_run(plan->json) : nlohmann::json();
  std::vector<std::string> inputs = {file};
  for (const sim::SweepPoint& p : plan->spec.points) {
    inputs.insert(inputs.end(), p.scene.files.begin(), p.scene.files.end());
    if (std::filesystem::is_regular_file(p.profile_path)) inputs.push_back(p.profile_path);
  }
  // The three files are -o's; its names tell them apart in messages.
  plan->outputs.emplace(std::vector<OutputOption>{{"--output", plan->csv}, {"-o", plan->json}, {"-o/--output", plan->html}},
                        inputs);
  const std::size_t n = plan->spec.points.size();
  plan->records.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::optional<nlohmann::json> kept;
    if (!earlier.is_null()) {
      try {
        kept = sim::find_sweep_record(earlier, sim::sweep_inputs(plan->spec.points[i]));
      } catch (const std::runtime_error& e) {
        throw std::runtime_error(fmt::format("{}: cannot resume from it: {}", plan->json, e.what()));
      }
    }
    if (kept) {
      kept->erase("speedup");  // recomputed over this sweep's points
      plan->records[i] = *kept;
    } else {
      plan->to_run.push_back(i);
    }
  }
  return plan;
}

// Runs the points `mine` of `spec` into their records, in parallel, each on one
// thread (one point alone is given them all). Progress lines start with `who`.
void run_points(const sim::SweepSpec& spec, const std::vector<std::size_t>& mine, int threads,
                std::vector<nlohmann::json>& records, Console& console, const std::string& who) {
  const int point_threads = mine.size() > 1 ? 1 : threads;
  std::mutex log;
  std::atomic<std::size_t> done{0};
  tbb::task_arena arena(host_arena_concurrency(threads));
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, mine.size(), 1), [&](const auto& range) {
      for (std::size_t k = range.begin(); k != range.end(); ++k) {
        const std::size_t i = mine[k];
        const sim::SweepPoint& p = spec.points[i];
        records[i] = sim::sweep_record(p, run_sweep_point(p, point_threads), CAPSIM_VERSION);
        const std::lock_guard<std::mutex> hold(log);
        console.progress(fmt::format("{}ran {}/{}: point {}: {}: {:.6f} s simulated\n", who, ++done, mine.size(),
                                     i + 1, point_name(p), records[i].at("frame_seconds").get<double>()));
      }
    });
  });
}

// A failure as main tells a command's; a sweep file's error as FILE: PATH:
// message, as a scene's.
CommandFailure sweep_failure(const std::exception_ptr& e) {
  try {
    std::rethrow_exception(e);
  } catch (const sim::SweepSpecError& spec_error) {
    return {1, spec_error.what()};
  } catch (...) {
    return describe_failure(e, "capsim sweep");
  }
}

// Prints a failure on stderr, after `who` (the failing rank under MPI, else
// nothing); returns its status.
int tell(const CommandFailure& f, const std::string& who) {
  std::fputs((who + f.message + "\n").c_str(), stderr);
  return f.status;
}

// Rank 0's last step: the outputs, written from every point's record, and the
// summary line.
void write_outputs(SweepPlan& plan, const std::string& file, std::size_t ran, const SweepRanks& ranks,
                   Console& console) {
  std::vector<nlohmann::json>& records = plan.records;
  sim::add_speedups(records);
  const std::string sweep_name = std::filesystem::path(file).filename().string();
  StagedOutputs& outputs = *plan.outputs;
  sim::write_text_file(outputs["--output"], sim::sweep_csv(records));
  sim::write_text_file(outputs["-o"], sim::sweep_json(records, sweep_name, CAPSIM_VERSION));
  sim::write_text_file(outputs["-o/--output"], sim::sweep_page(records, sweep_name, CAPSIM_VERSION));
  outputs.commit();
  const std::size_t n = records.size();
  console.summary(fmt::format(
      "{}, {}, {}: {} points ({} run{}, {} kept from the earlier run){}\n", plan.csv, plan.json, plan.html, n, ran,
      ranks.size() == 1 ? std::string() : fmt::format(" on {} MPI ranks", ranks.size()), n - ran,
      plan.spec.left_out.total() ? "; " + plan.spec.left_out.summary() : std::string()));
}

// Under MPI, rank 0 tells every failure, its own included, before it tells
// the others the status to end with: a rank that ends with a failing status
// makes mpirun end the job.
int run_sweep(const SweepOptions& o) {
  const int threads = whole_value(checked(o.threads));
  SweepRanks ranks;
  const bool alone = ranks.size() == 1;
  const std::string who = alone ? std::string() : fmt::format("rank {} of {}: ", ranks.rank(), ranks.size());
  // Rank 0 plans; every rank learns the sweep file's text and the points to
  // run, or the status to end with.
  std::unique_ptr<SweepPlan> plan;
  nlohmann::json told;
  if (ranks.rank() == 0) {
    try {
      plan = plan_sweep(o);
      told = {{"text", plan->text}, {"run", plan->to_run}};
    } catch (...) {
      told = {{"status", tell(sweep_failure(std::current_exception()), who)}};
    }
  }
  if (!alone) told = nlohmann::json::parse(ranks.broadcast(told.dump()));
  if (told.contains("status")) return told["status"].get<int>();

  // The k-th point to run goes to rank k mod size.
  const std::vector<std::size_t> to_run = told["run"].get<std::vector<std::size_t>>();
  std::vector<std::size_t> mine;
  for (std::size_t k = static_cast<std::size_t>(ranks.rank()); k < to_run.size();
       k += static_cast<std::size_t>(ranks.size()))
    mine.push_back(to_run[k]);
  Console console(o.quiet);
  if (plan && plan->outputs->stdout_taken()) console.divert_to_stderr();
  sim::SweepSpec other_spec;
  std::vector<nlohmann::json> other_records;
  std::optional<CommandFailure> failed;
  try {
    if (!plan) {
      other_spec = sim::parse_sweep_spec(told["text"].get<std::string>(), o.spec.text);
      other_records.resize(other_spec.points.size());
    }
    run_points(plan ? plan->spec : other_spec, mine, threads, plan ? plan->records : other_records, console, who);
  } catch (...) {
    failed = sweep_failure(std::current_exception());
  }

  // Every other rank's records, or its failure, to rank 0.
  nlohmann::json share = nlohmann::json::object();
  if (failed) {
    share = {{"status", failed->status}, {"error", failed->message}};
  } else if (!plan) {
    share["records"] = nlohmann::json::array();
    for (const std::size_t i : mine) share["records"].push_back({i, other_records[i]});
  }
  const std::vector<std::string> shares = alone ? std::vector<std::string>{share.dump()} : ranks.gather(share.dump());
  if (!plan) return std::stoi(ranks.broadcast(""));
  int status = 0;
  for (std::size_t r = 0; r < shares.size(); ++r) {
    const nlohmann::json got = nlohmann::json::parse(shares[r]);
    const std::string rank = alone ? std::string() : fmt::format("rank {} of {}: ", r, ranks.size());
    if (got.contains("error")) {
      const int s = tell({got["status"].get<int>(), got["error"].get<std::string>()}, rank);
      if (status == 0) status = s;
    } else if (got.contains("records")) {
      for (const nlohmann::json& record : got["records"]) plan->records[record[0].get<std::size_t>()] = record[1];
    }
  }
  if (status == 0) {
    try {
      write_outputs(*plan, o.spec.text, to_run.size(), ranks, console);
    } catch (...) {
      status = tell(sweep_failure(std::current_exception()), who);
    }
  }
  if (!alone) ranks.broadcast(std::to_string(status));
  return status;
}

}  // namespace

Command add_sweep_command(CLI::App& app) {
  auto o = std::make_shared<SweepOptions>();
  CLI::App* cmd = app.add_subcommand(
      "sweep",
      "Simulate every point of a design-space sweep (a JSON file of axes: scenes, cells, modes, balance, voxel_generation, aa, profiles, "
      "sizes, grid, primary_only, frame_average) into PREFIX.csv, PREFIX.json and a page of plots, PREFIX.html "
      "(docs/sweeps.md); built with MPI, under mpirun the ranks share the points");
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
