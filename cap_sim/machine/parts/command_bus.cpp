#include "machine/parts/command_bus.h"

#include <fmt/core.h>

#include <algorithm>
#include <stdexcept>

namespace capsim::sim {

CommandBus::CommandBus(EventKernel& kernel, const CostProfile& profile)
    : kernel_(kernel),
      arbitration_(profile.bus.arbitration),
      latency_(profile.bus.latency),
      profile_(profile) {}

Cycles CommandBus::transfer_cycles(std::uint64_t bytes) const {
  return arbitration_ + profile_.bus_data_cycles(bytes) + latency_;
}

CommandBus::TransferAwaiter CommandBus::transfer(Endpoint sender, Endpoint receiver, std::uint64_t bytes,
                                                 BusMessage message, int tile, int frame) {
  if (sender == kAllCells || sender == receiver)
    throw std::logic_error("bus transfer needs a sender and a different receiver");
  BusTransfer t;
  t.message = message;
  t.sender = sender;
  t.receiver = receiver;
  t.bytes = bytes;
  t.tile = tile;
  t.frame = frame;
  return TransferAwaiter{*this, std::move(t)};
}

void CommandBus::request(BusTransfer* transfer, std::coroutine_handle<> sender) {
  transfer->requested = kernel_.now();
  pending_.push_back(Request{transfer, sender, next_sequence_++});
  schedule_arbitration();
}

void CommandBus::schedule_arbitration() {
  if (busy_ || arbitration_scheduled_ || pending_.empty()) return;
  arbitration_scheduled_ = true;
  kernel_.schedule(kernel_.now(), EventPriority::Arbitration, [this] {
    arbitration_scheduled_ = false;
    arbitrate();
  });
}

void CommandBus::arbitrate() {
  if (busy_ || pending_.empty()) return;
  const auto winner = std::min_element(pending_.begin(), pending_.end(), [](const Request& a, const Request& b) {
    if (a.transfer->requested != b.transfer->requested)
      return a.transfer->requested < b.transfer->requested;
    if (a.transfer->sender != b.transfer->sender) return a.transfer->sender < b.transfer->sender;
    return a.sequence < b.sequence;
  });
  const Request r = *winner;
  pending_.erase(winner);

  BusTransfer& t = *r.transfer;
  busy_ = true;
  t.granted = kernel_.now();
  try {
    t.released = t.granted + arbitration_ + profile_.bus_data_cycles(t.bytes);
    t.delivered = t.released + latency_;
  } catch (const CycleOverflow& e) {
    throw e.inside(fmt::format("bus transfer \"{}\" granted at cycle {}", to_string(t.message), t.granted.count()));
  }

  kernel_.schedule(t.released, EventPriority::Arbitration, [this] {
    busy_ = false;
    arbitrate();
  });
  kernel_.schedule(t.delivered, EventPriority::Delivery, [this, r] {
    log_.push_back(*r.transfer);
    if (handler_) handler_(*r.transfer);
    kernel_.resume_at(kernel_.now(), r.sender);
  });
}

}  // namespace capsim::sim
