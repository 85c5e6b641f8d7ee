#include "paper/repro/repro.h"

#include "paper/repro/paper_figures.h"
#include "paper/simulate_command.h"

#include "capsim/scene/parser.h"
#include "capsim/trace/prepared_scene.h"
#include "capsim/trace/tracer.h"

#include <fmt/core.h>

#include <memory>

namespace capsim::sim {

namespace {

class Runner {
 public:
  explicit Runner(const ReproOptions& o) : o_(o) {}

  // A run of a model on the CAP (8 x 8 cells, dot mode).
  RunSpec model(const std::string& file) const {
    RunSpec s;
    s.scene = o_.scenes_dir + "/" + file;
    s.width = o_.width;
    s.height = o_.height;
    s.costs = o_.cap_costs;
    return s;
  }

  // The same run on the M380: one cell, its own screen and profile.
  RunSpec on_m380(RunSpec s) const {
    s.cells = {1, 1};
    s.profile = "m380";
    s.costs = o_.m380_costs;
    s.width = o_.m380_width;
    s.height = o_.m380_height;
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
  for (int row = 0; row < 5; ++row) {
    const LatticeShape shape = lattice_shape(paper::kTable42Objects[row]);
    t.shapes.push_back(shape);
    for (int col = 0; col < 7; ++col) {
      RunSpec s;
      s.lattice = shape;
      s = runner.on_m380(s);
      s.grid = paper::kTable42Divisions[col];
      s.primary_only = o.table_4_2_primary_only;
      t.cells[row][col] = runner.run(
          s, fmt::format("Table 4-2: {} spheres, {} divisions", shape.count(), paper::kTable42Divisions[col]));
    }
  }
  return t;
}

Table43 run_table_4_3(const Runner& runner) {
  Table43 t;
  for (int i = 0; i < 3; ++i) {
    RunSpec s = runner.on_m380(runner.model("piston.csg"));
    s.grid = paper::kTable43Divisions[i];
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
    config.profile = o.cap_costs ? *o.cap_costs : load_cost_profile("cap");
    config.screen = ScreenFormat::Srgb8;
    config.aa.depth = i == 0 ? 0 : 2;
    config.frame_average = i == 2;
    if (o.log) o.log(fmt::format("Table 4-5: DISB, {} frames, {}", t.frames, paper::kTable45[i].processing));
    const SimulationResult r = simulate_frames(frames, config, o.threads, false);
    t.runs[i].frame = r.frame;
    t.runs[i].seconds = r.frame.seconds(config.profile.clock_hz);
    t.runs[i].max_deviation_percent = max_deviation_percent(r);
    if (config.frame_average) t.frames_per_unit = r.config.frame_average_group;
    t.runs[i].profile = config.profile;
    t.runs[i].cells = static_cast<int>(r.cells.size());
    Cycles busy;
    for (const CellReport& c : r.cells) {
      t.runs[i].cell_work.ops += c.ops;
      t.runs[i].cell_work.pixels += c.pixels;
      busy += c.busy;
    }
    t.runs[i].busy_seconds = busy.seconds(config.profile.clock_hz);
    t.runs[i].voxels = r.voxel_counts;
    t.runs[i].voxel_generation_seconds =
        r.breakdown[CostCategory::VoxelGeneration].seconds(config.profile.clock_hz);
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
    s = runner.on_m380(s);
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
