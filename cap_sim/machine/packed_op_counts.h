#pragma once
// The operation counts of many items (a screen's pixels, or its corner
// samples), 32 bits a count. A screen traced ahead (ScreenTrace) is added into
// cells once per run laid out on it, and those additions read every item's
// counts: packed, they are half the bytes of OpCounts to read (and to keep).
// An item with a count that does not fit 32 bits is kept whole on the side,
// so every count read back is the one set, to the bit.

#include "capsim/trace/op_counts.h"

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

namespace capsim::sim {

class PackedOpCounts {
 public:
  PackedOpCounts() = default;
  explicit PackedOpCounts(std::size_t items)
      : counts_(items * kFields, 0), whole_mutex_(std::make_unique<std::mutex>()) {}

  std::size_t size() const { return counts_.size() / kFields; }

  // Item i's counts. Safe from several threads at once for different items.
  void set(std::size_t i, const OpCounts& ops);

  // sum += item i's counts: the machine's inner loop, inline.
  void add_to(std::size_t i, OpCounts& sum) const {
    const std::uint32_t* item = counts_.data() + i * kFields;
    if (item[0] == kKeptWhole) [[unlikely]] {
      sum += whole_.at(i);
      return;
    }
    // Count by count in place, through the sum's bytes (copying the whole
    // sum out and back costs more than the additions).
    auto* bytes = reinterpret_cast<unsigned char*>(&sum);
    for (std::size_t k = 0; k < kFields; ++k) {
      std::uint64_t n;
      std::memcpy(&n, bytes + k * sizeof n, sizeof n);
      n += item[k];
      std::memcpy(bytes + k * sizeof n, &n, sizeof n);
    }
  }

  OpCounts at(std::size_t i) const {
    OpCounts ops;
    add_to(i, ops);
    return ops;
  }

  // How many items are kept whole (a count of 2^32 - 1 or more).
  std::size_t kept_whole() const { return whole_.size(); }

 private:
  static constexpr std::size_t kFields = sizeof(OpCounts) / sizeof(std::uint64_t);
  using Fields = std::array<std::uint64_t, kFields>;
  static_assert(sizeof(Fields) == sizeof(OpCounts), "OpCounts is a run of 64-bit counts and nothing else");
  // In an item's first count: the item is kept whole, in whole_.
  static constexpr std::uint32_t kKeptWhole = UINT32_MAX;

  std::vector<std::uint32_t> counts_;  // kFields per item, in OpCounts' order
  std::map<std::size_t, OpCounts> whole_;
  std::unique_ptr<std::mutex> whole_mutex_;  // set() from several threads may add to whole_
};

}  // namespace capsim::sim
