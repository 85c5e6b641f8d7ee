// Simulated time never wraps: Cycles arithmetic at the edge of 64 bits, the
// overflow's message, and the event kernel refusing an event beyond the last
// countable cycle.

#include "kernel/cycles.h"
#include "kernel/event_kernel.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace capsim::sim {
namespace {

constexpr std::uint64_t kMax = Cycles::kMax;

std::string overflow_message(const auto& operation) {
  try {
    operation();
  } catch (const CycleOverflow& e) {
    return e.what();
  }
  ADD_FAILURE() << "no CycleOverflow";
  return {};
}

TEST(Cycles, SumsUpToTheLastCountableCycleAreExact) {
  EXPECT_EQ(Cycles(kMax - 1) + Cycles(1), Cycles(kMax));
  Cycles c(kMax - 7);
  c += Cycles(7);
  EXPECT_EQ(c, Cycles(kMax));
}

TEST(Cycles, ASumBeyondTheLastCycleThrowsAndNamesBothTerms) {
  EXPECT_EQ(overflow_message([] { return Cycles(kMax) + Cycles(1); }),
            "the simulated time exceeds the 64-bit cycle counter (18446744073709551615 cycles): "
            "18446744073709551615 + 1 cycles");
  Cycles c(kMax - 2);
  EXPECT_THROW(c += Cycles(3), CycleOverflow);
  EXPECT_EQ(c, Cycles(kMax - 2));  // unchanged
}

TEST(Cycles, ProductsUpToTheLastCycleAreExactAndBeyondThrow) {
  const std::uint64_t two_to_32 = std::uint64_t{1} << 32;
  EXPECT_EQ(two_to_32 * Cycles(two_to_32 - 1), Cycles(kMax - two_to_32 + 1));
  EXPECT_EQ(1 * Cycles(kMax), Cycles(kMax));
  EXPECT_EQ(0 * Cycles(kMax), Cycles(0));
  const std::string m = overflow_message([&] { return two_to_32 * Cycles(two_to_32); });
  EXPECT_NE(m.find("4294967296 x 4294967296 cycles"), std::string::npos) << m;
  EXPECT_THROW(2 * Cycles(kMax / 2 + 1), CycleOverflow);
}

TEST(Cycles, ANegativeDurationIsALogicError) {
  EXPECT_EQ(Cycles(5) - Cycles(5), Cycles(0));
  EXPECT_THROW(Cycles(4) - Cycles(5), std::logic_error);
}

TEST(CycleOverflow, LocatedAndBlamedOnAProfile) {
  const CycleOverflow e = CycleOverflow("3 x 7 cycles").inside("pixel (1, 2)").inside("cell[0,1]");
  EXPECT_EQ(e.quantity(), "cell[0,1]: pixel (1, 2): 3 x 7 cycles");
  EXPECT_EQ(std::string(e.of_profile("slow.json", 8'000'000).what()),
            "cost profile slow.json: the simulated time exceeds the 64-bit cycle counter "
            "(18446744073709551615 cycles, 2305843009214 s at clock_hz 8000000): "
            "cell[0,1]: pixel (1, 2): 3 x 7 cycles");
}

TEST(EventKernel, AnEventBeyondTheLastCycleIsAnOverflowNotThePast) {
  EventKernel k;
  std::string message;
  k.schedule(Cycles(kMax - 5), EventPriority::Resume, [&] {
    message = overflow_message([&] { k.schedule_after(Cycles(6), EventPriority::Resume, [] {}); });
    k.schedule_after(Cycles(5), EventPriority::Resume, [] {});  // the last cycle is fine
  });
  k.run();
  EXPECT_NE(message.find("an event 6 cycles after cycle 18446744073709551610"), std::string::npos)
      << message;
  EXPECT_EQ(k.now(), Cycles(kMax));
}

Process sleep_twice(EventKernel& k, Cycles first, Cycles second) {
  co_await k.delay(first);
  co_await k.delay(second);
}

TEST(EventKernel, AProcessDelayedBeyondTheLastCycleFailsTheRun) {
  EventKernel k;
  k.spawn(sleep_twice(k, Cycles(kMax), Cycles(1)));
  const std::string m = overflow_message([&] { k.run(); });
  EXPECT_NE(m.find("an event 1 cycles after cycle 18446744073709551615"), std::string::npos) << m;
}

}  // namespace
}  // namespace capsim::sim
