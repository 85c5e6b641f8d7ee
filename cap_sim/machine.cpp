#include "machine.h"

#include "cell.h"
#include "command_bus.h"
#include "event_kernel.h"
#include "host.h"
#include "capsim/host_threads.h"
#include "capsim/progress.h"
#include "video_bus.h"

#include <fmt/core.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <memory>
#include <stdexcept>

namespace capsim::sim {

void check_cell_memory(const SceneFootprint& f, const CostProfile& profile) {
  const std::uint64_t needed = profile.program_bytes + f.scene_bytes() + f.voxel_bytes();
  if (needed > profile.cell_memory_bytes)
    throw std::runtime_error(fmt::format(
        "the scene does not fit a cell's memory: it needs {} bytes (program {} + scene {} + voxel "
        "data {}) but a cell of profile '{}' has {} bytes; try a coarser --grid",
        needed, profile.program_bytes, f.scene_bytes(), f.voxel_bytes(), profile.name,
        profile.cell_memory_bytes));
}

namespace {

std::string sender_name(Endpoint e, const CellGrid& grid) {
  if (e == kHost) return "host";
  const CellPosition p = grid.position(e);
  return fmt::format("cell[{},{}]", p.row, p.col);
}

}  // namespace

SimulationResult run_frame(const PreparedScene& scene, const WindowLayout& layout,
                           std::vector<TracedCell> traced, const MachineConfig& config) {
  const CostProfile& profile = config.profile;
  const CellGrid grid = config.cells;
  SimulationResult result;
  result.config = config;
  result.footprint = scene_footprint(scene);
  check_cell_memory(result.footprint, profile);

  const CostBreakdown voxel_generation = voxel_generation_cost(scene.voxel_counts, profile.host);

  EventKernel kernel;
  CommandBus bus(kernel, profile);
  Timeline& timeline = result.timeline;
  const int host_track = timeline.add_track("host");
  const int bus_track = timeline.add_track("command bus");

  Host host({kernel, bus, timeline}, host_track, grid.cell_count(), profile.program_bytes,
            result.footprint, voxel_generation.total());
  std::vector<std::unique_ptr<Cell>> cells;
  cells.reserve(grid.cell_count());
  for (CellId id = 0; id < grid.cell_count(); ++id) {
    const CellPosition p = grid.position(id);
    const int track = timeline.add_track(fmt::format("cell[{},{}]", p.row, p.col));
    cells.push_back(std::make_unique<Cell>(id, layout.window(id), std::move(traced.at(id)), track,
                                           Cell::Wiring{kernel, bus, timeline}));
  }

  bus.on_delivery([&](const BusTransfer& t) {
    if (t.receiver == kAllCells) {
      for (auto& cell : cells) cell->bus_inbox().deliver(t);
    } else if (t.receiver == kHost) {
      host.bus_inbox().deliver(t);
    } else {
      cells.at(t.receiver)->bus_inbox().deliver(t);
    }
  });

  kernel.spawn(host.run_frame());
  for (auto& cell : cells) kernel.spawn(cell->run_frame());
  kernel.run();
  if (!kernel.all_processes_finished())
    throw std::logic_error("the simulated frame deadlocked: a process waits for a message that never came");

  for (const BusTransfer& t : bus.log())
    timeline.span(bus_track, fmt::format("{} ({})", t.label, sender_name(t.sender, grid)),
                  t.receiver == kAllCells ? "broadcast" : "message", t.granted, t.released, t.bytes);

  result.events = kernel.events_run();
  result.frame = host.frame_end();
  result.breakdown = voxel_generation;
  std::vector<const Framebuffer*> video;
  for (const auto& cell : cells) {
    const CellRecord& r = cell->record();
    CellReport c;
    c.id = cell->id();
    c.position = grid.position(c.id);
    c.pixels = r.pixels;
    c.rays = r.rays;
    c.busy = r.busy;
    c.comm = r.comm;
    c.finish = r.finish;
    c.idle = r.finish - r.busy - r.comm;
    c.work = r.work;
    result.breakdown += r.work;
    result.cells.push_back(c);
    video.push_back(&cell->video_memory());
  }
  result.screen = compose_screen(layout, video);

  result.pixel_cycles.assign(static_cast<std::size_t>(layout.width()) * layout.height(), 0.0f);
  for_each_window_pixel(layout, [&](CellId c, int k, std::size_t s) {
    result.pixel_cycles[s] = static_cast<float>(cells[c]->pixel_cycles()[k]);
  });
  return result;
}

std::uint64_t simulation_result_memory(int width, int height) {
  const std::uint64_t pixels = static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
  return Framebuffer::bytes(width, height) + pixels * sizeof(float);
}

std::uint64_t simulate_frame_memory(int width, int height) {
  const std::uint64_t pixels = static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
  // trace_cells: a framebuffer pixel and a 64-bit cycle count per pixel, held
  // by the cells until run_frame ends. compose_screen adds the screen and an
  // owner count per pixel; then the result's float cycles are added. The owner
  // counts are freed before that, but the allocator keeps blocks below its
  // mapping threshold (main sets 32 MiB) for reuse, so they are counted too.
  const std::uint64_t traced = Framebuffer::bytes(width, height) + pixels * sizeof(std::uint64_t);
  const std::uint64_t owners = pixels * sizeof(std::atomic<unsigned char>);
  return traced + owners + simulation_result_memory(width, height);
}

SimulationResult simulate_frame(const Tracer& tracer, const MachineConfig& config, int threads,
                                bool show_progress) {
  const Camera& cam = tracer.scene().camera;
  // Refuse a scene that does not fit before spending time tracing it.
  check_cell_memory(scene_footprint(tracer.scene()), config.profile);
  const WindowLayout layout(config.mode, config.cells, cam.width, cam.height);
  std::vector<TracedCell> traced;
  {
    Progress progress("tracing", static_cast<std::uint64_t>(cam.width) * cam.height, show_progress);
    traced = trace_cells(tracer, layout, config.profile.cell, threads, &progress);
  }
  // The event loop is serial; composing the screen uses the same host threads.
  tbb::task_arena arena(host_arena_concurrency(threads));
  return arena.execute([&] { return run_frame(tracer.scene(), layout, std::move(traced), config); });
}

}  // namespace capsim::sim
