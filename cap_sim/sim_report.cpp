#include "sim_report.h"

#include <fmt/core.h>

#include <algorithm>

namespace capsim::sim {

LoadSpread load_spread(const SimulationResult& r) {
  LoadSpread s;
  if (r.cells.empty()) return s;
  const auto [lo, hi] = std::minmax_element(
      r.cells.begin(), r.cells.end(),
      [](const CellReport& a, const CellReport& b) { return a.finish < b.finish; });
  s.min_finish = lo->finish;
  s.max_finish = hi->finish;
  if (s.max_finish.count() > 0)
    s.deviation_percent = 100.0 * static_cast<double>((s.max_finish - s.min_finish).count()) /
                          static_cast<double>(s.max_finish.count());
  return s;
}

namespace {

constexpr CostCategory kCategories[] = {CostCategory::Intersection, CostCategory::Dda,
                                        CostCategory::Csg, CostCategory::VoxelGeneration,
                                        CostCategory::Other};

}  // namespace

LinkTotals link_totals(const SimulationResult& r) {
  LinkTotals t;
  t.messages = r.link_messages.size();
  for (const LinkMessage& m : r.link_messages) {
    t.bytes += m.bytes;
    t.hops += static_cast<std::uint64_t>(m.hops);
    t.max_hops = std::max(t.max_hops, m.hops);
  }
  for (const LinkTraffic& l : r.links) {
    t.busiest = std::max(t.busiest, l.busy);
    t.longest_wait = std::max(t.longest_wait, l.max_wait);
  }
  return t;
}

namespace {

std::string format_antialiasing(const SimulationResult& r) {
  const std::uint64_t hz = r.config.profile.clock_hz;
  std::string out = fmt::format(
      "\nantialiasing: depth {}, threshold {}, links: {}\n"
      "{:>4} {:>4} {:>16} {:>14} {:>14} {:>9}\n",
      r.config.aa.depth, r.config.aa.threshold, to_string(r.config.profile.link.topology), "row",
      "col", "trace corners", "exchange", "subdivide", "corners in");
  for (const CellReport& c : r.cells)
    out += fmt::format("{:>4} {:>4} {:>16} {:>14} {:>14} {:>9}\n", c.position.row, c.position.col,
                       c.trace_corners.count(), c.exchange.count(), c.subdivide.count(),
                       c.corners_received.size());
  const LinkTotals t = link_totals(r);
  out += fmt::format(
      "link traffic: {} messages, {} bytes, {} hops (at most {} for one message) over {} links\n"
      "busiest link {} cycles ({:.3f} s); longest wait for a link {} cycles\n",
      t.messages, t.bytes, t.hops, t.max_hops, r.links.size(), t.busiest.count(),
      t.busiest.seconds(hz), t.longest_wait.count());
  return out;
}

}  // namespace

std::string format_report(const SimulationResult& r) {
  const std::uint64_t hz = r.config.profile.clock_hz;
  std::string out = fmt::format(
      "CAP simulation: {} cells, {} mode, profile {} ({} Hz), {}x{} pixels\n",
      to_string(r.config.cells), to_string(r.config.mode), r.config.profile.name, hz,
      r.width, r.height);
  out += fmt::format("data broadcast: program {} B, scene {} B, voxel data {} B\n\n",
                     r.config.profile.program_bytes, r.footprint.scene_bytes(),
                     r.footprint.voxel_bytes());
  out += fmt::format("{:>4} {:>4} {:>8} {:>9} {:>14} {:>14} {:>12} {:>14} {:>10} {:>10} {:>10} {:>10}\n",
                     "row", "col", "pixels", "rays", "busy cyc", "idle cyc", "comm cyc",
                     "finish cyc", "busy s", "idle s", "comm s", "finish s");
  for (const CellReport& c : r.cells)
    out += fmt::format(
        "{:>4} {:>4} {:>8} {:>9} {:>14} {:>14} {:>12} {:>14} {:>10.3f} {:>10.3f} {:>10.3f} {:>10.3f}\n",
        c.position.row, c.position.col, c.pixels, c.rays, c.busy.count(), c.idle.count(),
        c.comm.count(), c.finish.count(), c.busy.seconds(hz), c.idle.seconds(hz),
        c.comm.seconds(hz), c.finish.seconds(hz));

  const LoadSpread s = load_spread(r);
  out += fmt::format("\nMax {:.3f} s   Min {:.3f} s   d = (Max - Min) / Max = {:.2f} %\n",
                     s.max_finish.seconds(hz), s.min_finish.seconds(hz), s.deviation_percent);
  out += fmt::format("frame time {:.3f} s ({} cycles)\n\n", r.frame.seconds(hz), r.frame.count());

  out += "time by process (all cells' work and the host's voxel generation):\n";
  const double total = r.breakdown.total().seconds(hz);
  for (CostCategory c : kCategories) {
    const double sec = r.breakdown[c].seconds(hz);
    out += fmt::format("  {:<22} {:>14.3f} s {:>7.1f} %\n", to_string(c), sec,
                       total > 0 ? 100.0 * sec / total : 0.0);
  }
  out += fmt::format("  {:<22} {:>14.3f} s\n", "total", total);
  if (r.config.aa.depth > 0) out += format_antialiasing(r);
  return out;
}

namespace {

void add_antialiasing(nlohmann::json& report, const SimulationResult& r) {
  using nlohmann::json;
  report["antialiasing"] = {{"depth", r.config.aa.depth},
                            {"threshold", r.config.aa.threshold},
                            {"link_topology", to_string(r.config.profile.link.topology)},
                            {"sample_bytes", kScreenSampleBytes}};
  for (std::size_t i = 0; i < r.cells.size(); ++i) {
    const CellReport& c = r.cells[i];
    json& cell = report["cells"][i];
    cell["trace_corners_cycles"] = c.trace_corners.count();
    cell["exchange_cycles"] = c.exchange.count();
    cell["subdivide_cycles"] = c.subdivide.count();
    cell["corners_received"] = c.corners_received.size();
  }
  json links = json::array();
  for (const LinkTraffic& l : r.links) {
    const CellPosition p = r.config.cells.position(l.cell);
    links.push_back({{"row", p.row},
                     {"col", p.col},
                     {"direction", to_string(l.direction)},
                     {"messages", l.messages},
                     {"bytes", l.bytes},
                     {"busy_cycles", l.busy.count()},
                     {"max_wait_cycles", l.max_wait.count()}});
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

}  // namespace

nlohmann::json report_json(const SimulationResult& r) {
  using nlohmann::json;
  const std::uint64_t hz = r.config.profile.clock_hz;
  json cells = json::array();
  for (const CellReport& c : r.cells)
    cells.push_back({{"row", c.position.row},
                     {"col", c.position.col},
                     {"pixels", c.pixels},
                     {"rays", c.rays},
                     {"busy_cycles", c.busy.count()},
                     {"idle_cycles", c.idle.count()},
                     {"comm_cycles", c.comm.count()},
                     {"finish_cycles", c.finish.count()}});
  json breakdown = json::object();
  json breakdown_cycles = json::object();
  for (CostCategory c : kCategories) {
    breakdown[json_key(c)] = r.breakdown[c].seconds(hz);
    breakdown_cycles[json_key(c)] = r.breakdown[c].count();
  }
  const LoadSpread s = load_spread(r);
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
          {"breakdown", breakdown},
          {"breakdown_cycles", breakdown_cycles},
          {"total_cycles", r.frame.count()}};
  if (r.config.aa.depth > 0) add_antialiasing(report, r);
  return report;
}

}  // namespace capsim::sim
