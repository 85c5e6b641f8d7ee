#include "paper/experiment_run.h"

#include "capsim/parser.h"
#include "capsim/prepared_scene.h"
#include "capsim/tracer.h"
#include "paper/simulate_command.h"

#include <fmt/core.h>

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

RunFigures run_experiment(const RunSpec& spec, int threads) {
  PrepareOptions prep;
  prep.grid = spec.grid;
  prep.width = spec.width;
  prep.height = spec.height;
  const PreparedScene scene = prepare_scene(
      spec.lattice ? make_sphere_lattice(*spec.lattice, spec.width, spec.height) : parse_scene_file(spec.scene),
      prep);
  TraceOptions trace;
  trace.primary_only = spec.primary_only;
  const Tracer tracer(scene, trace);
  MachineConfig config;
  config.cells = spec.cells;
  config.mode = spec.mode;
  config.profile = spec.costs ? *spec.costs : load_cost_profile(spec.profile);
  config.aa.depth = spec.aa_depth;  // the default threshold, as the command's
  config.balance = spec.balance;
  config.screen = ScreenFormat::Srgb8;  // as for `-o screen.png`; the cycles do not depend on it
  const SimulationResult r = simulate_frame(tracer, config, threads, false);

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

}  // namespace capsim::sim
