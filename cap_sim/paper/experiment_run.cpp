#include "paper/experiment_run.h"

#include "capsim/scene/parser.h"
#include "capsim/trace/prepared_scene.h"
#include "capsim/trace/tracer.h"
#include "paper/simulate_command.h"

#include <fmt/core.h>

#include <memory>
#include <optional>

namespace capsim::sim {

namespace {

std::string lattice_file(const LatticeShape& shape) { return fmt::format("lattice-{}.csg", shape.count()); }

}  // namespace

std::string run_command(const RunSpec& spec) {
  // The shipped models and a lattice file (by default) give a 512x512 screen.
  const bool default_size = spec.width == 512 && spec.height == 512;
  const std::string size = default_size ? "" : fmt::format(" --size {}x{}", spec.width, spec.height);
  SimulateSettings run;
  run.scenes = {spec.lattice ? lattice_file(*spec.lattice) : spec.scene};
  run.output = "screen.png";
  if (!spec.lattice && !default_size) {
    run.width = spec.width;
    run.height = spec.height;
  }
  run.grid = spec.grid;
  run.primary_only = spec.primary_only;
  run.cells = spec.cells;
  run.mode = spec.mode;
  run.profile = spec.profile;
  run.aa.depth = spec.aa_depth;
  run.balance = spec.balance;
  const std::string simulate = simulate_command(run, CommandForm::NonDefaults);
  if (!spec.lattice) return simulate;
  return fmt::format("capsim lattice {} -o {}{} && {}", spec.lattice->count(), run.scenes[0], size, simulate);
}

namespace {

PreparedScene prepared_scene(const RunSpec& spec) {
  PrepareOptions prep;
  prep.grid = spec.grid;
  prep.width = spec.width;
  prep.height = spec.height;
  return prepare_scene(
      spec.lattice ? make_sphere_lattice(*spec.lattice, spec.width, spec.height) : parse_scene_file(spec.scene),
      prep);
}

TraceOptions trace_options(const RunSpec& spec) {
  TraceOptions trace;
  trace.primary_only = spec.primary_only;
  return trace;
}

AntialiasOptions antialiasing(const RunSpec& spec) {
  AntialiasOptions aa;
  aa.depth = spec.aa_depth;  // the default threshold, as the command's
  return aa;
}

// What decides a run's pixels, and so its trace.
struct TraceKey {
  std::string scene;
  int lattice = 0;
  int width = 0, height = 0, grid = 0, aa_depth = 0;
  bool primary_only = false;
  bool operator==(const TraceKey&) const = default;
};

TraceKey trace_key(const RunSpec& s) {
  return {s.lattice ? std::string() : s.scene, s.lattice ? s.lattice->count() : 0, s.width, s.height, s.grid,
          s.aa_depth, s.primary_only};
}

}  // namespace

struct ScreenTraces::Kept {
  TraceKey key;
  PreparedScene scene;
  std::unique_ptr<Tracer> tracer;
  ScreenTrace screen;
};

ScreenTraces::ScreenTraces() = default;
ScreenTraces::~ScreenTraces() = default;

const ScreenTrace& ScreenTraces::trace(const RunSpec& spec, int threads) {
  const TraceKey key = trace_key(spec);
  if (kept_ && kept_->key == key) return kept_->screen;
  kept_.reset();  // the old trace goes before the new one is made
  auto k = std::make_unique<Kept>();
  k->key = key;
  k->scene = prepared_scene(spec);
  k->tracer = std::make_unique<Tracer>(k->scene, trace_options(spec));
  k->screen = trace_screen(*k->tracer, antialiasing(spec), threads);
  kept_ = std::move(k);
  return kept_->screen;
}

namespace {

// The run, from `screen` when it is traced ahead, else tracing it now.
RunFigures run(const RunSpec& spec, int threads, const ScreenTrace* screen) {
  std::optional<PreparedScene> own_scene;
  std::optional<Tracer> own_tracer;
  if (!screen) {
    own_scene.emplace(prepared_scene(spec));
    own_tracer.emplace(*own_scene, trace_options(spec));
  }
  const Tracer& tracer = screen ? *screen->tracer : *own_tracer;
  const PreparedScene& scene = tracer.scene();
  MachineConfig config;
  config.cells = spec.cells;
  config.mode = spec.mode;
  config.profile = spec.costs ? *spec.costs : load_cost_profile(spec.profile);
  config.aa = antialiasing(spec);
  config.balance = spec.balance;
  config.screen = ScreenFormat::Srgb8;  // as for `-o screen.png`; the cycles do not depend on it
  const SimulationResult r =
      screen ? simulate_traced_frame(*screen, config, threads) : simulate_frame(tracer, config, threads, false);

  RunFigures f;
  f.command = run_command(spec);
  f.profile = config.profile;
  f.clock_hz = config.profile.clock_hz;
  f.frame = r.frame;
  f.spread = load_spread(r);
  f.breakdown = r.breakdown;
  for (const CellReport& c : r.cells) {
    f.ops += c.ops;
    f.pixels += c.pixels;
    f.cells.push_back({c.ops, c.pixels, c.finish});
    f.tile_wait += c.tile_wait;
    f.chunks_stolen += c.chunks_stolen;
  }
  f.voxels = r.voxel_counts;
  f.bus = r.bus;
  f.links = link_totals(r);
  f.balance_bus_percent = balance_bus_percent(r);
  f.steal_link_bytes = r.steal_links.bytes;
  f.grid_divisions = scene.grid.n;
  return f;
}

}  // namespace

RunFigures run_experiment(const RunSpec& spec, int threads, ScreenTraces* traces) {
  return run(spec, threads, traces ? &traces->trace(spec, threads) : nullptr);
}

RunFigures run_experiment(const RunSpec& spec, int threads, const ScreenTrace& screen) {
  return run(spec, threads, &screen);
}

}  // namespace capsim::sim
