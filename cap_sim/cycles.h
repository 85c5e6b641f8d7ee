#pragma once
// Simulated time. Every duration and every instant of the machine is a whole
// number of clock cycles, so every simulated figure is exactly reproducible.
// A distinct type (not a bare integer) keeps cycles from being mixed up with
// byte counts, pixel counts or seconds.

#include <compare>
#include <cstdint>

namespace capsim::sim {

class Cycles {
 public:
  constexpr Cycles() = default;
  constexpr explicit Cycles(std::uint64_t count) : count_(count) {}

  constexpr std::uint64_t count() const { return count_; }
  // The duration in seconds at the given clock rate.
  constexpr double seconds(std::uint64_t clock_hz) const {
    return static_cast<double>(count_) / static_cast<double>(clock_hz);
  }

  constexpr Cycles& operator+=(Cycles o) {
    count_ += o.count_;
    return *this;
  }
  friend constexpr Cycles operator+(Cycles a, Cycles b) { return Cycles(a.count_ + b.count_); }
  // Precondition: a >= b (durations are never negative).
  friend constexpr Cycles operator-(Cycles a, Cycles b) { return Cycles(a.count_ - b.count_); }
  // n repetitions of an operation that costs c cycles.
  friend constexpr Cycles operator*(std::uint64_t n, Cycles c) { return Cycles(n * c.count_); }
  friend constexpr auto operator<=>(Cycles, Cycles) = default;

 private:
  std::uint64_t count_ = 0;
};

}  // namespace capsim::sim
