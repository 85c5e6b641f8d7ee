#include "machine/parts/neighbour_links.h"

#include <fmt/core.h>

#include <algorithm>
#include <stdexcept>

namespace capsim::sim {

NeighbourLinks::NeighbourLinks(EventKernel& kernel, CellGrid grid, const CostProfile& profile)
    : kernel_(kernel), grid_(grid), profile_(profile),
      link_free_at_(static_cast<std::size_t>(grid.cell_count()) * 4, Cycles(0)),
      traffic_(static_cast<std::size_t>(grid.cell_count()) * 4) {
  for (std::size_t i = 0; i < traffic_.size(); ++i) {
    traffic_[i].cell = static_cast<CellId>(i / 4);
    traffic_[i].direction = static_cast<Direction>(i % 4);
  }
}

std::vector<LinkTraffic> NeighbourLinks::traffic() const {
  std::vector<LinkTraffic> used;
  for (const LinkTraffic& t : traffic_)
    if (t.messages > 0) used.push_back(t);
  return used;
}

Cycles NeighbourLinks::hop_cycles(std::uint64_t bytes) const {
  return profile_.link_data_cycles(bytes) + profile_.link.latency;
}

namespace {

// The step (+1 or -1) along one axis of `size` cells from a to b != a, on a
// ring: the shorter way round, the positive way on a tie.
int ring_step(int a, int b, int size) {
  const int forward = ((b - a) % size + size) % size;
  return forward <= size - forward ? 1 : -1;
}

}  // namespace

CellId NeighbourLinks::next_hop(CellId at, CellId to) const {
  const CellPosition a = grid_.position(at);
  const CellPosition b = grid_.position(to);
  if (profile_.link.topology == LinkTopology::Torus) {
    if (a.col != b.col)
      return grid_.id({a.row, (a.col + ring_step(a.col, b.col, grid_.cols) + grid_.cols) % grid_.cols});
    return grid_.id({(a.row + ring_step(a.row, b.row, grid_.rows) + grid_.rows) % grid_.rows, a.col});
  }
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

NeighbourLinks::SendAwaiter NeighbourLinks::send(CellId from, CellId to, std::uint64_t bytes, LinkPacket packet) {
  const int n = grid_.cell_count();
  if (from < 0 || from >= n || to < 0 || to >= n || from == to)
    throw std::logic_error("link message needs two different cells of the grid");
  LinkMessage m;
  m.packet = packet;
  m.from = from;
  m.to = to;
  m.bytes = bytes;
  return SendAwaiter{*this, std::move(m)};
}

void NeighbourLinks::start(LinkMessage m, std::coroutine_handle<> sender) {
  m.sent = kernel_.now();
  const CellId from = m.from;
  kernel_.resume_at(forward(std::move(m), from), sender);
}

Direction NeighbourLinks::direction_of(CellId at, CellId next) const {
  const CellPosition a = grid_.position(at);
  const CellPosition b = grid_.position(next);
  if (profile_.link.topology == LinkTopology::Mesh) {
    if (a.row == b.row) return b.col > a.col ? Direction::East : Direction::West;
    return b.row > a.row ? Direction::South : Direction::North;
  }
  // Adjacent on the ring, possibly over the wrap-around link; on a ring of two
  // both links join the same cells, and the east (south) one is taken, as
  // next_hop does.
  if (a.row == b.row) return b.col == (a.col + 1) % grid_.cols ? Direction::East : Direction::West;
  return b.row == (a.row + 1) % grid_.rows ? Direction::South : Direction::North;
}

Cycles NeighbourLinks::forward(LinkMessage m, CellId at) {
  const CellId next = next_hop(at, m.to);
  const Direction d = direction_of(at, next);
  const std::size_t link = static_cast<std::size_t>(at) * 4 + static_cast<int>(d);
  Cycles& free_at = link_free_at_[link];
  const Cycles start = std::max(kernel_.now(), free_at);
  Cycles data, last_bit, delivered;
  try {
    data = profile_.link_data_cycles(m.bytes);
    last_bit = start + data;
    delivered = last_bit + profile_.link.latency;
  } catch (const CycleOverflow& e) {
    throw e.inside(fmt::format("link message \"{}\" sent from cell {} at cycle {}", to_string(m.packet), at,
                               start.count()));
  }
  free_at = last_bit;
  LinkTraffic& t = traffic_[link];
  ++t.messages;
  t.bytes += m.bytes;
  t.busy += data;
  t.max_wait = std::max(t.max_wait, start - kernel_.now());
  hops_.push_back({at, d, m.packet, start, last_bit, m.bytes});
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
