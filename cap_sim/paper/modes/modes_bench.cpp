#include "paper/modes/modes_bench.h"

#include "report/svg_plot.h"

#include "capsim/system/host_threads.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>

namespace capsim::sim {

namespace {

using nlohmann::json;

std::string run_name(const std::string& model, const std::string& scheme, const std::string& cells, int aa) {
  return fmt::format("{} {} {} aa{}", model, scheme, cells, aa);
}

std::string run_name(const json& run) {
  const json& scheme = run.contains("balance") ? run.at("balance") : run.at("mode");
  return run_name(run.at("model").get<std::string>(), scheme.get<std::string>(), run.at("cells").get<std::string>(),
                  run.at("aa").get<int>());
}

std::string model_name(const std::string& file) {
  return file.size() > 4 && file.ends_with(".csg") ? file.substr(0, file.size() - 4) : file;
}

}  // namespace

const std::vector<std::string>& modes_bench_models() {
  static const std::vector<std::string> models = {"balls.csg", "chess.csg", "piston.csg", "cad.csg",
                                                  "disb/f00000.csg"};
  return models;
}

const std::vector<CellGrid>& modes_bench_grids() {
  static const std::vector<CellGrid> grids = {{4, 4}, {4, 8}, {8, 8}, {16, 16}};
  return grids;
}

const std::vector<int>& modes_bench_aa_depths() {
  static const std::vector<int> depths = {0, 2};
  return depths;
}

const std::vector<std::string>& modes_bench_schemes() {
  static const std::vector<std::string> schemes = {"block", "line", "dot",
                                                   to_string(BalanceOptions{BalanceScheme::Demand}),
                                                   to_string(BalanceOptions{BalanceScheme::Steal})};
  return schemes;
}

std::string ModeRun::scheme() const { return balance.is_static() ? to_string(mode) : to_string(balance); }

ModesBench run_modes_bench(const ModesBenchOptions& options) {
  ModesBench b;
  b.options = options;
  b.options.log = nullptr;
  // A model's runs at one antialiasing depth trace the same screen: it is
  // traced once, on every thread, and its twenty runs then go on the host
  // threads at once, each on one (their figures do not depend on it).
  ScreenTraces traces;
  std::mutex log_lock;
  for (const std::string& file : modes_bench_models())
    for (int aa : modes_bench_aa_depths()) {
      std::vector<RunSpec> specs;
      const std::size_t first = b.runs.size();
      for (const std::string& scheme : modes_bench_schemes())
        for (const CellGrid& grid : modes_bench_grids()) {
          ModeRun r;
          if (const auto mode = parse_pixel_mode(scheme))
            r.mode = *mode;
          else
            r.balance = parse_balance(scheme);
          RunSpec s;
          s.scene = options.scenes_dir + "/" + file;
          s.width = options.width;
          s.height = options.height;
          s.cells = grid;
          s.mode = r.mode;
          s.balance = r.balance;
          s.aa_depth = aa;
          r.model = model_name(file);
          r.cells = grid;
          r.aa_depth = aa;
          specs.push_back(std::move(s));
          b.runs.push_back(std::move(r));
        }
      const ScreenTrace& screen = traces.trace(specs[0], options.threads);
      parallel_rows(options.threads, static_cast<int>(specs.size()), [&](const tbb::blocked_range<int>& range) {
        for (int k = range.begin(); k != range.end(); ++k) {
          ModeRun& r = b.runs[first + static_cast<std::size_t>(k)];
          if (options.log) {
            const std::lock_guard<std::mutex> hold(log_lock);
            options.log(run_name(r.model, r.scheme(), to_string(r.cells), aa));
          }
          r.figures = run_experiment(specs[static_cast<std::size_t>(k)], 1, screen);
        }
      });
    }
  // Speed-up against the same model, antialiasing and scheme on the first grid (4x4).
  for (ModeRun& r : b.runs) {
    const auto base = std::find_if(b.runs.begin(), b.runs.end(), [&](const ModeRun& o) {
      return o.model == r.model && o.aa_depth == r.aa_depth && o.scheme() == r.scheme() &&
             o.cells == modes_bench_grids()[0];
    });
    r.speedup = static_cast<double>(base->figures.frame.count()) / static_cast<double>(r.figures.frame.count());
  }
  return b;
}

json modes_bench_json(const ModesBench& b) {
  json runs = json::array();
  for (const ModeRun& r : b.runs) {
    const RunFigures& f = r.figures;
    json run = {
        {"model", r.model},
        {r.balance.is_static() ? "mode" : "balance", r.scheme()},
        {"cells", to_string(r.cells)},
        {"aa", r.aa_depth},
        {"frame_cycles", f.frame.count()},
        {"max_cycles", f.spread.max_finish.count()},
        {"min_cycles", f.spread.min_finish.count()},
        {"deviation_percent", f.spread.deviation_percent},
        {"speedup_vs_4x4", r.speedup},
        {"bus_transfers", f.bus.transfers},
        {"bus_bytes", f.bus.bytes},
        {"bus_busy_cycles", f.bus.busy.count()},
        {"link_messages", f.links.messages},
        {"link_bytes", f.links.bytes},
        {"link_hops", f.links.hops},
        {"busiest_link_cycles", f.links.busiest.count()},
    };
    if (r.balance.on_demand())
      run.update({{"balance_bus_percent", f.balance_bus_percent}, {"tile_wait_cycles", f.tile_wait.count()}});
    if (r.balance.stealing())
      run.update({{"chunks_stolen", f.chunks_stolen}, {"steal_link_bytes", f.steal_link_bytes}});
    runs.push_back(std::move(run));
  }
  return {{"benchmark", "capsim bench modes"},
          {"size", fmt::format("{}x{}", b.options.width, b.options.height)},
          {"profile", "cap"},
          {"clock_hz", b.runs.empty() ? 0 : b.runs[0].figures.clock_hz},
          {"runs", runs}};
}

std::string modes_bench_table(const ModesBench& b) {
  std::string s = fmt::format("capsim bench modes: {}x{} pixels, cap profile; seconds simulated\n\n",
                              b.options.width, b.options.height);
  s += fmt::format("{:<12} {:<9} {:>5} {:>3} {:>10} {:>10} {:>10} {:>7} {:>8} {:>10} {:>9} {:>9} {:>11}\n", "model",
                   "scheme", "cells", "aa", "frame s", "Max s", "Min s", "d %", "speedup", "bus bytes", "bus s",
                   "link msgs", "link bytes");
  for (const ModeRun& r : b.runs) {
    const RunFigures& f = r.figures;
    s += fmt::format("{:<12} {:<9} {:>5} {:>3} {:>10.3f} {:>10.3f} {:>10.3f} {:>7.2f} {:>8.3f} {:>10} {:>9.4f} {:>9} {:>11}\n",
                     r.model, r.scheme(), to_string(r.cells), r.aa_depth, f.frame_seconds(),
                     f.seconds(f.spread.max_finish), f.seconds(f.spread.min_finish), f.spread.deviation_percent,
                     r.speedup, f.bus.bytes, f.seconds(f.bus.busy), f.links.messages, f.links.bytes);
  }
  return s;
}

std::string modes_bench_svg(const ModesBench& b) {
  // Plain frames: d and speed-up against the cell count, a colour per model
  // and a dash per scheme.
  std::vector<std::string> models;
  for (const ModeRun& r : b.runs)
    if (std::find(models.begin(), models.end(), r.model) == models.end()) models.push_back(r.model);
  const std::vector<std::string>& schemes = modes_bench_schemes();
  const char* dashes[5] = {"", "6 4", "2 3", "10 3 2 3", "1 4"};
  std::vector<PlotSeries> d_series, speed_series;
  double d_lo = 100, d_hi = 0.1;
  for (std::size_t m = 0; m < models.size(); ++m)
    for (std::size_t k = 0; k < schemes.size(); ++k) {
      PlotSeries d = plot_series(fmt::format("{} {}", models[m], schemes[k]), series_colour(static_cast<int>(m)),
                                 dashes[k % 5]);
      PlotSeries sp = d;
      for (const ModeRun& r : b.runs) {
        if (r.model != models[m] || r.scheme() != schemes[k] || r.aa_depth != 0) continue;
        const double cells = r.cells.cell_count();
        const double dev = std::max(r.figures.spread.deviation_percent, 0.01);
        d_lo = std::min(d_lo, dev);
        d_hi = std::max(d_hi, dev);
        d.points.push_back({cells, dev});
        sp.points.push_back({cells, r.speedup});
      }
      d_series.push_back(d);
      speed_series.push_back(sp);
    }
  PlotAxes d;
  d.title = "d = (Max - Min) / Max, plain frames";
  d.x_label = "cells";
  d.y_label = "d (%)";
  d.log_x = d.log_y = true;
  d.x_min = 12;
  d.x_max = 320;
  d.x_ticks = {16, 32, 64, 256};
  d.y_min = std::pow(10.0, std::floor(std::log10(d_lo)));
  d.y_max = std::pow(10.0, std::ceil(std::log10(d_hi)));
  for (double y = d.y_min; y <= d.y_max * 1.0001; y *= 10) d.y_ticks.push_back(y);
  PlotAxes s = d;
  s.title = "speed relative to 4x4 cells, plain frames";
  s.y_label = "speed (4x4 = 1)";
  s.y_min = 0.5;
  s.y_max = 32;
  s.y_ticks = {0.5, 1, 2, 4, 8, 16, 32};
  const double w = 620, h = 420;
  return svg_document(2 * w, h, plot_panel_svg(d, d_series, 0, 0, w, h) + plot_panel_svg(s, speed_series, w, 0, w, h));
}

std::vector<MovedFigure> compare_modes_bench(const json& baseline, const json& now) {
  for (const char* key : {"size", "profile"})
    if (baseline.at(key) != now.at(key))
      throw std::runtime_error(fmt::format("the baseline's {} is {} where this run's is {}", key,
                                           baseline.at(key).dump(), now.at(key).dump()));
  std::map<std::string, const json*> current;
  for (const json& r : now.at("runs")) current[run_name(r)] = &r;
  std::vector<MovedFigure> moved;
  std::map<std::string, bool> seen;
  for (const json& old_run : baseline.at("runs")) {
    const std::string name = run_name(old_run);
    seen[name] = true;
    const auto it = current.find(name);
    if (it == current.end()) {
      moved.push_back({name, "(run)", "present", "absent", 0});
      continue;
    }
    for (const auto& [metric, old_value] : old_run.items()) {
      const json& new_value = it->second->contains(metric) ? it->second->at(metric) : json();
      if (old_value == new_value) continue;
      MovedFigure f{name, metric, old_value.dump(), new_value.is_null() ? "absent" : new_value.dump(), 0};
      if (old_value.is_number() && new_value.is_number() && old_value.get<double>() != 0)
        f.ratio = new_value.get<double>() / old_value.get<double>();
      moved.push_back(f);
    }
    for (const auto& [metric, value] : it->second->items())
      if (!old_run.contains(metric)) moved.push_back({name, metric, "absent", value.dump(), 0});
  }
  for (const json& r : now.at("runs"))
    if (!seen.count(run_name(r))) moved.push_back({run_name(r), "(run)", "absent", "present", 0});
  return moved;
}

std::string format_moved(const std::vector<MovedFigure>& moved) {
  std::size_t run_w = 3, metric_w = 6, old_w = 3, new_w = 3;
  for (const MovedFigure& m : moved) {
    run_w = std::max(run_w, m.run.size());
    metric_w = std::max(metric_w, m.metric.size());
    old_w = std::max(old_w, std::min<std::size_t>(m.old_value.size(), 40));
    new_w = std::max(new_w, std::min<std::size_t>(m.new_value.size(), 40));
  }
  std::string s = fmt::format("{:<{}}  {:<{}}  {:>{}}  {:>{}}  {:>10}\n", "run", run_w, "metric", metric_w, "old",
                              old_w, "new", new_w, "new/old");
  for (const MovedFigure& m : moved)
    s += fmt::format("{:<{}}  {:<{}}  {:>{}}  {:>{}}  {:>10}\n", m.run, run_w, m.metric, metric_w, m.old_value, old_w,
                     m.new_value, new_w, m.ratio > 0 ? fmt::format("{:.6f}", m.ratio) : std::string("-"));
  return s;
}

}  // namespace capsim::sim
