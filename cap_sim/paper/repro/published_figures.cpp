#include "paper/repro/published_figures.h"

#include "paper/calibration/calibration.h"
#include "paper/repro/paper_figures.h"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <cmath>

namespace capsim::sim {

namespace {

WorkCounts counts_of(const RunFigures& f) { return {f.ops, f.pixels, f.voxels}; }

FigureModel one(LinearTime t) {
  FigureModel m;
  m.parts.push_back(std::move(t));
  return m;
}

// Max or Min over the cells of a run: each cell's "done" at the host, after
// the host's voxel generation.
FigureModel over_cells(const RunFigures& f, Machine machine, Combine combine) {
  FigureModel m;
  m.combine = combine;
  for (const CellWork& c : f.cells)
    m.parts.push_back(linear_time(f.seconds(c.finish), {c.ops, c.pixels, f.voxels}, f.profile, machine));
  return m;
}

// A sequence's time follows, in proportion, the mean cell's busy time plus
// the host's voxel generation.
FigureModel sequence(const Table45Run& run) {
  const LinearTime cells = linear_time(run.busy_seconds, run.cell_work, run.profile, Machine::Cap);
  const LinearTime host = linear_time(run.voxel_generation_seconds, {{}, 0, run.voxels}, run.profile, Machine::Cap,
                                      CostCategory::VoxelGeneration);
  const double n = run.cells;
  LinearTime mean;
  mean.fixed = cells.fixed / n + host.fixed;
  for (std::size_t k = 0; k < cells.per_param.size(); ++k)
    mean.per_param.push_back(cells.per_param[k] / n + host.per_param[k]);
  FigureModel m;
  m.combine = Combine::Scaled;
  m.parts.push_back(mean);
  const double base = run.busy_seconds / n + run.voxel_generation_seconds;
  m.scale = base > 0 ? run.seconds / base : 1;
  return m;
}

const char* kSameRunWhy =
    "Table 5-1 gives the same run (64 cells, dot mode) as {} s; Table 4-4's {} s and it cannot both hold";
const char* kSameRunWhy51 =
    "Table 4-4 gives the same run (64 cells, dot mode) a Max of {} s; it and Table 5-1's {} s cannot both hold";

}  // namespace

std::vector<ComparedFigure> compared_figures(const ReproResult& r, Exclusions exclusions) {
  std::vector<ComparedFigure> out;
  auto add = [&](std::string table, std::string row, std::string column, std::string quantity, double ours,
                 double paper, std::optional<FigureModel> model = std::nullopt) -> ComparedFigure& {
    out.push_back({std::move(table), std::move(row), std::move(column), std::move(quantity), ours, paper, false, "",
                   std::move(model)});
    return out.back();
  };

  const Table42& t42 = r.table_4_2;
  for (int row = 0; row < 5; ++row) {
    for (int col = 0; col < 7; ++col) {
      const RunFigures& f = t42.cells[row][col];
      add("4-2", std::to_string(paper::kTable42Objects[row]), std::to_string(paper::kTable42Divisions[col]),
          "seconds", f.frame_seconds(), paper::kTable42Seconds[row][col],
          one(linear_time(f.frame_seconds(), counts_of(f), f.profile, Machine::M380)));
    }
  }
  for (int row = 0; row < 5; ++row) {
    const Table42Row ours = table_4_2_row(t42, row), theirs = table_4_2_paper_row(row);
    add("4-2", std::to_string(paper::kTable42Objects[row]), "optimum", "divisions",
        paper::kTable42Divisions[ours.best_column], paper::kTable42Divisions[theirs.best_column]);
    add("4-2", std::to_string(paper::kTable42Objects[row]), "speed-up", "ratio", ours.speedup, theirs.speedup);
  }

  for (int i = 0; i < 3; ++i) {
    const RunFigures& f = r.table_4_3.runs[i];
    const std::string row = fmt::format("PISTON, {} divisions", paper::kTable43Divisions[i]);
    const double total = f.total_seconds();
    for (int k = 0; k < kCostCategories; ++k) {
      const CostCategory c = kCostCategoryTable[k].category;
      add("4-3", row, to_string(c), "seconds", f.category_seconds(c), paper::kTable43Seconds[i][k],
          one(linear_time(f.category_seconds(c), counts_of(f), f.profile, Machine::M380, c)));
    }
    for (int k = 0; k < kCostCategories; ++k) {
      const CostCategory c = kCostCategoryTable[k].category;
      const double share = 100 * f.category_seconds(c) / total;
      add("4-3", row, fmt::format("{} share", to_string(c)), "percent", share, paper::kTable43Percent[i][k]);
      add("4-3", row, fmt::format("{} share (renormalised)", to_string(c)), "percent", share,
          paper::table_4_3_renormalised_percent(i, k));
    }
  }

  for (int i = 0; i < 3; ++i) {
    const paper::Table44Row& p = paper::kTable44[i];
    const ModeSpread& m = r.table_4_4.rows[i];
    const bool excluded = exclusions == Exclusions::Table44ChessCad && i > 0;
    const double t51 = paper::kTable51[i == 1 ? 0 : 3].cap;  // CHESS or CAD
    for (const auto& [mode, f, pf] : {std::tuple{"line", &m.line, p.line}, std::tuple{"dot", &m.dot, p.dot}}) {
      ComparedFigure& mx = add("4-4", p.model, fmt::format("{} Max", mode), "seconds",
                               f->seconds(f->spread.max_finish), pf.max, over_cells(*f, Machine::Cap, Combine::Max));
      ComparedFigure& mn = add("4-4", p.model, fmt::format("{} Min", mode), "seconds",
                               f->seconds(f->spread.min_finish), pf.min, over_cells(*f, Machine::Cap, Combine::Min));
      for (ComparedFigure* c : {&mx, &mn}) {
        c->excluded = excluded;
        if (excluded) c->why = fmt::format(fmt::runtime(kSameRunWhy), t51, p.dot.max);
      }
      add("4-4", p.model, fmt::format("{} d", mode), "percent", f->spread.deviation_percent, pf.d);
    }
  }

  {
    const Graph43& g = r.graph_4_3;
    add("graph 4-3", "CHESS", "dot speed at 64 cells", "ratio",
        static_cast<double>(g.dot.front().frame.count()) / static_cast<double>(g.dot.back().frame.count()),
        paper::kGraph43DotSpeedAt64);
  }

  const Table45& t45 = r.table_4_5;
  if (t45.frames > 0) {
    for (int i = 0; i < 3; ++i) {
      const paper::Table45Row& p = paper::kTable45[i];
      ComparedFigure& c = add("4-5", p.processing, "time", "seconds", t45.runs[i].seconds, p.seconds,
                              sequence(t45.runs[i]));
      if (t45.frames != 64) {
        c.excluded = true;
        c.why = fmt::format("only {} of the 64 frames were run", t45.frames);
      }
    }
    for (int i = 0; i < 3; ++i)
      add("4-5", paper::kTable45[i].processing, "max deviation", "percent", t45.runs[i].max_deviation_percent,
          paper::kTable45[i].max_deviation);
  }

  for (int i = 0; i < 4; ++i) {
    const paper::Table51Row& p = paper::kTable51[i];
    const RunFigures& cap = r.table_5_1.cap[i];
    const RunFigures& m380 = r.table_5_1.m380[i];
    ComparedFigure& c = add("5-1", p.model, "CAP", "seconds", cap.frame_seconds(), p.cap,
                            over_cells(cap, Machine::Cap, Combine::Max));
    if (exclusions == Exclusions::Table51ChessCad && (i == 0 || i == 3)) {
      c.excluded = true;
      c.why = fmt::format(fmt::runtime(kSameRunWhy51), paper::kTable44[i == 0 ? 1 : 2].dot.max, p.cap);
    }
    add("5-1", p.model, "M380", "seconds", m380.frame_seconds(), p.m380,
        one(linear_time(m380.frame_seconds(), counts_of(m380), m380.profile, Machine::M380)));
    add("5-1", p.model, "CAP / M380", "ratio", cap.frame_seconds() / m380.frame_seconds(), p.cap / p.m380);
  }
  return out;
}

std::vector<const ComparedFigure*> fitted_figures(const std::vector<ComparedFigure>& all) {
  std::vector<const ComparedFigure*> out;
  for (const ComparedFigure& f : all)
    if (f.model) out.push_back(&f);
  return out;
}

namespace {

// The fitted times not excluded, of one table or (empty) of all.
std::vector<const ComparedFigure*> counted(const std::vector<ComparedFigure>& all, const std::string& table) {
  std::vector<const ComparedFigure*> out;
  for (const ComparedFigure* f : fitted_figures(all))
    if (!f->excluded && (table.empty() || f->table == table)) out.push_back(f);
  return out;
}

double rms_log_of(const std::vector<const ComparedFigure*>& figures) {
  std::vector<double> ours, paper;
  for (const ComparedFigure* f : figures) {
    ours.push_back(f->ours);
    paper.push_back(f->paper);
  }
  return figures.empty() ? 0 : rms_log_error(ours, paper);
}

}  // namespace

std::vector<TableError> table_errors(const std::vector<ComparedFigure>& all) {
  std::vector<TableError> out;
  for (const char* table : {"4-2", "4-3", "4-4", "4-5", "5-1"}) {
    const std::vector<const ComparedFigure*> figures = counted(all, table);
    if (figures.empty()) continue;
    TableError e;
    e.table = table;
    e.figures = static_cast<int>(figures.size());
    e.rms_log = rms_log_of(figures);
    double worst = -1;
    for (const ComparedFigure* f : figures) {
      const double l = std::abs(std::log(f->ours / f->paper));
      if (l > worst) {
        worst = l;
        e.worst = *f;
      }
    }
    out.push_back(e);
  }
  return out;
}

double overall_rms_log(const std::vector<ComparedFigure>& all) { return rms_log_of(counted(all, "")); }

std::string reproduction_json(const ReproResult& r, const std::vector<ComparedFigure>& all,
                              const std::string& capsim_version) {
  nlohmann::ordered_json j;
  j["capsim_version"] = capsim_version;
  nlohmann::ordered_json& a = j["assumptions"];
  a["screen"] = {{"cap", fmt::format("{}x{}", r.options.width, r.options.height)},
                 {"m380", fmt::format("{}x{}", r.options.m380_width, r.options.m380_height)}};
  a["primary_only"] = r.options.table_4_2_primary_only;
  a["cap_over_m380"] = paper::kCapOverM380;
  for (const auto& [name, f] : {std::pair{"cap", &r.table_4_4.rows[0].dot}, std::pair{"m380", &r.table_4_3.runs[0]}}) {
    nlohmann::ordered_json costs;
    for (const FitParameter& p : fit_parameters())
      costs[profile_key(p.term)] =
          static_cast<double>(f->profile.costs[p.term].count()) * 1e6 / static_cast<double>(f->profile.clock_hz);
    a["fitted_costs_us"][name] = costs;
  }
  nlohmann::ordered_json& tables = j["tables"];
  tables = nlohmann::ordered_json::array();
  for (const TableError& e : table_errors(all))
    tables.push_back({{"table", e.table},
                      {"figures", e.figures},
                      {"rms_ln_ratio", e.rms_log},
                      {"worst", {{"row", e.worst.row}, {"column", e.worst.column}, {"ours", e.worst.ours},
                                 {"paper", e.worst.paper}}}});
  j["rms_ln_ratio"] = overall_rms_log(all);
  nlohmann::ordered_json& figures = j["figures"];
  figures = nlohmann::ordered_json::array();
  for (const ComparedFigure& f : all)
    figures.push_back({{"table", f.table},
                       {"row", f.row},
                       {"column", f.column},
                       {"quantity", f.quantity},
                       {"ours", f.ours},
                       {"paper", f.paper},
                       {"fitted", f.model.has_value()},
                       {"excluded", f.excluded},
                       {"why", f.why}});
  return j.dump(2) + "\n";
}

}  // namespace capsim::sim
