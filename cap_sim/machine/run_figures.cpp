#include "machine/run_figures.h"

#include <algorithm>

namespace capsim::sim {

namespace {

LoadSpread spread_of(const std::vector<Cycles>& times) {
  LoadSpread s;
  if (times.empty()) return s;
  const auto [lo, hi] = std::minmax_element(times.begin(), times.end());
  s.min_finish = *lo;
  s.max_finish = *hi;
  if (s.max_finish.count() > 0)
    s.deviation_percent = 100.0 * static_cast<double>((s.max_finish - s.min_finish).count()) /
                          static_cast<double>(s.max_finish.count());
  return s;
}

}  // namespace

LoadSpread load_spread(const SimulationResult& r) {
  std::vector<Cycles> times;
  for (const CellReport& c : r.cells) times.push_back(c.finish);
  return spread_of(times);
}

LoadSpread busy_spread(const SimulationResult& r) {
  std::vector<Cycles> times;
  for (const CellReport& c : r.cells) times.push_back(c.busy);
  return spread_of(times);
}

UnitMemoryPeak unit_memory_peak(const SimulationResult& r) {
  UnitMemoryPeak peak;
  for (const UnitTimes& u : r.units) {
    peak.cell_memory_bytes = std::max(peak.cell_memory_bytes, u.cell_memory_bytes);
    peak.video_memory_bytes = std::max(peak.video_memory_bytes, u.video_memory_bytes);
  }
  return peak;
}

std::vector<LoadSpread> unit_spreads(const SimulationResult& r) {
  std::vector<LoadSpread> out;
  for (std::size_t u = 0; u < r.units.size(); ++u) {
    std::vector<Cycles> times;
    for (const CellReport& c : r.cells) times.push_back(c.unit_finish.at(u) - r.units[u].start);
    out.push_back(spread_of(times));
  }
  return out;
}

std::vector<LoadSpread> frame_spreads(const SimulationResult& r) {
  if (!r.config.frame_average) return unit_spreads(r);
  std::vector<LoadSpread> out;
  for (std::size_t f = 0; f < r.screens.size(); ++f) {
    std::vector<Cycles> times;
    for (const CellReport& c : r.cells) times.push_back(c.frame_busy.at(f));
    out.push_back(spread_of(times));
  }
  return out;
}

double max_deviation_percent(const SimulationResult& r) {
  double most = 0;
  for (const LoadSpread& s : unit_spreads(r)) most = std::max(most, s.deviation_percent);
  return most;
}

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

double balance_bus_percent(const SimulationResult& r) {
  return r.frame.count() > 0
             ? 100.0 * static_cast<double>(r.balance_bus.busy.count()) / static_cast<double>(r.frame.count())
             : 0.0;
}

}  // namespace capsim::sim
