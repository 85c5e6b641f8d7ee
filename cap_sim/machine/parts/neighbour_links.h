#pragma once
// The neighbour links: every cell has a link to each adjacent cell (N, E, S, W),
// one direction per link, each carrying one message at a time in FIFO order.
// A hop occupies its link for ceil(bytes * 8 * clock / bits_per_second) cycles and
// the message is in the next cell `latency` cycles after its last bit.
// Messages to cells that are not adjacent go store-and-forward, hop by hop: X
// first (east or west along the row), then Y (north or south along the column);
// each intermediate cell receives the whole message before sending it on, in its
// link hardware, without the cell's program. On a torus (the profile's
// link.topology) the edge cells are linked to the opposite edge too, and each
// axis goes the shorter way round (east or south where both are as short).

#include "kernel/event_kernel.h"
#include "machine/parts/cell_grid.h"
#include "machine/costs/cost_profile.h"
#include "machine/parts/frame_protocol.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace capsim::sim {

struct LinkMessage {
  LinkPacket packet;
  CellId from = 0;
  CellId to = 0;
  std::uint64_t bytes = 0;
  Cycles sent;     // the sender handed it to its first link
  Cycles arrived;  // it is in the destination's memory
  int hops = 0;
};

// One direction of one link, from `cell` toward `direction`.
struct LinkTraffic {
  CellId cell = 0;
  Direction direction = Direction::North;
  std::uint64_t messages = 0;
  std::uint64_t bytes = 0;
  Cycles busy;      // cycles bits were on it
  Cycles max_wait;  // longest a message waited for it to be free
};

// One message on one link: when its first and last bits were sent.
struct LinkHop {
  CellId cell = 0;
  Direction direction = Direction::North;
  LinkPacket packet;
  Cycles begin, end;
  std::uint64_t bytes = 0;
};

class NeighbourLinks {
 public:
  NeighbourLinks(EventKernel& kernel, CellGrid grid, const CostProfile& profile);

  // Called at each message's arrival at its destination (priority Delivery).
  void on_delivery(std::function<void(const LinkMessage&)> handler) { handler_ = std::move(handler); }

  // The cells a message passes after leaving `from`, ending with `to` (X then Y).
  std::vector<CellId> route(CellId from, CellId to) const;
  // One uncontended hop: data cycles plus latency.
  Cycles hop_cycles(std::uint64_t bytes) const;

  // co_await links.send(...): the sender continues when the message has left it
  // (its last bit is on the first link); delivery happens later.
  struct SendAwaiter {
    NeighbourLinks& links;
    LinkMessage message;
    bool await_ready() const noexcept { return false; }
    void await_suspend(std::coroutine_handle<> h) { links.start(std::move(message), h); }
    void await_resume() const noexcept {}
  };
  SendAwaiter send(CellId from, CellId to, std::uint64_t bytes, LinkPacket packet);

  // Delivered messages, in order of arrival.
  const std::vector<LinkMessage>& log() const { return log_; }
  // Every hop of every message, in the order they were put on their links.
  const std::vector<LinkHop>& hops() const { return hops_; }
  // The links that carried anything, in order of (cell, direction).
  std::vector<LinkTraffic> traffic() const;

 private:
  CellId next_hop(CellId at, CellId to) const;
  Direction direction_of(CellId at, CellId next) const;
  void start(LinkMessage m, std::coroutine_handle<> sender);
  // Queues the message on the link from `at` toward its next hop; returns the
  // cycle its last bit leaves `at`.
  Cycles forward(LinkMessage m, CellId at);

  EventKernel& kernel_;
  CellGrid grid_;
  const CostProfile& profile_;
  std::function<void(const LinkMessage&)> handler_;
  std::vector<Cycles> link_free_at_;  // per (cell, direction): cell * 4 + direction
  std::vector<LinkTraffic> traffic_;  // the same index
  std::vector<LinkMessage> log_;
  std::vector<LinkHop> hops_;
};

}  // namespace capsim::sim
