#include "machine/machine.h"

#include "kernel/event_kernel.h"
#include "machine/cell.h"
#include "machine/command_bus.h"
#include "machine/host.h"
#include "machine/unit_memory.h"
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
  const int group = unit_frames(config);
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

// A run's preconditions that the parts cannot check themselves: frame
// averaging in dot mode, at least one frame; then the units' size resolved
// and every unit within a cell's memory and video memory. Returns what a cell
// holds for each unit.
std::vector<UnitMemory> check_frames(const std::vector<FrameWork>& frames, MachineConfig& config) {
  if (config.frame_average && config.mode != PixelMode::Dot)
    throw std::invalid_argument("frame averaging turns the dot pattern: it needs dot mode");
  if (frames.empty()) throw std::invalid_argument("a run needs at least one frame");
  std::vector<SceneFootprint> footprints;
  for (const FrameWork& f : frames) footprints.push_back(f.footprint);
  const int width = frames[0].layout.width(), height = frames[0].layout.height();
  config = resolve_units(footprints, config, width, height);
  return unit_memories(footprints, config, width, height);
}

// The host's voxel generation over all frames, by process, and its operations
// added to `counts`; refused before the run if it does not fit.
CostBreakdown host_voxel_generation(const std::vector<FrameWork>& frames, VoxelGenCounts& counts) {
  CostBreakdown work;
  try {
    for (const FrameWork& f : frames) {
      work[CostCategory::VoxelGeneration] += f.voxel_generation;
      counts += f.voxel_counts;
    }
  } catch (const CycleOverflow& e) {
    throw e.inside("the host's voxel generation, all frames");
  }
  return work;
}

// The machine's parts wired for one run: host, command bus, neighbour links
// and the cells on one event kernel, with their timeline tracks in display
// order (host, command bus, each cell; the links' follow once the run has
// shown which carried anything). Antialiased, each unit's corner exchange is
// planned as the host starts the unit and dropped once it has collected it.
// The parts refer to each other and to frames and units, which must outlive
// them.
struct MachineParts {
  MachineParts(std::vector<FrameWork>& frames, std::vector<DistributionUnit>& units, const MachineConfig& config,
               Timeline& timeline);
  MachineParts(const MachineParts&) = delete;
  MachineParts& operator=(const MachineParts&) = delete;

  // Runs the host's and the cells' programs to their end. Throws
  // std::logic_error if one waits for a message that never comes.
  void run();

  std::vector<FrameWork>& frames;
  std::vector<DistributionUnit>& units;
  const CellGrid grid;
  const bool antialiased;
  Timeline& timeline;
  EventKernel kernel;
  CommandBus bus;
  NeighbourLinks links;
  const int host_track, bus_track;
  Host host;
  std::vector<std::unique_ptr<Cell>> cells;

 private:
  void unit_begins(std::size_t u);
  void unit_ends(std::size_t u);
};

MachineParts::MachineParts(std::vector<FrameWork>& frames_in, std::vector<DistributionUnit>& units_in,
                           const MachineConfig& config, Timeline& timeline_in)
    : frames(frames_in),
      units(units_in),
      grid(config.cells),
      antialiased(config.aa.depth > 0),
      timeline(timeline_in),
      bus(kernel, config.profile),
      links(kernel, grid, config.profile),
      host_track(timeline.add_track("host")),
      bus_track(timeline.add_track("command bus")),
      host({kernel, bus, timeline, frames, units, [this](std::size_t u) { unit_begins(u); },
            [this](std::size_t u) { unit_ends(u); }},
           host_track, grid.cell_count(), config.profile.program_bytes) {
  cells.reserve(grid.cell_count());
  for (CellId id = 0; id < grid.cell_count(); ++id) {
    const CellPosition p = grid.position(id);
    const int track = timeline.add_track(fmt::format("cell[{},{}]", p.row, p.col));
    cells.push_back(std::make_unique<Cell>(
        id, track,
        Cell::Wiring{kernel, bus, links, grid, timeline, frames, units, antialiased, config.keep_received_corners}));
  }
  bus.on_delivery([this](const BusTransfer& t) {
    if (t.receiver == kAllCells) {
      for (auto& cell : cells) cell->bus_inbox().deliver(t);
    } else if (t.receiver == kHost) {
      host.bus_inbox().deliver(t);
    } else {
      cells.at(t.receiver)->bus_inbox().deliver(t);
    }
  });
  links.on_delivery([this](const LinkMessage& m) { cells.at(m.to)->link_inbox().deliver(m); });
}

void MachineParts::unit_begins(std::size_t u) {
  if (antialiased) units[u].exchange = plan_exchange(frames, units[u]);
}

void MachineParts::unit_ends(std::size_t u) { units[u].exchange.reset(); }

void MachineParts::run() {
  kernel.spawn(host.run());
  for (auto& cell : cells) kernel.spawn(cell->run());
  kernel.run();
  if (!kernel.all_processes_finished())
    throw std::logic_error("the simulated run deadlocked: a process waits for a message that never came");
}

// The bus's transfers on its track, and its totals; then one track per link
// direction that carried anything, after the cells', with every hop on it.
void record_traffic(MachineParts& m, SimulationResult& result) {
  for (const BusTransfer& t : m.bus.log()) {
    m.timeline.span(m.bus_track, fmt::format("{} ({})", to_string(t.message), sender_name(t.sender, m.grid)),
                    t.receiver == kAllCells ? SpanCategory::Broadcast : SpanCategory::Message, t.granted,
                    t.released, t.bytes);
    ++result.bus.transfers;
    result.bus.bytes += t.bytes;
    result.bus.busy += t.released - t.granted;
  }
  std::vector<int> link_tracks(static_cast<std::size_t>(m.grid.cell_count()) * 4, -1);
  for (const LinkTraffic& t : m.links.traffic()) {
    const CellPosition p = m.grid.position(t.cell);
    link_tracks[static_cast<std::size_t>(t.cell) * 4 + static_cast<int>(t.direction)] =
        m.timeline.add_track(fmt::format("link cell[{},{}] {}", p.row, p.col, to_string(t.direction)));
  }
  for (const LinkHop& h : m.links.hops())
    m.timeline.span(link_tracks[static_cast<std::size_t>(h.cell) * 4 + static_cast<int>(h.direction)],
                    std::string(to_string(h.packet)),
                    SpanCategory::Link, h.begin, h.end, h.bytes);
  result.links = m.links.traffic();
  result.link_messages = m.links.log();
  result.events = m.kernel.events_run();
}

// When the host started and collected each unit, and what a cell held for
// it; the last collection is the run's time.
void record_units(const MachineParts& m, const std::vector<UnitMemory>& memory, SimulationResult& result) {
  result.frame = m.host.unit_end().back();
  for (std::size_t u = 0; u < m.units.size(); ++u)
    result.units.push_back({m.units[u].first_frame, m.units[u].frames, m.host.unit_start()[u], m.host.unit_end()[u],
                            static_cast<std::uint64_t>(memory[u].cell_memory), memory[u].video_memory});
}

// What a cell measured, as the report gives it.
CellReport cell_report(const Cell& cell, const CellGrid& grid) {
  CellReport c;
  static_cast<CellRecord&>(c) = cell.record();
  c.id = cell.id();
  c.position = grid.position(c.id);
  c.idle = c.finish - c.busy - c.comm;
  return c;
}

// Every cell's report, and the run's time by process: the host's voxel
// generation and every cell's work, refused here if it does not fit, before
// any report prints it.
void record_cells(const MachineParts& m, const CostBreakdown& host_work, SimulationResult& result) {
  result.breakdown = host_work;
  for (const auto& cell : m.cells) {
    result.cells.push_back(cell_report(*cell, m.grid));
    try {
      result.breakdown += cell->record().work;
    } catch (const CycleOverflow& e) {
      throw e.inside("all cells' work and the host's voxel generation, by process");
    }
  }
  try {
    (void)result.breakdown.total();
  } catch (const CycleOverflow& e) {
    throw e.inside("all cells' work and the host's voxel generation, in total");
  }
}

// Every frame as the video bus showed it.
void compose_screens(const MachineParts& m, const MachineConfig& config, SimulationResult& result) {
  result.width = m.frames[0].layout.width();
  result.height = m.frames[0].layout.height();
  for (std::size_t f = 0; f < m.frames.size(); ++f)
    result.screens.push_back(compose_frame(m.frames[f].layout, m.cells, static_cast<int>(f), config));
}

}  // namespace

// Plan the units, wire the parts, run their programs, collect what they
// recorded.
SimulationResult run_frames(std::vector<FrameWork> frames, const MachineConfig& asked) {
  MachineConfig config = asked;
  const std::vector<UnitMemory> memory = check_frames(frames, config);
  SimulationResult result;
  result.config = config;
  result.footprint = frames[0].footprint;
  const CostBreakdown host_work = host_voxel_generation(frames, result.voxel_counts);
  std::vector<DistributionUnit> units = distribution_units(frames, config);

  MachineParts machine(frames, units, config, result.timeline);
  machine.run();

  record_traffic(machine, result);
  record_units(machine, memory, result);
  record_cells(machine, host_work, result);
  compose_screens(machine, config, result);
  return result;
}

}  // namespace capsim::sim
