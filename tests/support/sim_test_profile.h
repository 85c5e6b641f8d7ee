#pragma once
// A cost profile with round numbers for the machine-part tests: 1 MHz clock,
// so one cycle is one microsecond.

#include "machine/costs/cost_profile.h"

namespace capsim::sim::testing {

inline CostProfile round_number_profile() {
  CostProfile p;
  p.name = "test";
  p.clock_hz = 1'000'000;
  p.bus.bytes_per_second = 100'000;  // 10 cycles per byte
  p.bus.arbitration = Cycles(3);
  p.bus.latency = Cycles(2);
  p.link.bits_per_second = 1'000'000;  // 8 cycles per byte
  p.link.latency = Cycles(5);
  p.cell_memory_bytes = 1 << 20;
  p.program_bytes = 1000;
  p.video_memory_bytes = 1 << 20;
  return p;
}

}  // namespace capsim::sim::testing
