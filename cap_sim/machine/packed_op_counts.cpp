#include "machine/packed_op_counts.h"

#include <algorithm>

namespace capsim::sim {

void PackedOpCounts::set(std::size_t i, const OpCounts& ops) {
  const Fields wide = std::bit_cast<Fields>(ops);
  std::uint32_t* item = counts_.data() + i * kFields;
  if (std::all_of(wide.begin(), wide.end(), [](std::uint64_t n) { return n < kKeptWhole; })) {
    std::copy(wide.begin(), wide.end(), item);
    return;
  }
  item[0] = kKeptWhole;
  const std::lock_guard lock(*whole_mutex_);
  whole_[i] = ops;
}

}  // namespace capsim::sim
