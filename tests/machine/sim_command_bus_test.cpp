// The command bus: transfer cycles and the arbitration policy.

#include "machine/parts/command_bus.h"
#include "support/sim_test_profile.h"

#include <gtest/gtest.h>

#include <vector>

namespace capsim::sim {
namespace {

Process send_after(EventKernel& k, CommandBus& bus, Endpoint who, Cycles wait, std::uint64_t bytes,
                   std::vector<BusTransfer>& done) {
  co_await k.delay(wait);
  done.push_back(co_await bus.transfer(who, kHost, bytes, BusMessage::Done));
}

TEST(CommandBus, TransferTakesArbitrationPlusBytesOverBandwidthPlusLatency) {
  const CostProfile profile = testing::round_number_profile();
  EventKernel k;
  CommandBus bus(k, profile);
  std::vector<BusTransfer> done;
  k.spawn(send_after(k, bus, 4, Cycles(7), 25, done));
  k.run();
  ASSERT_EQ(done.size(), 1u);
  // 3 arbitration + 25 bytes x 10 cycles + 2 latency.
  EXPECT_EQ(bus.transfer_cycles(25), Cycles(255));
  EXPECT_EQ(done[0].requested, Cycles(7));
  EXPECT_EQ(done[0].granted, Cycles(7));
  EXPECT_EQ(done[0].released, Cycles(7 + 3 + 250));
  EXPECT_EQ(done[0].delivered, Cycles(7 + 255));
  EXPECT_EQ(k.now(), Cycles(262));
}

TEST(CommandBus, DataCyclesRoundUp) {
  CostProfile profile = testing::round_number_profile();
  profile.bus.bytes_per_second = 300'000;  // 3.33 cycles per byte
  EXPECT_EQ(profile.bus_data_cycles(3), Cycles(10));
  EXPECT_EQ(profile.bus_data_cycles(4), Cycles(14));
  EXPECT_EQ(profile.bus_data_cycles(0), Cycles(0));
}

TEST(CommandBus, SameCycleRequestsAreGrantedHostFirstThenLowestCell) {
  const CostProfile profile = testing::round_number_profile();
  EventKernel k;
  CommandBus bus(k, profile);
  std::vector<BusTransfer> done;
  // Spawned in an order unlike the grant order.
  for (Endpoint who : {5, 2, 9}) k.spawn(send_after(k, bus, who, Cycles(0), 1, done));
  bool host_done = false;
  k.spawn([](EventKernel&, CommandBus& b, bool& flag) -> Process {
    co_await b.transfer(kHost, 3, 1, BusMessage::Start);
    flag = true;
  }(k, bus, host_done));
  k.run();
  ASSERT_TRUE(host_done);
  const std::vector<BusTransfer>& log = bus.log();
  ASSERT_EQ(log.size(), 4u);
  EXPECT_EQ(log[0].message, BusMessage::Start);
  EXPECT_EQ(log[1].message, BusMessage::Done);
  std::vector<Endpoint> order;
  for (const BusTransfer& t : log) order.push_back(t.sender);
  EXPECT_EQ(order, (std::vector<Endpoint>{kHost, 2, 5, 9}));
  // Each waits for the previous one to leave the bus (13 cycles of occupancy).
  for (std::size_t i = 0; i < log.size(); ++i) {
    EXPECT_EQ(log[i].requested, Cycles(0));
    EXPECT_EQ(log[i].granted, Cycles(13 * i));
    EXPECT_EQ(log[i].delivered, Cycles(13 * i + 15));
  }
}

TEST(CommandBus, EarlierRequestWinsOverLowerId) {
  const CostProfile profile = testing::round_number_profile();
  EventKernel k;
  CommandBus bus(k, profile);
  std::vector<BusTransfer> done;
  k.spawn(send_after(k, bus, 0, Cycles(0), 10, done));  // busy 0 .. 103
  k.spawn(send_after(k, bus, 7, Cycles(50), 1, done));  // asks first
  k.spawn(send_after(k, bus, 1, Cycles(60), 1, done));  // lower id, asks later
  k.run();
  const std::vector<BusTransfer>& log = bus.log();
  ASSERT_EQ(log.size(), 3u);
  EXPECT_EQ(log[1].sender, 7);
  EXPECT_EQ(log[1].granted, Cycles(103));
  EXPECT_EQ(log[2].sender, 1);
  EXPECT_EQ(log[2].granted, Cycles(116));
}

TEST(CommandBus, BroadcastIsOneTransferSeenByTheDeliveryHandlerOnce) {
  const CostProfile profile = testing::round_number_profile();
  EventKernel k;
  CommandBus bus(k, profile);
  int deliveries = 0;
  bus.on_delivery([&](const BusTransfer& t) {
    EXPECT_EQ(t.receiver, kAllCells);
    EXPECT_EQ(k.now(), Cycles(3 + 1000 + 2));
    ++deliveries;
  });
  k.spawn([](CommandBus& b) -> Process { co_await b.transfer(kHost, kAllCells, 100, BusMessage::Scene); }(bus));
  k.run();
  EXPECT_EQ(deliveries, 1);
}

}  // namespace
}  // namespace capsim::sim
