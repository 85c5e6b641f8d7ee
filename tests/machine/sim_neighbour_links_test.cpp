// The neighbour links: routing (X first, then Y), hop timing, store-and-forward,
// and the synthetic exchange of the antialiasing phase (§3.3): every cell sends a
// message to its right, lower and lower-right neighbours.

#include "machine/parts/neighbour_links.h"
#include "support/sim_test_profile.h"

#include <gtest/gtest.h>

#include <map>
#include <tuple>

namespace capsim::sim {
namespace {

// The links carry corner packets; here each packet's index tells the messages
// apart.
LinkPacket packet(std::size_t index) { return {LinkKind::Corners, ExchangeStep::Vertical, index}; }

TEST(NeighbourLinks, RoutesAlongTheRowFirstThenTheColumn) {
  const CostProfile profile = testing::round_number_profile();
  EventKernel k;
  NeighbourLinks links(k, {3, 4}, profile);
  EXPECT_EQ(links.route(0, 11), (std::vector<CellId>{1, 2, 3, 7, 11}));
  EXPECT_EQ(links.route(11, 0), (std::vector<CellId>{10, 9, 8, 4, 0}));
  EXPECT_EQ(links.route(5, 6), (std::vector<CellId>{6}));
}

TEST(NeighbourLinks, StoreAndForwardPaysEveryHopInFull) {
  const CostProfile profile = testing::round_number_profile();
  EventKernel k;
  NeighbourLinks links(k, {3, 4}, profile);
  // 4 bytes: 32 cycles on each link + 5 latency per hop.
  EXPECT_EQ(links.hop_cycles(4), Cycles(37));
  Cycles sender_free;
  k.spawn([](EventKernel& k, NeighbourLinks& l, Cycles& free) -> Process {
    co_await l.send(0, 11, 4, packet(0));
    free = k.now();
  }(k, links, sender_free));
  k.run();
  ASSERT_EQ(links.log().size(), 1u);
  EXPECT_EQ(sender_free, Cycles(32));
  EXPECT_EQ(links.log()[0].hops, 5);
  EXPECT_EQ(links.log()[0].arrived, Cycles(5 * 37));
}

enum Neighbour : std::size_t { kRight, kLower, kLowerRight };

Process exchange(NeighbourLinks& links, CellGrid grid, CellId self) {
  const auto right = grid.neighbour(self, Direction::East);
  const auto lower = grid.neighbour(self, Direction::South);
  if (right) co_await links.send(self, *right, 4, packet(kRight));
  if (lower) co_await links.send(self, *lower, 4, packet(kLower));
  if (right && lower) co_await links.send(self, *grid.neighbour(*right, Direction::South), 4, packet(kLowerRight));
}

TEST(NeighbourLinks, SyntheticExchangeArrivesOnTheExpectedCycles) {
  const CostProfile profile = testing::round_number_profile();
  const CellGrid grid{3, 4};
  EventKernel k;
  NeighbourLinks links(k, grid, profile);
  for (CellId c = 0; c < grid.cell_count(); ++c) k.spawn(exchange(links, grid, c));
  k.run();
  ASSERT_TRUE(k.all_processes_finished());

  // S = 32 cycles on a link, L = 5 latency. A cell's sends follow one another:
  //   right:       E link [0, S)                      -> arrives S + L        =  37
  //   lower:       S link [S, 2S) (after `right`)     -> arrives 2S + L       =  69
  //                (a cell of the last column has no right: [0, S) -> 37)
  //   lower-right: E link [2S, 3S), in the right cell at 3S + L; its S link is
  //                free since 2S, [3S + L, 4S + L)    -> arrives 4S + 2L      = 138
  std::map<std::tuple<CellId, CellId, std::size_t>, std::uint64_t> arrivals;
  for (const LinkMessage& m : links.log()) arrivals[{m.from, m.to, m.packet.index}] = m.arrived.count();

  std::size_t expected_messages = 0;
  for (CellId c = 0; c < grid.cell_count(); ++c) {
    const CellPosition p = grid.position(c);
    const bool has_right = p.col + 1 < grid.cols;
    const bool has_lower = p.row + 1 < grid.rows;
    if (has_right) {
      EXPECT_EQ((arrivals[{c, c + 1, kRight}]), 37u) << "cell " << c;
      ++expected_messages;
    }
    if (has_lower) {
      EXPECT_EQ((arrivals[{c, c + grid.cols, kLower}]), has_right ? 69u : 37u) << "cell " << c;
      ++expected_messages;
    }
    if (has_right && has_lower) {
      EXPECT_EQ((arrivals[{c, c + grid.cols + 1, kLowerRight}]), 138u) << "cell " << c;
      ++expected_messages;
    }
  }
  EXPECT_EQ(links.log().size(), expected_messages);
  for (const LinkMessage& m : links.log())
    EXPECT_EQ(m.hops, m.packet.index == kLowerRight ? 2 : 1);
}

TEST(NeighbourLinks, MessagesOnOneLinkQueueInOrder) {
  const CostProfile profile = testing::round_number_profile();
  EventKernel k;
  NeighbourLinks links(k, {1, 2}, profile);
  // Two cells' worth of traffic on one link: cell 0 sends twice without waiting
  // in between; a second process of cell 0 sends a third at cycle 10.
  k.spawn([](NeighbourLinks& l) -> Process {
    co_await l.send(0, 1, 1, packet(0));
    co_await l.send(0, 1, 1, packet(1));
  }(links));
  k.spawn([](EventKernel& k, NeighbourLinks& l) -> Process {
    co_await k.delay(Cycles(10));
    co_await l.send(0, 1, 1, packet(2));
  }(k, links));
  k.run();
  ASSERT_EQ(links.log().size(), 3u);
  // a: [0, 8) -> 13; c asks at 10, while b holds the link [8, 16); c: [16, 24) -> 29.
  EXPECT_EQ(links.log()[0].packet, packet(0));
  EXPECT_EQ(links.log()[0].arrived, Cycles(13));
  EXPECT_EQ(links.log()[1].packet, packet(1));
  EXPECT_EQ(links.log()[1].arrived, Cycles(21));
  EXPECT_EQ(links.log()[2].packet, packet(2));
  EXPECT_EQ(links.log()[2].arrived, Cycles(29));
}

}  // namespace
}  // namespace capsim::sim
