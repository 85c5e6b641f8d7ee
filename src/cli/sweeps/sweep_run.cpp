#include "cli/sweeps/sweep_run.h"

#include "capsim/trace/tracer.h"
#include "cli/options/cli_options.h"

#include <memory>

namespace capsim::cli {

sim::SimulationResult run_sweep_point(const sim::SweepPoint& p, int threads) {
  TracerSettings s;
  s.scenes = p.scene.files;
  s.animate = p.scene.frames > 0;
  s.frames = s.animate ? p.scene.frames : static_cast<int>(s.scenes.size());
  s.prepare.width = p.width;
  s.prepare.height = p.height;
  s.prepare.grid = p.grid;
  s.threads = threads;
  s.trace.primary_only = p.primary_only;
  s.aa.depth = p.aa_depth;  // the default threshold, as simulate's
  sim::MachineConfig config;
  config.cells = p.cells;
  config.mode = p.mode;
  config.frame_average = p.frame_average;
  config.balance = p.balance;
  config.voxel_generation = p.voxel_generation;
  config.aa = s.aa;
  config.profile = sim::load_cost_profile(p.profile_path);
  config.screen = sim::ScreenFormat::Srgb8;  // as simulate's for a .png; the cycles do not depend on it
  const std::vector<PreparedScene> scenes = load_scenes(s, [config](ImageSize size, int count) {
    return sim::simulation_memory_until_written(config, size.width, size.height, count);
  });
  std::vector<std::unique_ptr<Tracer>> tracers;
  std::vector<const Tracer*> frames;
  for (const PreparedScene& scene : scenes) {
    tracers.push_back(std::make_unique<Tracer>(scene, s.trace));
    frames.push_back(tracers.back().get());
  }
  return sim::simulate_frames(frames, config, threads, false);
}

}  // namespace capsim::cli
