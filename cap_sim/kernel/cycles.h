#pragma once
// Simulated time. Every duration and every instant of the machine is a whole
// number of clock cycles, so every simulated figure is exactly reproducible.
// A distinct type (not a bare integer) keeps cycles from being mixed up with
// byte counts, pixel counts or seconds.
//
// The arithmetic is checked: a sum or product beyond 2^64 - 1 cycles throws
// CycleOverflow rather than wrapping, so a report never shows a wrapped count.

#include <compare>
#include <cstdint>
#include <iosfwd>
#include <stdexcept>
#include <string>
#include <string_view>

namespace capsim::sim {

// Simulated time that does not fit a 64-bit cycle count. quantity() names what
// overflowed ("cell [0,3]'s work adds up to ... cycles"); what() is the whole
// sentence, with the profile whose costs led there once of_profile() added it.
class CycleOverflow : public std::overflow_error {
 public:
  explicit CycleOverflow(std::string quantity);

  const std::string& quantity() const { return quantity_; }
  // The same overflow, located: "<where>: <quantity>".
  [[nodiscard]] CycleOverflow inside(std::string_view where) const;
  // The same overflow, blamed on a cost profile (its source: a built-in name or
  // a path), with the limit in seconds at the profile's clock.
  [[nodiscard]] CycleOverflow of_profile(std::string_view profile_source,
                                         std::uint64_t clock_hz) const;

 private:
  CycleOverflow(std::string what, std::string quantity);
  std::string quantity_;
};

namespace detail {
[[noreturn]] void throw_sum_overflow(std::uint64_t a, std::uint64_t b);
[[noreturn]] void throw_product_overflow(std::uint64_t n, std::uint64_t c);
[[noreturn]] void throw_negative_duration(std::uint64_t a, std::uint64_t b);
}  // namespace detail

class Cycles {
 public:
  static constexpr std::uint64_t kMax = UINT64_MAX;

  constexpr Cycles() = default;
  constexpr explicit Cycles(std::uint64_t count) : count_(count) {}

  constexpr std::uint64_t count() const { return count_; }
  // The duration in seconds at the given clock rate.
  constexpr double seconds(std::uint64_t clock_hz) const {
    return static_cast<double>(count_) / static_cast<double>(clock_hz);
  }

  // Throws CycleOverflow when the sum exceeds kMax.
  constexpr Cycles& operator+=(Cycles o) { return *this = *this + o; }
  friend constexpr Cycles operator+(Cycles a, Cycles b) {
    std::uint64_t sum = 0;
    if (__builtin_add_overflow(a.count_, b.count_, &sum)) detail::throw_sum_overflow(a.count_, b.count_);
    return Cycles(sum);
  }
  // Durations are never negative: throws std::logic_error when a < b.
  friend constexpr Cycles operator-(Cycles a, Cycles b) {
    if (a.count_ < b.count_) detail::throw_negative_duration(a.count_, b.count_);
    return Cycles(a.count_ - b.count_);
  }
  // n repetitions of an operation that costs c cycles. Throws CycleOverflow when
  // the product exceeds kMax.
  friend constexpr Cycles operator*(std::uint64_t n, Cycles c) {
    std::uint64_t product = 0;
    if (__builtin_mul_overflow(n, c.count_, &product)) detail::throw_product_overflow(n, c.count_);
    return Cycles(product);
  }
  friend constexpr auto operator<=>(Cycles, Cycles) = default;

 private:
  std::uint64_t count_ = 0;
};

// "1234 cycles": how test failures and logs print a count (not its bytes).
std::ostream& operator<<(std::ostream& out, Cycles c);

}  // namespace capsim::sim
