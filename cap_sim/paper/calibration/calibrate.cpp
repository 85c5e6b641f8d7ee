#include "paper/calibration/calibrate.h"

#include "paper/calibration/calibration.h"

#include <fmt/core.h>

#include <limits>

namespace capsim::sim {

namespace {

struct Evaluated {
  std::vector<ComparedFigure> figures;
  double rms = 0;
};

// Every experiment run at the costs x, and its figures beside the paper's.
Evaluated run_at(const CalibrationOptions& o, const std::vector<double>& x) {
  ReproOptions repro = o.repro;
  repro.cap_costs = calibrated_profile(x, Machine::Cap);
  repro.m380_costs = calibrated_profile(x, Machine::M380);
  repro.log = nullptr;
  const ReproResult result = run_reproduction(repro);
  Evaluated e;
  e.figures = compared_figures(result, o.exclusions);
  e.rms = overall_rms_log(e.figures);
  return e;
}

}  // namespace

Calibration calibrate(const CalibrationOptions& o, const std::function<void(const std::string&)>& log) {
  auto say = [&](const std::string& s) {
    if (log) log(s);
  };
  Calibration c;
  std::vector<double> x =
      parameter_values(o.repro.m380_costs ? *o.repro.m380_costs : load_cost_profile("m380"), Machine::M380);
  double model_rms = std::numeric_limits<double>::quiet_NaN();
  double best_rms = std::numeric_limits<double>::infinity();
  for (int round = 0; round <= o.rounds; ++round) {
    const Evaluated e = run_at(o, x);
    c.rounds.push_back({x, e.rms, model_rms});
    say(fmt::format("round {}: rms ln(ours / paper) {:.4f} from the runs{}", round, e.rms,
                    round ? fmt::format(", {:.4f} by the fit's model", model_rms) : ""));
    if (e.rms < best_rms) {
      best_rms = e.rms;
      c.best = c.rounds.size() - 1;
      c.best_tables = table_errors(e.figures);
    }
    if (round == o.rounds) break;
    std::vector<FigureModel> models;
    std::vector<double> targets;
    for (const ComparedFigure* f : fitted_figures(e.figures)) {
      if (f->excluded) continue;
      models.push_back(*f->model);
      targets.push_back(f->paper);
    }
    const LogFitResult fit = fit_log_least_squares(models, targets, x);
    x = fit.x;
    model_rms = fit.rms_log;
  }
  return c;
}

std::vector<Alternative> calibration_alternatives(const CalibrationOptions& base) {
  std::vector<Alternative> out;
  auto add = [&](std::string name, auto change) {
    CalibrationOptions o = base;
    change(o);
    out.push_back({std::move(name), o});
  };
  add("shipped: CAP 384 x 384, M380 512 x 512, Table 4-2 all rays, Table 4-4 CHESS and CAD left out",
      [](CalibrationOptions&) {});
  for (const auto& [w, h] : {std::pair{256, 256}, std::pair{320, 240}, std::pair{512, 512}})
    add(fmt::format("CAP {} x {}", w, h), [w = w, h = h](CalibrationOptions& o) {
      o.repro.width = w;
      o.repro.height = h;
    });
  for (const auto& [w, h] : {std::pair{384, 384}, std::pair{256, 256}})
    add(fmt::format("M380 {} x {}", w, h), [w = w, h = h](CalibrationOptions& o) {
      o.repro.m380_width = w;
      o.repro.m380_height = h;
    });
  add("Table 4-2 primary rays only", [](CalibrationOptions& o) { o.repro.table_4_2_primary_only = true; });
  add("Table 5-1 CHESS and CAD left out instead", [](CalibrationOptions& o) {
    o.exclusions = Exclusions::Table51ChessCad;
  });
  add("nothing left out", [](CalibrationOptions& o) { o.exclusions = Exclusions::None; });
  return out;
}

std::string alternatives_markdown(const std::vector<AlternativeResult>& results) {
  std::string md = "| assumptions | all | 4-2 | 4-3 | 4-4 | 4-5 | 5-1 |\n|---|---|---|---|---|---|---|\n";
  for (const AlternativeResult& r : results) {
    md += fmt::format("| {} | {:.3f} |", r.name, r.calibration.rounds[r.calibration.best].simulated_rms);
    for (const char* table : {"4-2", "4-3", "4-4", "4-5", "5-1"}) {
      std::string cell = " - |";
      for (const TableError& t : r.calibration.best_tables)
        if (t.table == table) cell = fmt::format(" {:.3f} |", t.rms_log);
      md += cell;
    }
    md += "\n";
  }
  return md;
}

}  // namespace capsim::sim
