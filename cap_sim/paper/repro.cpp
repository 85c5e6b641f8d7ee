#include "paper/repro.h"

#include "paper/paper_figures.h"
#include "paper/simulate_command.h"

#include "capsim/parser.h"
#include "capsim/prepared_scene.h"
#include "capsim/tracer.h"

#include <fmt/core.h>

#include <memory>

namespace capsim::sim {

std::vector<CostTerm> shipped_fitted_costs() { return {CostTerm::RayOther, CostTerm::VoxelVisit}; }

namespace {

class Runner {
 public:
  explicit Runner(const ReproOptions& o) : o_(o) {}

  RunSpec model(const std::string& file) const {
    RunSpec s;
    s.scene = o_.scenes_dir + "/" + file;
    s.width = o_.width;
    s.height = o_.height;
    return s;
  }

  RunFigures run(const RunSpec& spec, const std::string& what) const {
    if (o_.log) o_.log(what);
    RunFigures f = run_experiment(spec, o_.threads);
    // Commands name the scenes as the repository holds them.
    return f;
  }

  const ReproOptions& options() const { return o_; }

 private:
  const ReproOptions& o_;
};

Table42 table_4_2(const Runner& runner) {
  Table42 t;
  const ReproOptions& o = runner.options();
  const CostProfile m380 = load_cost_profile("m380");
  for (int row = 0; row < 5; ++row) {
    const LatticeShape shape = lattice_shape(paper::kTable42Objects[row]);
    t.shapes.push_back(shape);
    for (int col = 0; col < 7; ++col) {
      RunSpec s;
      s.lattice = shape;
      s.width = o.width;
      s.height = o.height;
      s.grid = paper::kTable42Divisions[col];
      s.primary_only = true;
      s.cells = {1, 1};
      s.profile = "m380";
      t.cells[row][col] = runner.run(
          s, fmt::format("Table 4-2: {} spheres, {} divisions", shape.count(), paper::kTable42Divisions[col]));
      FitCell cell;
      cell.paper_seconds = paper::kTable42Seconds[row][col];
      cell.simulated_seconds = t.cells[row][col].frame_seconds();
      cell.ops = t.cells[row][col].ops;
      cell.pixels = t.cells[row][col].pixels;
      cell.voxels = t.cells[row][col].voxels;
      t.fit_cells.push_back(cell);
    }
  }
  t.as_shipped = evaluate_costs(t.fit_cells);
  t.shipped_fit = fit_costs(t.fit_cells, m380, shipped_fitted_costs());
  t.full_fit = fit_costs(t.fit_cells, m380, all_fitted_costs());
  return t;
}

Table43 run_table_4_3(const Runner& runner) {
  Table43 t;
  for (int i = 0; i < 3; ++i) {
    RunSpec s = runner.model("piston.csg");
    s.grid = paper::kTable43Divisions[i];
    s.cells = {1, 1};
    s.profile = "m380";
    t.runs[i] = runner.run(s, fmt::format("Table 4-3: PISTON, {} divisions", s.grid));
  }
  return t;
}

Table44 run_table_4_4(const Runner& runner) {
  Table44 t;
  const char* files[3] = {"balls.csg", "chess.csg", "cad.csg"};
  for (int i = 0; i < 3; ++i) {
    RunSpec s = runner.model(files[i]);
    s.mode = PixelMode::Line;
    t.rows[i].line = runner.run(s, fmt::format("Table 4-4: {}, line mode", paper::kTable44[i].model));
    s.mode = PixelMode::Dot;
    t.rows[i].dot = runner.run(s, fmt::format("Table 4-4: {}, dot mode", paper::kTable44[i].model));
  }
  return t;
}

Graph43 run_graph_4_3(const Runner& runner, const Table44& t44) {
  Graph43 g;
  g.grids = {{4, 4}, {4, 8}, {8, 8}};
  for (const CellGrid& grid : g.grids) {
    if (grid == CellGrid{8, 8}) {  // Table 4-4's CHESS runs
      g.line.push_back(t44.rows[1].line);
      g.dot.push_back(t44.rows[1].dot);
      continue;
    }
    RunSpec s = runner.model("chess.csg");
    s.cells = grid;
    s.mode = PixelMode::Line;
    g.line.push_back(runner.run(s, fmt::format("Graph 4-3: CHESS, {} cells, line mode", to_string(grid))));
    s.mode = PixelMode::Dot;
    g.dot.push_back(runner.run(s, fmt::format("Graph 4-3: CHESS, {} cells, dot mode", to_string(grid))));
  }
  return g;
}

// The first `frames` DISB frames as a shell names them: all 64 by a glob
// (which the shell sorts), fewer one by one.
std::string disb_files(const std::string& dir, int frames) {
  if (frames == 64) return dir + "/disb/f*.csg";
  std::string files;
  for (int f = 0; f < frames; ++f) files += fmt::format("{}{}/disb/f{:05}.csg", f == 0 ? "" : " ", dir, f);
  return files;
}

Table45 run_table_4_5(const ReproOptions& o) {
  Table45 t;
  t.frames = o.table_4_5_frames;
  if (t.frames <= 0) return t;
  std::vector<PreparedScene> scenes;
  scenes.reserve(t.frames);
  PrepareOptions prep;  // DISB's own screen, whatever the other experiments' (scenes/disb.scad)
  prep.width = kDisbSide;
  prep.height = kDisbSide;
  for (int f = 0; f < t.frames; ++f)
    scenes.push_back(prepare_scene(parse_scene_file(fmt::format("{}/disb/f{:05}.csg", o.scenes_dir, f)), prep));
  frame_sequence(scenes);  // one camera for the whole sequence, as `capsim simulate` gives it
  std::vector<std::unique_ptr<Tracer>> tracers;
  std::vector<const Tracer*> frames;
  for (const PreparedScene& s : scenes) {
    tracers.push_back(std::make_unique<Tracer>(s, TraceOptions{}));
    frames.push_back(tracers.back().get());
  }
  for (int i = 0; i < 3; ++i) {
    MachineConfig config;  // 8x8 cells, dot mode
    config.profile = load_cost_profile("cap");
    config.screen = ScreenFormat::Srgb8;
    config.aa.depth = i == 0 ? 0 : 2;
    config.frame_average = i == 2;
    if (o.log) o.log(fmt::format("Table 4-5: DISB, {} frames, {}", t.frames, paper::kTable45[i].processing));
    const SimulationResult r = simulate_frames(frames, config, o.threads, false);
    t.runs[i].frame = r.frame;
    t.runs[i].seconds = r.frame.seconds(config.profile.clock_hz);
    t.runs[i].max_deviation_percent = max_deviation_percent(r);
    if (config.frame_average) t.frames_per_unit = r.config.frame_average_group;
    SimulateSettings run;
    run.scenes = {disb_files(o.scenes_dir, t.frames)};
    run.output = "disb.png";
    run.width = kDisbSide;
    run.height = kDisbSide;
    run.aa.depth = config.aa.depth;
    run.frame_average = config.frame_average;
    t.runs[i].command = simulate_command(run, CommandForm::NonDefaults);
  }
  return t;
}

Table51 run_table_5_1(const Runner& runner, const Table44& t44) {
  Table51 t;
  const char* files[4] = {"chess.csg", "balls.csg", "piston.csg", "cad.csg"};
  const int from_44[4] = {1, 0, -1, 2};
  for (int i = 0; i < 4; ++i) {
    RunSpec s = runner.model(files[i]);
    t.cap[i] = from_44[i] >= 0 ? t44.rows[from_44[i]].dot
                               : runner.run(s, fmt::format("Table 5-1: {} on CAP", paper::kTable51[i].model));
    s.cells = {1, 1};
    s.profile = "m380";
    t.m380[i] = runner.run(s, fmt::format("Table 5-1: {} on the M380", paper::kTable51[i].model));
  }
  return t;
}

}  // namespace

Table42 run_table_4_2(const ReproOptions& options) { return table_4_2(Runner(options)); }

ReproResult run_reproduction(const ReproOptions& options) {
  ReproResult r;
  r.options = options;
  r.options.log = nullptr;
  const Runner runner(options);
  r.table_4_2 = table_4_2(runner);
  r.table_4_3 = run_table_4_3(runner);
  r.table_4_4 = run_table_4_4(runner);
  r.graph_4_3 = run_graph_4_3(runner, r.table_4_4);
  r.table_4_5 = run_table_4_5(options);
  r.table_5_1 = run_table_5_1(runner, r.table_4_4);
  return r;
}

}  // namespace capsim::sim
