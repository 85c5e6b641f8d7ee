#include "neighbour_links.h"

#include <fmt/core.h>

#include <stdexcept>

namespace capsim::sim {

NeighbourLinks::NeighbourLinks(EventKernel& kernel, CellGrid grid, const CostProfile& profile)
    : kernel_(kernel), grid_(grid), profile_(profile),
      link_free_at_(static_cast<std::size_t>(grid.cell_count()) * 4, Cycles(0)) {}

Cycles NeighbourLinks::hop_cycles(std::uint64_t bytes) const {
  return profile_.link_data_cycles(bytes) + profile_.link.latency;
}

CellId NeighbourLinks::next_hop(CellId at, CellId to) const {
  const CellPosition a = grid_.position(at);
  const CellPosition b = grid_.position(to);
  if (a.col < b.col) return grid_.id({a.row, a.col + 1});
  if (a.col > b.col) return grid_.id({a.row, a.col - 1});
  if (a.row < b.row) return grid_.id({a.row + 1, a.col});
  return grid_.id({a.row - 1, a.col});
}

std::vector<CellId> NeighbourLinks::route(CellId from, CellId to) const {
  std::vector<CellId> cells;
  for (CellId at = from; at != to; at = cells.back()) cells.push_back(next_hop(at, to));
  return cells;
}

NeighbourLinks::SendAwaiter NeighbourLinks::send(CellId from, CellId to, std::uint64_t bytes,
                                                 std::string label) {
  const int n = grid_.cell_count();
  if (from < 0 || from >= n || to < 0 || to >= n || from == to)
    throw std::logic_error("link message needs two different cells of the grid");
  LinkMessage m;
  m.label = std::move(label);
  m.from = from;
  m.to = to;
  m.bytes = bytes;
  return SendAwaiter{*this, std::move(m)};
}

void NeighbourLinks::start(LinkMessage m, ProcessHandle sender) {
  m.sent = kernel_.now();
  const CellId from = m.from;
  kernel_.resume_at(forward(std::move(m), from), sender);
}

Cycles NeighbourLinks::forward(LinkMessage m, CellId at) {
  const CellId next = next_hop(at, m.to);
  const CellPosition a = grid_.position(at);
  const CellPosition b = grid_.position(next);
  const Direction d = b.col > a.col   ? Direction::East
                      : b.col < a.col ? Direction::West
                      : b.row > a.row ? Direction::South
                                      : Direction::North;
  Cycles& free_at = link_free_at_[static_cast<std::size_t>(at) * 4 + static_cast<int>(d)];
  const Cycles start = std::max(kernel_.now(), free_at);
  Cycles last_bit, delivered;
  try {
    last_bit = start + profile_.link_data_cycles(m.bytes);
    delivered = last_bit + profile_.link.latency;
  } catch (const CycleOverflow& e) {
    throw e.inside(fmt::format("link message \"{}\" sent from cell {} at cycle {}", m.label, at,
                               start.count()));
  }
  free_at = last_bit;
  kernel_.schedule(delivered, EventPriority::Delivery,
                   [this, m = std::move(m), next]() mutable {
                     ++m.hops;
                     if (next != m.to) {
                       forward(std::move(m), next);
                       return;
                     }
                     m.arrived = kernel_.now();
                     log_.push_back(m);
                     if (handler_) handler_(m);
                   });
  return last_bit;
}

}  // namespace capsim::sim
