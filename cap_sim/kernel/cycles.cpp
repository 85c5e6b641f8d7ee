#include "kernel/cycles.h"

#include <fmt/core.h>

#include <ostream>

namespace capsim::sim {

namespace {

std::string overflow_sentence(std::string_view quantity) {
  return fmt::format("the simulated time exceeds the 64-bit cycle counter ({} cycles): {}",
                     Cycles::kMax, quantity);
}

}  // namespace

CycleOverflow::CycleOverflow(std::string quantity)
    : CycleOverflow(overflow_sentence(quantity), quantity) {}

CycleOverflow::CycleOverflow(std::string what, std::string quantity)
    : std::overflow_error(std::move(what)), quantity_(std::move(quantity)) {}

CycleOverflow CycleOverflow::inside(std::string_view where) const {
  return CycleOverflow(fmt::format("{}: {}", where, quantity_));
}

CycleOverflow CycleOverflow::of_profile(std::string_view profile_source,
                                        std::uint64_t clock_hz) const {
  return CycleOverflow(
      fmt::format("cost profile {}: the simulated time exceeds the 64-bit cycle counter ({} "
                  "cycles, {:.0f} s at clock_hz {}): {}",
                  profile_source, Cycles::kMax, Cycles(Cycles::kMax).seconds(clock_hz), clock_hz,
                  quantity_),
      quantity_);
}

namespace detail {

void throw_sum_overflow(std::uint64_t a, std::uint64_t b) {
  throw CycleOverflow(fmt::format("{} + {} cycles", a, b));
}

void throw_product_overflow(std::uint64_t n, std::uint64_t c) {
  throw CycleOverflow(fmt::format("{} x {} cycles", n, c));
}

void throw_negative_duration(std::uint64_t a, std::uint64_t b) {
  throw std::logic_error(fmt::format("negative duration: {} - {} cycles", a, b));
}

}  // namespace detail

std::ostream& operator<<(std::ostream& out, Cycles c) { return out << c.count() << " cycles"; }

}  // namespace capsim::sim
