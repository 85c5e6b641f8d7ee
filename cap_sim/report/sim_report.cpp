#include "report/sim_report.h"

#include "machine/statistics.h"
#include "machine/unit_memory.h"
#include "report/chrome_trace.h"

#include <fmt/core.h>

#include <algorithm>

namespace capsim::sim {

namespace {

// Table 4-5's name for what the run did.
std::string processing_name(const SimulationResult& r) {
  const bool aa = r.config.aa.depth > 0;
  if (r.config.frame_average) return aa ? "frame-averaged antialiasing" : "frame-averaged";
  return aa ? "antialiasing" : "no antialiasing";
}

// A sequence's time and max deviation as the paper's Table 4-5 gives them.
std::string table_4_5_lines(const SimulationResult& r) {
  return fmt::format("Table 4-5 form, {} frames:\n{:<30} {:>12} {:>15}\n{:<30} {:>10.3f} s {:>13.2f} %\n",
                     r.screens.size(), "processing", "time", "max deviation", processing_name(r),
                     r.frame.seconds(r.config.profile.clock_hz), max_deviation_percent(r));
}

std::string format_sequence(const SimulationResult& r) {
  const std::uint64_t hz = r.config.profile.clock_hz;
  std::string out = fmt::format("\n{} frames{}\n{:>6} {:>12} {:>12} {:>8}\n", r.screens.size(),
                                r.config.frame_average
                                    ? fmt::format(", frame averaged in groups of {}", unit_frames(r.config))
                                    : "",
                                "frame", "Max s", "Min s", "d %");
  const std::vector<LoadSpread> frames = frame_spreads(r);
  for (std::size_t f = 0; f < frames.size(); ++f)
    out += fmt::format("{:>6} {:>12.3f} {:>12.3f} {:>8.2f}\n", f, frames[f].max_finish.seconds(hz),
                       frames[f].min_finish.seconds(hz), frames[f].deviation_percent);
  if (r.config.frame_average) {
    out += fmt::format("{:>6} {:>6} {:>12} {:>12} {:>8} {:>14} {:>14}\n", "group", "frames", "Max s", "Min s",
                       "d %", "memory", "video memory");
    const std::vector<LoadSpread> units = unit_spreads(r);
    for (std::size_t u = 0; u < units.size(); ++u)
      out += fmt::format("{:>6} {:>6} {:>12.3f} {:>12.3f} {:>8.2f} {:>12} B {:>12} B\n", u, r.units[u].frames,
                         units[u].max_finish.seconds(hz), units[u].min_finish.seconds(hz),
                         units[u].deviation_percent, r.units[u].cell_memory_bytes, r.units[u].video_memory_bytes);
  }
  out += "The Max, Min and d above the breakdown compare totals over the whole sequence; the load spread that "
         "costs time is each unit's, from its start (the largest is Table 4-5's max deviation, below).\n";
  return out + "\n" + table_4_5_lines(r);
}

}  // namespace

SequenceTime sequence_time(const SimulationResult& r) {
  SequenceTime t;
  t.frames = r.screens.size();
  t.groups = r.config.frame_average ? r.units.size() : 0;
  t.total_seconds = r.frame.seconds(r.config.profile.clock_hz);
  t.frame_seconds = t.frames > 0 ? t.total_seconds / static_cast<double>(t.frames) : 0;
  t.group_seconds = t.groups > 0 ? t.total_seconds / static_cast<double>(t.groups) : 0;
  return t;
}

std::string sequence_time_text(const SimulationResult& r) {
  const SequenceTime t = sequence_time(r);
  if (t.groups > 0)
    return fmt::format("frames: {} in {} groups, time per group (mean) {:.3f} s, per frame (mean) {:.3f} s, total "
                       "{:.3f} s",
                       t.frames, t.groups, t.group_seconds, t.frame_seconds, t.total_seconds);
  return fmt::format("frames: {}, time per frame (mean) {:.3f} s, total {:.3f} s", t.frames, t.frame_seconds,
                     t.total_seconds);
}

namespace {

// One row per cell: row, col, then the value of every cell statistic of the
// scope (cycles as counts), and, with `seconds`, every cycles statistic again
// in seconds.
std::string cell_table(const SimulationResult& r, StatisticScope scope, bool seconds) {
  const std::uint64_t hz = r.config.profile.clock_hz;
  std::string out = fmt::format("{:>4} {:>4}", "row", "col");
  for (const auto& s : kCellStatistics)
    if (s.scope == scope) out += fmt::format(" {:>{}}", s.heading, s.width);
  if (seconds)
    for (const auto& s : kCellStatistics)
      if (s.scope == scope && s.unit == StatisticUnit::Cycles) out += fmt::format(" {:>10}", std::string(s.name) + " s");
  out += "\n";
  for (const CellReport& c : r.cells) {
    out += fmt::format("{:>4} {:>4}", c.position.row, c.position.col);
    for (const auto& s : kCellStatistics)
      if (s.scope == scope) out += fmt::format(" {:>{}}", s.value(c), s.width);
    if (seconds)
      for (const auto& s : kCellStatistics)
        if (s.scope == scope && s.unit == StatisticUnit::Cycles)
          out += fmt::format(" {:>10.3f}", Cycles(s.value(c)).seconds(hz));
    out += "\n";
  }
  return out;
}

std::string header_line(const SimulationResult& r) {
  const std::string sharing =
      r.config.balance.on_demand()
          ? fmt::format("balanced on demand in tiles of {} pixels", r.config.balance.tile_pixels)
      : r.config.balance.stealing()
          ? fmt::format("{} mode, stealing chunks of {} pixels", to_string(r.config.mode), r.config.balance.chunk_pixels)
          : fmt::format("{} mode", to_string(r.config.mode));
  return fmt::format("CAP simulation: {} cells, {}, {}profile {} ({} Hz), {}x{} pixels\n", to_string(r.config.cells),
                     sharing, r.config.voxel_generation == VoxelGeneration::Cells ? "voxels generated by the cells, " : "",
                     r.config.profile.name, r.config.profile.clock_hz, r.width, r.height);
}

std::string format_balancing(const SimulationResult& r) {
  const std::uint64_t hz = r.config.profile.clock_hz;
  const int side = r.config.balance.tile_side();
  std::size_t tiles = 0;
  for (const auto& frame : r.tile_cells) tiles += frame.size();
  std::string out = fmt::format("\nbalanced on demand: {} tiles of at most {}x{} pixels\n", tiles, side, side);
  out += cell_table(r, StatisticScope::Demand, false);
  const Host::Balancing& h = r.balancing;
  out += fmt::format(
      "host: {} requests ({} B) answered with {} grants and {} \"no tile\" ({} B)\n"
      "bus for balancing: {} transfers, {} B, busy {} cycles ({:.3f} s), {:.3f} % of the run's time\n",
      h.requests, h.bytes_received, h.grants, h.refusals, h.bytes_sent, r.balance_bus.transfers,
      r.balance_bus.bytes, r.balance_bus.busy.count(), r.balance_bus.busy.seconds(hz), balance_bus_percent(r));
  return out;
}

// Voxel generation on the cells: Algorithm-3's operations the shares summed
// (each as often as the host's), and the two broadcasts' traffic.
VoxelGenCounts shares_counts(const SimulationResult& r) {
  VoxelGenCounts n;
  for (const auto& frame : r.voxel_shares)
    for (const VoxelShare& s : frame) {
      n += s.placing;
      n += s.building;
    }
  return n;
}

std::string format_voxel_generation(const SimulationResult& r) {
  const std::uint64_t hz = r.config.profile.clock_hz;
  const VoxelGenCounts n = shares_counts(r);
  std::string out = fmt::format(
      "\nvoxel generation on the cells: {} primitives placed, {} voxel columns, {} entries, {} grid voxels\n",
      n.primitives, n.columns, n.voxel_entries, n.grid_voxels);
  out += cell_table(r, StatisticScope::CellVoxels, false);
  out += fmt::format("bus: voxel entries {} transfers, {} B, busy {} cycles ({:.3f} s); voxel rows {} transfers, {} B, "
                     "busy {} cycles ({:.3f} s)\n",
                     r.voxel_entries_bus.transfers, r.voxel_entries_bus.bytes, r.voxel_entries_bus.busy.count(),
                     r.voxel_entries_bus.busy.seconds(hz), r.voxel_rows_bus.transfers, r.voxel_rows_bus.bytes,
                     r.voxel_rows_bus.busy.count(), r.voxel_rows_bus.busy.seconds(hz));
  return out;
}

// Stealing: what was stolen and the links' stealing traffic.
struct StealTotals {
  std::uint64_t chunks = 0, stolen = 0, requests = 0, refused = 0;
};
StealTotals steal_totals(const SimulationResult& r) {
  StealTotals t;
  for (const CellReport& c : r.cells) {
    t.stolen += c.chunks_stolen;
    t.requests += c.steal_requests;
    t.refused += c.steals_refused;
  }
  for (const auto& frame : r.chunk_cells)
    for (const auto& window : frame) t.chunks += window.size();
  return t;
}

std::string format_stealing(const SimulationResult& r) {
  const StealTotals t = steal_totals(r);
  std::string out = fmt::format("\nstealing: {} chunks of at most {} pixels, {} of them stolen\n", t.chunks,
                                r.config.balance.chunk_pixels, t.stolen);
  out += cell_table(r, StatisticScope::Steal, false);
  out += fmt::format("requests: {}, {} answered \"no work\"; links for stealing: {} messages, {} B\n", t.requests,
                     t.refused, r.steal_links.messages, r.steal_links.bytes);
  return out;
}

// Max, Min and d over the finish times, the same over busy time, and the
// frame's time (a sequence's per frame and in all).
std::string spread_lines(const SimulationResult& r) {
  const std::uint64_t hz = r.config.profile.clock_hz;
  const LoadSpread s = load_spread(r);
  const LoadSpread busy = busy_spread(r);
  return fmt::format("Max {:.3f} s   Min {:.3f} s   d = (Max - Min) / Max = {:.2f} %\n", s.max_finish.seconds(hz),
                     s.min_finish.seconds(hz), s.deviation_percent) +
         fmt::format("busy only (the cycles each cell computed): Max {:.3f} s   Min {:.3f} s   d = {:.2f} %\n",
                     busy.max_finish.seconds(hz), busy.min_finish.seconds(hz), busy.deviation_percent) +
         (r.screens.size() > 1 ? fmt::format("{} ({} cycles)\n", sequence_time_text(r), r.frame.count())
                               : fmt::format("frame time {:.3f} s ({} cycles)\n", r.frame.seconds(hz), r.frame.count()));
}

std::string format_antialiasing(const SimulationResult& r) {
  const std::uint64_t hz = r.config.profile.clock_hz;
  std::string out = fmt::format("\nantialiasing: depth {}, threshold {}, links: {}\n", r.config.aa.depth,
                                r.config.aa.threshold, to_string(r.config.profile.link.topology));
  out += cell_table(r, StatisticScope::Antialiased, false);
  const LinkTotals t = link_totals(r);
  out += fmt::format(
      "link traffic: {} messages, {} bytes, {} hops (at most {} for one message) over {} links\n"
      "busiest link {} cycles ({:.3f} s); longest wait for a link {} cycles\n",
      t.messages, t.bytes, t.hops, t.max_hops, r.links.size(), t.busiest.count(),
      t.busiest.seconds(hz), t.longest_wait.count());
  return out;
}

}  // namespace

std::string format_summary(const SimulationResult& r) {
  std::string out = header_line(r) + spread_lines(r);
  if (r.screens.size() > 1) out += table_4_5_lines(r);
  return out;
}

std::string format_report(const SimulationResult& r, const Provenance* provenance) {
  const std::uint64_t hz = r.config.profile.clock_hz;
  std::string out = header_line(r);
  if (r.config.voxel_generation == VoxelGeneration::Cells)
    out += fmt::format("data broadcast: program {} B, scene {} B (and the grid's header, {} B); the cells broadcast the "
                       "voxel data ({} B as the host would broadcast it)\n",
                       r.config.profile.program_bytes, r.footprint.scene_bytes(), kCellGridHeaderBytes,
                       r.footprint.voxel_bytes());
  else
    out += fmt::format("data broadcast: program {} B, scene {} B, voxel data {} B\n", r.config.profile.program_bytes,
                       r.footprint.scene_bytes(), r.footprint.voxel_bytes());
  const UnitMemoryPeak peak = unit_memory_peak(r);
  out += fmt::format("a cell holds, for a unit of {} frame{} (the most over the units): memory {} of {} B, "
                     "video memory {} of {} B\n\n",
                     unit_frames(r.config), unit_frames(r.config) == 1 ? "" : "s", peak.cell_memory_bytes,
                     r.config.profile.cell_memory_bytes, peak.video_memory_bytes, r.config.profile.video_memory_bytes);
  out += cell_table(r, StatisticScope::Always, true);

  out += "\n";
  out += spread_lines(r);
  out += "\n";

  out += r.config.voxel_generation == VoxelGeneration::Cells
             ? "time by process (all cells' work, their voxel generation included):\n"
             : "time by process (all cells' work and the host's voxel generation):\n";
  const double total = r.breakdown.total().seconds(hz);
  for (const CostCategoryInfo& c : kCostCategoryTable) {
    const double sec = r.breakdown[c.category].seconds(hz);
    out += fmt::format("  {:<22} {:>14.3f} s {:>7.1f} %\n", c.name, sec,
                       total > 0 ? 100.0 * sec / total : 0.0);
  }
  out += fmt::format("  {:<22} {:>14.3f} s\n", "total", total);
  if (r.config.aa.depth > 0) out += format_antialiasing(r);
  if (r.config.balance.on_demand()) out += format_balancing(r);
  if (r.config.balance.stealing()) out += format_stealing(r);
  if (r.config.voxel_generation == VoxelGeneration::Cells) out += format_voxel_generation(r);
  if (r.screens.size() > 1) out += format_sequence(r);
  if (provenance) out += provenance_text(*provenance);
  return out;
}

namespace {

void add_antialiasing(nlohmann::json& report, const SimulationResult& r) {
  using nlohmann::json;
  report["antialiasing"] = {{"depth", r.config.aa.depth},
                            {"threshold", r.config.aa.threshold},
                            {"link_topology", to_string(r.config.profile.link.topology)},
                            {"sample_bytes", kScreenSampleBytes}};
  for (std::size_t i = 0; i < r.cells.size(); ++i)
    for (const auto& s : kCellStatistics)
      if (s.scope == StatisticScope::Antialiased) report["cells"][i][s.json_key()] = s.value(r.cells[i]);
  json links = json::array();
  for (const LinkTraffic& l : r.links) {
    const CellPosition p = r.config.cells.position(l.cell);
    json link = {{"row", p.row}, {"col", p.col}, {"direction", to_string(l.direction)}};
    for (const auto& s : kLinkStatistics) link[s.json_key()] = s.value(l);
    links.push_back(link);
  }
  const LinkTotals t = link_totals(r);
  report["links"] = links;
  report["link_totals"] = {{"messages", t.messages},
                           {"bytes", t.bytes},
                           {"hops", t.hops},
                           {"max_hops", t.max_hops},
                           {"busiest_link_cycles", t.busiest.count()},
                           {"longest_wait_cycles", t.longest_wait.count()}};
}

void add_stealing(nlohmann::json& report, const SimulationResult& r) {
  for (std::size_t i = 0; i < r.cells.size(); ++i)
    for (const auto& s : kCellStatistics)
      if (s.scope == StatisticScope::Steal) report["cells"][i][s.json_key()] = s.value(r.cells[i]);
  const StealTotals t = steal_totals(r);
  report["balancing"] = {{"scheme", "steal"},
                         {"chunk_pixels", r.config.balance.chunk_pixels},
                         {"chunks", t.chunks},
                         {"chunks_stolen", t.stolen},
                         {"requests", t.requests},
                         {"refused", t.refused},
                         {"chunk_cells", r.chunk_cells},
                         {"links", {{"messages", r.steal_links.messages}, {"bytes", r.steal_links.bytes}}}};
}

void add_voxel_generation(nlohmann::json& report, const SimulationResult& r) {
  for (std::size_t i = 0; i < r.cells.size(); ++i)
    for (const auto& s : kCellStatistics)
      if (s.scope == StatisticScope::CellVoxels) report["cells"][i][s.json_key()] = s.value(r.cells[i]);
  const VoxelGenCounts n = shares_counts(r);
  auto bus = [](const BusTotals& b) {
    return nlohmann::json{{"transfers", b.transfers}, {"bytes", b.bytes}, {"busy_cycles", b.busy.count()}};
  };
  report["voxel_generation"] = {{"by", "cells"},
                                {"primitives", n.primitives},
                                {"columns", n.columns},
                                {"entries", n.voxel_entries},
                                {"grid_voxels", n.grid_voxels},
                                {"grid_header_bytes", kCellGridHeaderBytes},
                                {"entries_bus", bus(r.voxel_entries_bus)},
                                {"rows_bus", bus(r.voxel_rows_bus)}};
}

void add_balancing(nlohmann::json& report, const SimulationResult& r) {
  for (std::size_t i = 0; i < r.cells.size(); ++i)
    for (const auto& s : kCellStatistics)
      if (s.scope == StatisticScope::Demand) report["cells"][i][s.json_key()] = s.value(r.cells[i]);
  const Host::Balancing& h = r.balancing;
  report["balancing"] = {{"scheme", "demand"},
                         {"tile_pixels", r.config.balance.tile_pixels},
                         {"tile_side", r.config.balance.tile_side()},
                         {"tile_cells", r.tile_cells},
                         {"host", {{"requests", h.requests},
                                   {"grants", h.grants},
                                   {"no_tile", h.refusals},
                                   {"bytes_received", h.bytes_received},
                                   {"bytes_sent", h.bytes_sent}}},
                         {"bus", {{"transfers", r.balance_bus.transfers},
                                  {"bytes", r.balance_bus.bytes},
                                  {"busy_cycles", r.balance_bus.busy.count()},
                                  {"occupancy_percent", balance_bus_percent(r)}}}};
}

void add_sequence(nlohmann::json& report, const SimulationResult& r) {
  using nlohmann::json;
  const std::uint64_t hz = r.config.profile.clock_hz;
  auto spread_json = [&](const LoadSpread& s) {
    return json{{"max_seconds", s.max_finish.seconds(hz)},
                {"min_seconds", s.min_finish.seconds(hz)},
                {"max_cycles", s.max_finish.count()},
                {"min_cycles", s.min_finish.count()},
                {"deviation_percent", s.deviation_percent}};
  };
  json frames = json::array();
  const std::vector<LoadSpread> fs = frame_spreads(r);
  for (std::size_t f = 0; f < fs.size(); ++f) {
    json j = spread_json(fs[f]);
    j["frame"] = f;
    frames.push_back(j);
  }
  json units = json::array();
  const std::vector<LoadSpread> us = unit_spreads(r);
  for (std::size_t u = 0; u < us.size(); ++u) {
    json j = spread_json(us[u]);
    j["first_frame"] = r.units[u].first_frame;
    j["frames"] = r.units[u].frames;
    j["start_cycles"] = r.units[u].start.count();
    j["end_cycles"] = r.units[u].end.count();
    j["cell_memory_bytes"] = r.units[u].cell_memory_bytes;
    j["video_memory_bytes"] = r.units[u].video_memory_bytes;
    units.push_back(j);
  }
  for (std::size_t i = 0; i < r.cells.size(); ++i) {
    json busy = json::array();
    for (Cycles c : r.cells[i].frame_busy) busy.push_back(c.count());
    report["cells"][i]["frame_busy_cycles"] = busy;
  }
  report["frames"] = frames;
  report["units"] = units;
  const SequenceTime time = sequence_time(r);
  report["sequence"] = {{"frames", r.screens.size()},
                        {"frame_average", r.config.frame_average},
                        {"processing", processing_name(r)},
                        {"total_seconds", r.frame.seconds(hz)},
                        {"mean_frame_seconds", time.frame_seconds},
                        {"total_cycles", r.frame.count()},
                        {"max_deviation_percent", max_deviation_percent(r)}};
  if (time.groups > 0) {
    report["sequence"]["groups"] = time.groups;
    report["sequence"]["mean_group_seconds"] = time.group_seconds;
  }
}

}  // namespace

nlohmann::json report_json(const SimulationResult& r, const Provenance* provenance) {
  using nlohmann::json;
  const std::uint64_t hz = r.config.profile.clock_hz;
  json cells = json::array();
  for (const CellReport& c : r.cells) {
    json cell = {{"row", c.position.row}, {"col", c.position.col}};
    for (const auto& s : kCellStatistics)
      if (s.scope == StatisticScope::Always) cell[s.json_key()] = s.value(c);
    cells.push_back(cell);
  }
  json breakdown = json::object();
  json breakdown_cycles = json::object();
  for (const CostCategoryInfo& c : kCostCategoryTable) {
    breakdown[c.json_key] = r.breakdown[c.category].seconds(hz);
    breakdown_cycles[c.json_key] = r.breakdown[c.category].count();
  }
  const LoadSpread s = load_spread(r);
  const LoadSpread busy = busy_spread(r);
  const UnitMemoryPeak peak = unit_memory_peak(r);
  json report = {{"mode", to_string(r.config.mode)},
          {"cells_grid", to_string(r.config.cells)},
          {"profile", r.config.profile.name},
          {"clock_hz", hz},
          {"width", r.width},
          {"height", r.height},
          {"program_bytes", r.config.profile.program_bytes},
          {"scene_bytes", r.footprint.scene_bytes()},
          {"voxel_bytes", r.footprint.voxel_bytes()},
          {"cells", cells},
          {"max_seconds", s.max_finish.seconds(hz)},
          {"min_seconds", s.min_finish.seconds(hz)},
          {"deviation_percent", s.deviation_percent},
          {"busy_max_seconds", busy.max_finish.seconds(hz)},
          {"busy_min_seconds", busy.min_finish.seconds(hz)},
          {"busy_max_cycles", busy.max_finish.count()},
          {"busy_min_cycles", busy.min_finish.count()},
          {"busy_deviation_percent", busy.deviation_percent},
          {"unit_memory", {{"unit_frames", unit_frames(r.config)},
                           {"cell_memory_bytes", peak.cell_memory_bytes},
                           {"cell_memory_limit_bytes", r.config.profile.cell_memory_bytes},
                           {"video_memory_bytes", peak.video_memory_bytes},
                           {"video_memory_limit_bytes", r.config.profile.video_memory_bytes}}},
          {"breakdown", breakdown},
          {"breakdown_cycles", breakdown_cycles},
          {"total_cycles", r.frame.count()}};
  if (r.config.aa.depth > 0) add_antialiasing(report, r);
  if (r.config.balance.on_demand()) add_balancing(report, r);
  if (r.config.balance.stealing()) add_stealing(report, r);
  if (r.config.voxel_generation == VoxelGeneration::Cells) add_voxel_generation(report, r);
  if (r.screens.size() > 1) add_sequence(report, r);
  if (provenance) report["provenance"] = provenance_json(*provenance);
  return report;
}

std::string report_json_text(const SimulationResult& r, const Provenance* provenance) {
  return report_json(r, provenance).dump(2) + "\n";
}

std::string chrome_trace_text(const SimulationResult& r) {
  const std::string name = fmt::format("CAP {} cells, {} mode, profile {}", to_string(r.config.cells),
                                       to_string(r.config.mode), r.config.profile.name);
  return chrome_trace(r.timeline, name, r.config.profile.clock_hz).dump() + "\n";
}

}  // namespace capsim::sim
