#include "machine/machine.h"

#include "machine/unit_memory.h"

#include "capsim/image/image_io.h"
#include "capsim/system/host_threads.h"
#include "capsim/system/progress.h"

#include <fmt/core.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <stdexcept>

namespace capsim::sim {

FrameWork frame_work(const PreparedScene& scene, const WindowLayout& layout, std::vector<TracedCell> traced,
                     const MachineConfig& config) {
  if (config.voxel_generation == VoxelGeneration::Cells)
    return FrameWork{layout, scene_footprint(scene), Cycles(), {}, std::move(traced),
                     voxel_shares(scene, config.cells.cell_count(), config.profile.costs)};
  Cycles voxel_generation;
  try {
    voxel_generation = voxel_generation_cost(scene.voxel_counts, config.profile.costs).total();
  } catch (const CycleOverflow& e) {
    throw e.inside("the host's voxel generation");
  }
  return FrameWork{layout, scene_footprint(scene), voxel_generation, scene.voxel_counts, std::move(traced), {}};
}

std::uint64_t simulation_memory(const MachineConfig& config, int width, int height, int frames) {
  const std::uint64_t pixels = static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
  const std::uint64_t corners = static_cast<std::uint64_t>(width + 1) * static_cast<std::uint64_t>(height + 1);
  const bool aa = config.aa.depth > 0;
  // Per pixel and frame, kept to the end: the video memory and the screen.
  std::uint64_t per_pixel = 0;
  if (config.screen == ScreenFormat::Srgb8) {
    per_pixel = 3 + 3;
  } else {
    const std::uint64_t frame = Framebuffer::bytes(1, 1);
    per_pixel = frame + sizeof(std::uint64_t) + (aa ? sizeof(std::uint32_t) : 0)   // video memory
                + frame + sizeof(float) + (aa ? sizeof(float) : 0);                   // screen
  }
  std::uint64_t bytes = per_pixel * pixels * static_cast<std::uint64_t>(frames) + pixels;  // + owner counts
  if (aa) {
    // One frame's corners (and their cycles, for a float screen) while it is traced.
    bytes += corners * (sizeof(ScreenSample) + (config.screen == ScreenFormat::Float ? sizeof(std::uint64_t) : 0));
    // The running unit's exchange plan (DistributionUnit::exchange): up to 3
    // corners needed from other cells per pixel of its frames, each kept as a
    // need and in at most two messages (4 bytes each); and, when kept, every
    // corner a cell took in (4 bytes).
    const std::uint64_t unit = std::min<std::uint64_t>(frames, unit_frames(config));
    bytes += unit * pixels * 3 * (4 + 4 + 4);
    if (config.keep_received_corners) bytes += static_cast<std::uint64_t>(frames) * pixels * 3 * 4;
  }
  return bytes;
}

std::uint64_t simulation_result_memory(const MachineConfig& config, int width, int height, int frames) {
  const std::uint64_t pixels = static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
  const std::uint64_t per_pixel = config.screen == ScreenFormat::Srgb8
                                      ? 3
                                      : Framebuffer::bytes(1, 1) + sizeof(float) +
                                            (config.aa.depth > 0 ? sizeof(float) : 0);
  return per_pixel * pixels * static_cast<std::uint64_t>(frames);
}

std::uint64_t simulation_memory_until_written(const MachineConfig& config, int width, int height, int frames) {
  const std::uint64_t pixels = static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
  const std::size_t extra = config.aa.depth > 0 ? 2 : 1;  // EXR channels: cycles, and samples
  const std::uint64_t writing =
      simulation_result_memory(config, width, height, frames) +
      (config.screen == ScreenFormat::Srgb8
           ? write_png_rgb8_memory(width, height)
           : extra * pixels * sizeof(float) + write_image_memory(".exr", width, height, extra));
  return std::max(simulation_memory(config, width, height, frames), writing);
}

WindowLayout frame_layout(const MachineConfig& config, int width, int height, int frame) {
  if (config.balance.on_demand()) return tile_layout(config.balance, width, height);
  return WindowLayout(config.mode, config.cells, width, height,
                      config.frame_average ? dot_shift_for_frame(config.cells, frame % unit_frames(config))
                                           : DotShift{});
}

SimulationResult run_frame(const PreparedScene& scene, const WindowLayout& layout,
                           std::vector<TracedCell> traced, const MachineConfig& config) {
  std::vector<FrameWork> frames;
  frames.push_back(frame_work(scene, layout, std::move(traced), config));
  return run_frames(std::move(frames), config);
}

namespace {

// How the cells trace the corners antialiasing shares: each window that
// needs one when the windows are dealt on demand (their owners are not
// known ahead), else only the corner's owner.
CornerTracing corner_tracing(const MachineConfig& config) {
  return config.balance.on_demand() ? CornerTracing::ByEveryWindowThatNeedsIt : CornerTracing::ByOwner;
}

// The pixels of a chunk a neighbour may steal; 0 without stealing.
int steal_chunk(const MachineConfig& config) {
  return config.balance.stealing() ? config.balance.chunk_pixels : 0;
}

// The event loop over the traced frames: serial; composing the screens uses
// the same host threads.
SimulationResult run_on_host_threads(std::vector<FrameWork> work, const MachineConfig& config, int threads) {
  tbb::task_arena arena(host_arena_concurrency(threads));
  return arena.execute([&] { return run_frames(std::move(work), config); });
}

// `run()`, a cycle count too large to hold named by the profile whose costs
// made it so (the scenes are valid).
template <typename Run>
SimulationResult naming_overflow(const CostProfile& profile, Run&& run) {
  try {
    return run();
  } catch (const CycleOverflow& e) {
    throw e.of_profile(profile.source.empty() ? profile.name : profile.source, profile.clock_hz);
  }
}

// Every frame traced for its cells (the camera's size for all), then run.
SimulationResult trace_and_run(const std::vector<const Tracer*>& frames, const MachineConfig& config,
                               int threads, bool show_progress) {
  const Camera& cam = frames[0]->scene().camera;
  std::vector<FrameWork> work;
  work.reserve(frames.size());
  {
    const bool one = frames.size() == 1;
    Progress progress(one ? "tracing" : "frames",
                      one ? render_work(cam.width, cam.height, config.aa) : frames.size(), show_progress);
    for (std::size_t f = 0; f < frames.size(); ++f) {
      const Tracer& tracer = *frames[f];
      const Camera& c = tracer.scene().camera;
      if (c.width != cam.width || c.height != cam.height)
        throw std::invalid_argument(fmt::format("frame {} is {}x{} where frame 0 is {}x{}", f, c.width, c.height,
                                                cam.width, cam.height));
      const WindowLayout layout = frame_layout(config, cam.width, cam.height, static_cast<int>(f));
      std::vector<TracedCell> traced =
          trace_cells(tracer, layout, config.profile.costs, threads, one ? &progress : nullptr, config.aa,
                      config.screen, config.completion_cycles, corner_tracing(config), steal_chunk(config));
      work.push_back(frame_work(tracer.scene(), layout, std::move(traced), config));
      if (!one) progress.advance(1);
    }
  }
  return run_on_host_threads(std::move(work), config, threads);
}

}  // namespace

SimulationResult simulate_frames(const std::vector<const Tracer*>& frames, const MachineConfig& config,
                                 int threads, bool show_progress) {
  if (frames.empty()) throw std::invalid_argument("a run needs at least one frame");
  check_balance(config);
  // Refuse a unit that does not fit before spending time tracing it; frame
  // averaged, the units' size decides the frames' dot shifts, so it is
  // resolved first.
  std::vector<SceneFootprint> footprints;
  for (const Tracer* t : frames) footprints.push_back(scene_footprint(t->scene()));
  const Camera& cam = frames[0]->scene().camera;
  const MachineConfig resolved = resolve_units(footprints, config, cam.width, cam.height);
  return naming_overflow(config.profile, [&] { return trace_and_run(frames, resolved, threads, show_progress); });
}

SimulationResult simulate_frame(const Tracer& tracer, const MachineConfig& config, int threads,
                                bool show_progress) {
  return simulate_frames({&tracer}, config, threads, show_progress);
}

SimulationResult simulate_traced_frame(const ScreenTrace& screen, const MachineConfig& config, int threads) {
  if (screen.aa.depth != config.aa.depth || screen.aa.threshold != config.aa.threshold)
    throw std::invalid_argument("a screen traced ahead runs with the antialiasing it was traced with");
  check_balance(config);
  const PreparedScene& scene = screen.tracer->scene();
  const MachineConfig resolved = resolve_units({scene_footprint(scene)}, config, screen.width, screen.height);
  return naming_overflow(config.profile, [&] {
    const WindowLayout layout = frame_layout(resolved, screen.width, screen.height, 0);
    std::vector<FrameWork> work;
    work.push_back(frame_work(scene, layout,
                              trace_cells(screen, layout, resolved.profile.costs, threads, resolved.screen,
                                          resolved.completion_cycles, corner_tracing(resolved),
                                          steal_chunk(resolved)),
                              resolved));
    return run_on_host_threads(std::move(work), resolved, threads);
  });
}

}  // namespace capsim::sim
