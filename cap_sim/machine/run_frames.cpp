#include "machine/machine.h"

#include "kernel/event_kernel.h"
#include "machine/cell.h"
#include "machine/command_bus.h"
#include "machine/host.h"
#include "machine/video_bus.h"

#include <fmt/core.h>

#include <algorithm>
#include <memory>
#include <stdexcept>

namespace capsim::sim {

namespace {

std::string sender_name(Endpoint e, const CellGrid& grid) {
  if (e == kHost) return "host";
  const CellPosition p = grid.position(e);
  return fmt::format("cell[{},{}]", p.row, p.col);
}

// The units the host hands the frames out in (frame_work.h); antialiased,
// their exchanges are planned as each starts (plan_exchange).
std::vector<DistributionUnit> distribution_units(const std::vector<FrameWork>& frames,
                                                 const MachineConfig& config) {
  const int count = static_cast<int>(frames.size());
  const int group = config.frame_average ? config.cells.cell_count() : 1;
  std::vector<DistributionUnit> units;
  for (int first = 0; first < count; first += group) {
    DistributionUnit u;
    u.first_frame = first;
    u.frames = std::min(group, count - first);
    units.push_back(std::move(u));
  }
  return units;
}

// The corner exchange of a unit's frames.
std::unique_ptr<CornerExchange> plan_exchange(const std::vector<FrameWork>& frames, const DistributionUnit& unit) {
  std::vector<const WindowLayout*> layouts;
  for (int f = unit.first_frame; f < unit.first_frame + unit.frames; ++f) layouts.push_back(&frames[f].layout);
  return std::make_unique<CornerExchange>(layouts, unit.first_frame);
}

// When each screen pixel of a frame reached video memory: a cell writes its
// pixels in video-memory order from its frame_write_start, pixel k when the
// write cycles of pixels 0 to k have passed.
std::vector<std::uint64_t> completion_cycles(const WindowLayout& layout,
                                             const std::vector<std::unique_ptr<Cell>>& cells, int frame) {
  std::vector<std::uint64_t> out(static_cast<std::size_t>(layout.width()) * layout.height());
  for (const auto& cell : cells)
    if (cell->video_memory(frame).write_cycles.size() !=
        static_cast<std::size_t>(layout.window(cell->id()).pixel_count()))
      throw std::logic_error("completion cycles need the write cycles traced ahead (trace_cells' keep_write_cycles)");
  std::vector<std::uint64_t> clock(cells.size());
  for (std::size_t c = 0; c < cells.size(); ++c) clock[c] = cells[c]->record().frame_write_start.at(frame).count();
  // A cell's pixels come in video-memory order on one thread: its clock is its own.
  for_each_window_pixel(layout, [&](CellId c, int k, std::size_t s) {
    clock[c] += cells[c]->video_memory(frame).write_cycles[k];
    out[s] = clock[c];
  });
  return out;
}

// Every video memory of a frame, composed as the video bus shows it.
FrameScreen compose_frame(const WindowLayout& layout, const std::vector<std::unique_ptr<Cell>>& cells,
                          int frame, const MachineConfig& config) {
  FrameScreen out;
  if (config.completion_cycles) out.completion_cycles = completion_cycles(layout, cells, frame);
  if (config.screen == ScreenFormat::Srgb8) {
    std::vector<const std::vector<unsigned char>*> video;
    for (const auto& cell : cells) video.push_back(&cell->video_memory(frame).srgb8);
    out.screen_srgb8 = compose_screen_srgb8(layout, video);
    return out;
  }
  std::vector<const Framebuffer*> video;
  for (const auto& cell : cells) video.push_back(&cell->video_memory(frame).samples);
  out.screen = compose_screen(layout, video);
  out.pixel_cycles.assign(static_cast<std::size_t>(layout.width()) * layout.height(), 0.0f);
  for_each_window_pixel(layout, [&](CellId c, int k, std::size_t s) {
    out.pixel_cycles[s] = static_cast<float>(cells[c]->video_memory(frame).pixel_cycles[k]);
  });
  if (config.aa.depth > 0) {
    out.pixel_samples.assign(out.pixel_cycles.size(), 0.0f);
    for_each_window_pixel(layout, [&](CellId c, int k, std::size_t s) {
      out.pixel_samples[s] = static_cast<float>(cells[c]->video_memory(frame).pixel_samples[k]);
    });
  }
  return out;
}

// The most video memory a cell needs for a unit (UnitTimes::video_memory_bytes).
std::uint64_t unit_video_memory(const std::vector<FrameWork>& frames, const DistributionUnit& unit,
                                const std::vector<std::unique_ptr<Cell>>& cells) {
  std::uint64_t most = 0;
  for (const auto& cell : cells) {
    std::uint64_t bytes = 0;
    for (int f = unit.first_frame; f < unit.first_frame + unit.frames; ++f) {
      const WindowLayout& layout = frames[f].layout;
      const CellWindow& w = layout.window(cell->id());
      bytes += static_cast<std::uint64_t>(w.pixel_count()) * kVideoPixelBytes;
      if (unit.corners_needed.empty()) continue;
      for (int k = 0; k < w.pixel_count(); ++k) {
        const ScreenPixel p = w.screen_pixel(k);
        bytes += static_cast<std::uint64_t>(owned_corner_count(p.x, p.y, layout.width(), layout.height())) *
                 kScreenSampleBytes;
      }
    }
    if (!unit.corners_needed.empty()) bytes += unit.corners_needed[cell->id()] * kScreenSampleBytes;
    most = std::max(most, bytes);
  }
  return most;
}

}  // namespace

SimulationResult run_frames(std::vector<FrameWork> frames, const MachineConfig& config) {
  const CostProfile& profile = config.profile;
  const CellGrid grid = config.cells;
  if (config.frame_average && config.mode != PixelMode::Dot)
    throw std::invalid_argument("frame averaging turns the dot pattern: it needs dot mode");
  if (frames.empty()) throw std::invalid_argument("a run needs at least one frame");
  SimulationResult result;
  result.config = config;
  result.footprint = frames[0].footprint;
  for (const FrameWork& f : frames) check_cell_memory(f.footprint, profile);

  CostBreakdown voxel_generation;
  try {
    for (const FrameWork& f : frames) {
      voxel_generation[CostCategory::VoxelGeneration] += f.voxel_generation;
      result.voxel_counts += f.voxel_counts;
    }
  } catch (const CycleOverflow& e) {
    throw e.inside("the host's voxel generation, all frames");
  }
  std::vector<DistributionUnit> units = distribution_units(frames, config);

  EventKernel kernel;
  CommandBus bus(kernel, profile);
  NeighbourLinks links(kernel, grid, profile);
  Timeline& timeline = result.timeline;
  const int host_track = timeline.add_track("host");
  const int bus_track = timeline.add_track("command bus");

  const bool antialiased = config.aa.depth > 0;
  auto unit_begins = [&](std::size_t u) {
    if (antialiased) units[u].exchange = plan_exchange(frames, units[u]);
  };
  auto unit_ends = [&](std::size_t u) {
    if (!antialiased) return;
    for (CellId c = 0; c < grid.cell_count(); ++c) units[u].corners_needed.push_back(units[u].exchange->needs(c).size());
    units[u].exchange.reset();
  };
  Host host({kernel, bus, timeline, frames, units, unit_begins, unit_ends}, host_track, grid.cell_count(),
            profile.program_bytes);
  std::vector<std::unique_ptr<Cell>> cells;
  cells.reserve(grid.cell_count());
  for (CellId id = 0; id < grid.cell_count(); ++id) {
    const CellPosition p = grid.position(id);
    const int track = timeline.add_track(fmt::format("cell[{},{}]", p.row, p.col));
    cells.push_back(std::make_unique<Cell>(
        id, track, Cell::Wiring{kernel, bus, links, grid, timeline, frames, units, antialiased,
                                        config.keep_received_corners}));
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
  links.on_delivery([&](const LinkMessage& m) { cells.at(m.to)->link_inbox().deliver(m); });

  kernel.spawn(host.run());
  for (auto& cell : cells) kernel.spawn(cell->run());
  kernel.run();
  if (!kernel.all_processes_finished())
    throw std::logic_error("the simulated run deadlocked: a process waits for a message that never came");

  for (const BusTransfer& t : bus.log()) {
    timeline.span(bus_track, fmt::format("{} ({})", t.label, sender_name(t.sender, grid)),
                  t.receiver == kAllCells ? SpanCategory::Broadcast : SpanCategory::Message, t.granted, t.released, t.bytes);
    ++result.bus.transfers;
    result.bus.bytes += t.bytes;
    result.bus.busy += t.released - t.granted;
  }
  // One track per link direction that carried anything, after the cells'.
  std::vector<int> link_tracks(static_cast<std::size_t>(grid.cell_count()) * 4, -1);
  for (const LinkTraffic& t : links.traffic()) {
    const CellPosition p = grid.position(t.cell);
    link_tracks[static_cast<std::size_t>(t.cell) * 4 + static_cast<int>(t.direction)] =
        timeline.add_track(fmt::format("link cell[{},{}] {}", p.row, p.col, to_string(t.direction)));
  }
  for (const LinkHop& h : links.hops())
    timeline.span(link_tracks[static_cast<std::size_t>(h.cell) * 4 + static_cast<int>(h.direction)], h.label,
                  SpanCategory::Link, h.begin, h.end, h.bytes);
  result.links = links.traffic();
  result.link_messages = links.log();

  result.events = kernel.events_run();
  result.frame = host.unit_end().back();
  for (std::size_t u = 0; u < units.size(); ++u)
    result.units.push_back({units[u].first_frame, units[u].frames, host.unit_start()[u], host.unit_end()[u],
                            unit_video_memory(frames, units[u], cells)});
  result.breakdown = voxel_generation;
  for (const auto& cell : cells) {
    const CellRecord& r = cell->record();
    CellReport c;
    c.id = cell->id();
    c.position = grid.position(c.id);
    c.pixels = r.pixels;
    c.rays = r.rays;
    c.ops = r.ops;
    c.busy = r.busy;
    c.comm = r.comm;
    c.finish = r.finish;
    c.idle = r.finish - r.busy - r.comm;
    c.work = r.work;
    c.trace_corners = r.trace_corners;
    c.exchange = r.exchange;
    c.subdivide = r.subdivide;
    c.corners_received = r.corners_received;
    c.received_corners = r.received_corners;
    c.frame_busy = r.frame_busy;
    c.unit_finish = r.unit_finish;
    try {
      result.breakdown += r.work;
    } catch (const CycleOverflow& e) {
      throw e.inside("all cells' work and the host's voxel generation, by process");
    }
    result.cells.push_back(std::move(c));
  }
  try {
    (void)result.breakdown.total();  // the reports print it: refuse now, before any output
  } catch (const CycleOverflow& e) {
    throw e.inside("all cells' work and the host's voxel generation, in total");
  }
  result.width = frames[0].layout.width();
  result.height = frames[0].layout.height();
  for (std::size_t f = 0; f < frames.size(); ++f)
    result.screens.push_back(compose_frame(frames[f].layout, cells, static_cast<int>(f), config));
  return result;
}

}  // namespace capsim::sim
