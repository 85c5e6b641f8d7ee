#pragma once
// The command bus: one bus shared by the host and every cell (paper §3.1).
//
// One transfer at a time. A transfer occupies the bus for
//   arbitration + ceil(bytes * clock / bytes_per_second)   cycles
// from its grant, and its data is in the receivers' memory `latency` cycles after
// the last byte; a broadcast (receiver kAllCells) reaches every cell in that one
// transfer. Uncontended, a transfer therefore takes arbitration + data + latency.
//
// Arbitration policy: whenever the bus is free, at the Arbitration priority of a
// cycle (after every process of that cycle has had its turn), it grants the
// pending request with the earliest request cycle; among equals the host first,
// then the lowest cell id; then the earliest request (FIFO).

#include "kernel/event_kernel.h"
#include "machine/costs/cost_profile.h"
#include "machine/parts/frame_protocol.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace capsim::sim {

// Who sends or receives on the bus: a cell id (>= 0), the host, or every cell
// (a cell's broadcast reaches every other cell).
using Endpoint = int;
inline constexpr Endpoint kHost = -1;
inline constexpr Endpoint kAllCells = -2;

struct BusTransfer {
  BusMessage message = BusMessage::Start;
  Endpoint sender = kHost;
  Endpoint receiver = kAllCells;
  std::uint64_t bytes = 0;
  int tile = -1;     // a grant: the tile it hands out (balance.h)
  int frame = -1;    // voxel entries or rows: the run's frame whose grid they build
  Cycles requested;  // the sender asked for the bus
  Cycles granted;    // the bus was granted (arbitration starts)
  Cycles released;   // the last byte left the bus; the bus is free again
  Cycles delivered;  // the data is in the receivers' memory; the sender continues
};

class CommandBus {
 public:
  CommandBus(EventKernel& kernel, const CostProfile& profile);

  // Called at each transfer's delivery cycle (priority Delivery), before the
  // sender continues.
  void on_delivery(std::function<void(const BusTransfer&)> handler) { handler_ = std::move(handler); }

  // The cycles an uncontended transfer of `bytes` takes from request to delivery.
  Cycles transfer_cycles(std::uint64_t bytes) const;

  // co_await bus.transfer(...): requests the bus, waits for the grant and the
  // transfer, and returns its record once the data is delivered.
  struct TransferAwaiter {
    CommandBus& bus;
    BusTransfer transfer;
    bool await_ready() const noexcept { return false; }
    void await_suspend(std::coroutine_handle<> h) { bus.request(&transfer, h); }
    BusTransfer await_resume() { return std::move(transfer); }
  };
  TransferAwaiter transfer(Endpoint sender, Endpoint receiver, std::uint64_t bytes, BusMessage message,
                           int tile = -1, int frame = -1);

  // Every completed transfer, in delivery order.
  const std::vector<BusTransfer>& log() const { return log_; }

 private:
  struct Request {
    BusTransfer* transfer;  // lives in the waiting sender's frame
    std::coroutine_handle<> sender;
    std::uint64_t sequence;
  };
  void request(BusTransfer* transfer, std::coroutine_handle<> sender);
  void schedule_arbitration();
  void arbitrate();

  EventKernel& kernel_;
  Cycles arbitration_;
  Cycles latency_;
  const CostProfile& profile_;
  std::function<void(const BusTransfer&)> handler_;
  std::vector<Request> pending_;
  std::uint64_t next_sequence_ = 0;
  bool busy_ = false;
  bool arbitration_scheduled_ = false;
  std::vector<BusTransfer> log_;
};

}  // namespace capsim::sim
