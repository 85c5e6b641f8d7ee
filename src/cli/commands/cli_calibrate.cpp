// `capsim calibrate`: the joint fit of the costs the paper does not give to
// every published time (docs/calibration.md), written as the two shipped
// profiles; with --alternatives, the same for every alternative assumption,
// as a Markdown table of their errors.

#include "cli/commands/cli_commands.h"
#include "cli/options/cli_options.h"
#include "cli/cli_outputs.h"
#include "cli/console.h"
#include "cli/shipped_data.h"
#include "paper/calibration/calibrate.h"
#include "paper/calibration/calibration.h"
#include "report/text_output.h"

#include <fmt/core.h>

#include <filesystem>
#include <memory>
#include <tuple>

namespace capsim::cli {

namespace {

struct CalibrateCliOptions {
  std::string profiles = ".";  // the project's own: cap_sim/profiles
  std::string alternatives;  // empty = not run
  OptionText<> rounds{"3"};
  OptionText<> scenes;  // default: the shipped models, found (shipped_data.h)
  OptionText<> threads{"0"};
  bool quiet = false;
};

}  // namespace

Command add_calibrate_command(CLI::App& app) {
  auto o = std::make_shared<CalibrateCliOptions>();
  CLI::App* cmd = app.add_subcommand(
      "calibrate",
      "Fit the costs the paper does not give to all its published times at once (Tables 4-2 to 4-5 and 5-1) and "
      "write the cap and m380 profiles");
  cmd->add_option("--profiles", o->profiles,
                  "Directory the fitted cap.json and m380.json are written to (the project's own: cap_sim/profiles)")
      ->default_val(".");
  cmd->add_option("--alternatives", o->alternatives,
                  "Also calibrate under every alternative assumption (screens, primary rays, exclusions) and "
                  "write their errors here as a Markdown table");
  add_option(*cmd, "--rounds", o->rounds, "Fits, each followed by a run of every experiment",
             whole_number(1, 20).description("1 to 20"))
      ->default_val("3");
  add_scenes_option(*cmd, o->scenes);
  add_option(*cmd, "--threads", o->threads, "Host threads (0 = all); the result does not depend on it",
             host_threads_check())
      ->default_val("0");
  add_quiet_flag(*cmd, o->quiet, "the summary (which round fits best, and its error)");
  return [o] {
    sim::CalibrationOptions options;
    options.rounds = static_cast<int>(whole_value(checked(o->rounds)));
    options.repro.scenes_dir = scenes_dir(o->scenes);
    options.repro.threads = whole_value(checked(o->threads));
    const std::filesystem::path dir(o->profiles);
    std::vector<OutputOption> files = {{"--profiles (cap.json)", (dir / "cap.json").string()},
                                       {"--profiles (m380.json)", (dir / "m380.json").string()}};
    if (!o->alternatives.empty()) files.push_back({"--alternatives", o->alternatives});
    StagedOutputs outputs(files, {});
    Console console(o->quiet);
    if (outputs.stdout_taken()) console.divert_to_stderr();

    const ElapsedLog log(console);
    const sim::Calibration c = sim::calibrate(options, log);
    sim::write_text_file(outputs["--profiles (cap.json)"], sim::calibrated_profile_json(c.x(), sim::Machine::Cap));
    sim::write_text_file(outputs["--profiles (m380.json)"],
                         sim::calibrated_profile_json(c.x(), sim::Machine::M380));
    if (!o->alternatives.empty()) {
      std::vector<sim::AlternativeResult> results;
      for (const sim::Alternative& a : sim::calibration_alternatives(options)) {
        log("alternative: " + a.name);
        results.push_back({a.name, a.name.rfind("shipped", 0) == 0 ? c : sim::calibrate(a.options, log)});
      }
      sim::write_text_file(outputs["--alternatives"], sim::alternatives_markdown(results));
    }
    outputs.commit();
    console.summary(fmt::format("round {} of {} fits best: rms ln(ours / paper) {:.4f}\n", c.best,
                                c.rounds.size() - 1, c.rounds[c.best].simulated_rms));
    for (const OutputOption& f : files) console.summary(fmt::format("{}: written\n", f.path));
    const std::vector<sim::FitParameter> params = sim::fit_parameters();
    for (std::size_t k = 0; k < params.size(); ++k)
      console.detail(fmt::format("  {:<28} {:10.4g} us (M380)\n", sim::profile_key(params[k].term), c.x()[k]));
    return 0;
  };
}

}  // namespace capsim::cli
