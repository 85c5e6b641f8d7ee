#include "machine/machine.h"

#include "kernel/event_kernel.h"
#include "machine/parts/cell.h"
#include "machine/parts/command_bus.h"
#include "machine/parts/host.h"
#include "machine/unit_memory.h"
#include "machine/parts/video_bus.h"

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

// When each screen pixel of a frame reached video memory: the window w of
// the layout (a cell's, or on demand a tile's) holds video[w], written in
// video-memory order from write_start[w], pixel k when the write cycles of
// pixels 0 to k have passed.
std::vector<std::uint64_t> completion_cycles(const WindowLayout& layout, const std::vector<const TracedCell*>& video,
                                             const std::vector<Cycles>& write_start) {
  std::vector<std::uint64_t> out(static_cast<std::size_t>(layout.width()) * layout.height());
  for (std::size_t w = 0; w < video.size(); ++w)
    if (video[w]->write_cycles.size() != static_cast<std::size_t>(layout.window(static_cast<CellId>(w)).pixel_count()))
      throw std::logic_error("completion cycles need the write cycles traced ahead (trace_cells' keep_write_cycles)");
  std::vector<std::uint64_t> clock(video.size());
  for (std::size_t w = 0; w < video.size(); ++w) clock[w] = write_start[w].count();
  // A window's pixels come in video-memory order on one thread: its clock is its own.
  for_each_window_pixel(layout, [&](CellId w, int k, std::size_t s) {
    clock[w] += video[w]->write_cycles[k];
    out[s] = clock[w];
  });
  return out;
}

// A frame as the video bus shows it: every window of its layout (a cell's,
// or on demand a tile's) with its video memory, composed.
FrameScreen compose_frame(const WindowLayout& layout, const std::vector<const TracedCell*>& video,
                          const std::vector<Cycles>& write_start, const MachineConfig& config) {
  FrameScreen out;
  if (config.completion_cycles) out.completion_cycles = completion_cycles(layout, video, write_start);
  if (config.screen == ScreenFormat::Srgb8) {
    std::vector<const std::vector<unsigned char>*> bytes;
    for (const TracedCell* v : video) bytes.push_back(&v->srgb8);
    out.screen_srgb8 = compose_screen_srgb8(layout, bytes);
    return out;
  }
  std::vector<const Framebuffer*> samples;
  for (const TracedCell* v : video) samples.push_back(&v->samples);
  out.screen = compose_screen(layout, samples);
  out.pixel_cycles.assign(static_cast<std::size_t>(layout.width()) * layout.height(), 0.0f);
  for_each_window_pixel(layout, [&](CellId c, int k, std::size_t s) {
    out.pixel_cycles[s] = static_cast<float>(video[c]->pixel_cycles[k]);
  });
  if (config.aa.depth > 0) {
    out.pixel_samples.assign(out.pixel_cycles.size(), 0.0f);
    for_each_window_pixel(layout, [&](CellId c, int k, std::size_t s) {
      out.pixel_samples[s] = static_cast<float>(video[c]->pixel_samples[k]);
    });
  }
  return out;
}

// A run's preconditions that the parts cannot check themselves: frame
// averaging in dot mode, at least one frame; then the units' size resolved
// and every unit within a cell's memory and video memory. Returns what a cell
// holds for each unit.
std::vector<UnitMemory> check_frames(const std::vector<FrameWork>& frames, MachineConfig& config) {
  check_balance(config);
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
            [this](std::size_t u) { unit_ends(u); }, config.balance.on_demand(),
            config.voxel_generation == VoxelGeneration::Cells},
           host_track, grid.cell_count(), config.profile.program_bytes) {
  cells.reserve(grid.cell_count());
  for (CellId id = 0; id < grid.cell_count(); ++id) {
    const CellPosition p = grid.position(id);
    const int track = timeline.add_track(fmt::format("cell[{},{}]", p.row, p.col));
    cells.push_back(std::make_unique<Cell>(
        id, track,
        Cell::Wiring{kernel, bus, links, grid, timeline, frames, units, antialiased, config.keep_received_corners,
                     config.balance.on_demand(), config.balance.stealing() ? config.balance.chunk_pixels : 0,
                     [this](CellId c, int f) -> const TracedCell& { return cells.at(c)->video_memory(f); },
                     config.voxel_generation == VoxelGeneration::Cells}));
  }
  bus.on_delivery([this](const BusTransfer& t) {
    if (t.receiver == kAllCells) {
      for (auto& cell : cells)
        if (cell->id() != t.sender) cell->bus_inbox().deliver(t);
    } else if (t.receiver == kHost) {
      host.bus_inbox().deliver(t);
    } else {
      cells.at(t.receiver)->bus_inbox().deliver(t);
    }
  });
  links.on_delivery([this](const LinkMessage& m) { cells.at(m.to)->deliver_link(m); });
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
    if (t.message == BusMessage::Request || t.message == BusMessage::Grant || t.message == BusMessage::NoTile) {
      ++result.balance_bus.transfers;
      result.balance_bus.bytes += t.bytes;
      result.balance_bus.busy += t.released - t.granted;
    }
    if (t.message == BusMessage::VoxelEntries || t.message == BusMessage::VoxelRows) {
      BusTotals& part = t.message == BusMessage::VoxelEntries ? result.voxel_entries_bus : result.voxel_rows_bus;
      ++part.transfers;
      part.bytes += t.bytes;
      part.busy += t.released - t.granted;
    }
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
  for (const LinkMessage& l : result.link_messages)
    if (l.packet.kind != LinkKind::Corners) {
      ++result.steal_links.messages;
      result.steal_links.bytes += l.bytes;
    }
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

// Balanced on demand: which cell traced each tile, and when it began; every
// tile exactly once.
struct TileOwners {
  std::vector<std::vector<CellId>> cell;  // per frame, per tile
  std::vector<std::vector<Cycles>> start;
};
TileOwners tile_owners(const MachineParts& m) {
  TileOwners out;
  for (const FrameWork& f : m.frames) {
    out.cell.emplace_back(f.layout.grid().cell_count(), -1);
    out.start.emplace_back(f.layout.grid().cell_count());
  }
  for (const auto& cell : m.cells)
    for (const TileRun& t : cell->record().tiles) {
      CellId& owner = out.cell.at(t.frame).at(t.tile);
      if (owner >= 0) throw std::logic_error(fmt::format("tile {} of frame {} was traced twice", t.tile, t.frame));
      owner = cell->id();
      out.start[t.frame][t.tile] = t.start;
    }
  for (std::size_t f = 0; f < out.cell.size(); ++f)
    for (std::size_t t = 0; t < out.cell[f].size(); ++t)
      if (out.cell[f][t] < 0) throw std::logic_error(fmt::format("tile {} of frame {} was never traced", t, f));
  return out;
}

// On demand a cell's video memory holds the tiles it traced of the unit's
// frame, which only the run decides: the most any cell took, checked here
// against the profile (before any output is written).
void check_tile_video_memory(const MachineParts& m, const MachineConfig& config, SimulationResult& result) {
  const CostProfile& profile = config.profile;
  for (UnitTimes& unit : result.units) {
    std::uint64_t most = 0;
    for (const auto& cell : m.cells) {
      std::uint64_t pixels = 0;
      for (const TileRun& t : cell->record().tiles)
        if (t.frame == unit.first_frame)
          pixels += static_cast<std::uint64_t>(m.frames[t.frame].layout.window(t.tile).pixel_count());
      const std::uint64_t bytes = pixels * kVideoPixelBytes;
      if (bytes > profile.video_memory_bytes)
        throw std::runtime_error(fmt::format(
            "frame {}: {} traced {} pixels of tiles, which need {} B of video memory; the profile gives {} B: "
            "more --cells or a smaller --size can help",
            unit.first_frame, sender_name(cell->id(), m.grid), pixels, bytes, profile.video_memory_bytes));
      most = std::max(most, bytes);
    }
    unit.video_memory_bytes = most;
  }
}

// Stealing: which cell traced each chunk of each window, per frame; every
// chunk exactly once.
std::vector<std::vector<std::vector<CellId>>> chunk_tracers(const MachineParts& m) {
  std::vector<std::vector<std::vector<CellId>>> out;
  for (std::size_t f = 0; f < m.frames.size(); ++f) {
    out.emplace_back();
    for (const auto& cell : m.cells)
      out.back().emplace_back(cell->video_memory(static_cast<int>(f)).chunk_work.size(), -1);
  }
  for (const auto& cell : m.cells)
    for (const ChunkRun& r : cell->record().chunk_runs)
      for (int k = r.first_chunk; k < r.first_chunk + r.chunks; ++k) {
        CellId& tracer = out.at(r.frame).at(r.owner).at(k);
        if (tracer >= 0)
          throw std::logic_error(fmt::format("chunk {} of {} in frame {} was traced twice", k,
                                             sender_name(r.owner, m.grid), r.frame));
        tracer = cell->id();
      }
  for (std::size_t f = 0; f < out.size(); ++f)
    for (std::size_t w = 0; w < out[f].size(); ++w)
      for (std::size_t k = 0; k < out[f][w].size(); ++k)
        if (out[f][w][k] < 0)
          throw std::logic_error(fmt::format("chunk {} of {} in frame {} was never traced", k,
                                             sender_name(static_cast<CellId>(w), m.grid), f));
  return out;
}

// Stealing: when each pixel of a frame was in its owner's video memory: a
// chunk the owner traced as its pixels' write cycles pass from the chunk's
// start; a stolen chunk when its pixels came back.
std::vector<std::uint64_t> stolen_completion_cycles(const MachineParts& m, int f, const MachineConfig& config) {
  const WindowLayout& layout = m.frames[f].layout;
  std::vector<std::vector<std::uint64_t>> written(m.cells.size());
  for (const auto& cell : m.cells) {
    const TracedCell& video = cell->video_memory(f);
    const int pixels = layout.window(cell->id()).pixel_count();
    if (video.write_cycles.size() != static_cast<std::size_t>(pixels))
      throw std::logic_error("completion cycles need the write cycles traced ahead (trace_cells' keep_write_cycles)");
    std::vector<std::uint64_t>& mine = written[cell->id()];
    mine.assign(pixels, 0);
    for (const ChunkRun& r : cell->record().chunk_runs) {
      if (r.frame != f || r.owner != cell->id()) continue;
      const ChunkRange range = chunk_range(r.first_chunk, pixels, config.balance.chunk_pixels);
      std::uint64_t clock = r.start.count();
      for (int k = range.first_pixel; k < range.first_pixel + range.pixels; ++k) mine[k] = clock += video.write_cycles[k];
    }
    for (const ReturnedChunks& r : cell->record().returned) {
      if (r.frame != f) continue;
      for (int c = r.first_chunk; c < r.first_chunk + r.chunks; ++c) {
        const ChunkRange range = chunk_range(c, pixels, config.balance.chunk_pixels);
        for (int k = range.first_pixel; k < range.first_pixel + range.pixels; ++k) mine[k] = r.arrived.count();
      }
    }
  }
  std::vector<std::uint64_t> out(static_cast<std::size_t>(layout.width()) * layout.height());
  for_each_window_pixel(layout, [&](CellId w, int k, std::size_t s) { out[s] = written[w][k]; });
  return out;
}

// Every frame as the video bus showed it: the cells' windows, or on demand
// the tiles where their cells' window controllers put them.
void compose_screens(const MachineParts& m, const MachineConfig& config, SimulationResult& result) {
  result.width = m.frames[0].layout.width();
  result.height = m.frames[0].layout.height();
  if (config.balance.on_demand()) {
    TileOwners owners = tile_owners(m);
    for (std::size_t f = 0; f < m.frames.size(); ++f) {
      std::vector<const TracedCell*> video;
      std::vector<Cycles> write_start;
      for (std::size_t t = 0; t < m.frames[f].cells.size(); ++t) {
        const TracedCell& tile = m.frames[f].cells[t];
        video.push_back(&tile);
        // Antialiased, a tile's pixels are written as it subdivides them,
        // after tracing its corners.
        write_start.push_back(owners.start[f][t] + tile.corner_work.total());
      }
      result.screens.push_back(compose_frame(m.frames[f].layout, video, write_start, config));
    }
    result.tile_cells = std::move(owners.cell);
    return;
  }
  if (config.balance.stealing()) result.chunk_cells = chunk_tracers(m);
  for (std::size_t f = 0; f < m.frames.size(); ++f) {
    std::vector<const TracedCell*> video;
    std::vector<Cycles> write_start;
    for (const auto& cell : m.cells) {
      video.push_back(&cell->video_memory(static_cast<int>(f)));
      write_start.push_back(cell->record().frame_write_start.at(f));
    }
    MachineConfig compose = config;
    compose.completion_cycles = config.completion_cycles && !config.balance.stealing();
    result.screens.push_back(compose_frame(m.frames[f].layout, video, write_start, compose));
    if (config.completion_cycles && config.balance.stealing())
      result.screens.back().completion_cycles = stolen_completion_cycles(m, static_cast<int>(f), config);
  }
}

}  // namespace

void check_balance(const MachineConfig& config) {
  if (config.frame_average && config.mode != PixelMode::Dot)
    throw std::invalid_argument("frame averaging turns the dot pattern: it needs dot mode");
  if (config.balance.stealing() && config.frame_average)
    throw std::invalid_argument("stealing takes chunks of one frame at a time: no frame averaging");
  if (!config.balance.on_demand()) return;
  if (config.balance.tile_side() < 1)
    throw std::invalid_argument(fmt::format("a tile of {} pixels is not a square", config.balance.tile_pixels));
  if (config.frame_average)
    throw std::invalid_argument("balancing on demand hands out tiles of one frame at a time: no frame averaging");
}

// Plan the units, wire the parts, run their programs, collect what they
// recorded.
SimulationResult run_frames(std::vector<FrameWork> frames, const MachineConfig& asked) {
  MachineConfig config = asked;
  const std::vector<UnitMemory> memory = check_frames(frames, config);
  SimulationResult result;
  result.config = config;
  result.footprint = frames[0].footprint;
  const CostBreakdown host_work = host_voxel_generation(frames, result.voxel_counts);
  for (const FrameWork& f : frames)
    if (!f.voxel_shares.empty()) result.voxel_shares.push_back(f.voxel_shares);
  std::vector<DistributionUnit> units = distribution_units(frames, config);

  MachineParts machine(frames, units, config, result.timeline);
  machine.run();

  record_traffic(machine, result);
  record_units(machine, memory, result);
  record_cells(machine, host_work, result);
  if (config.balance.on_demand()) {
    check_tile_video_memory(machine, config, result);
    result.balancing = machine.host.balancing();
  }
  compose_screens(machine, config, result);
  return result;
}

}  // namespace capsim::sim
