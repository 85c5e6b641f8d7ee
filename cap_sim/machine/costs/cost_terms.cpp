#include "machine/costs/cost_terms.h"

#include "kernel/cycles.h"

#include <fmt/core.h>

namespace capsim::sim {

const char* to_string(CostCategory c) { return kCostCategoryTable[static_cast<int>(c)].name; }

const char* json_key(CostCategory c) { return kCostCategoryTable[static_cast<int>(c)].json_key; }

std::uint64_t voxels_visited(const OpCounts& ops) {
  std::uint64_t n = 0;
  if (__builtin_add_overflow(ops.dda_setups, ops.dda_steps, &n))
    throw CycleOverflow(fmt::format("{} 3DDDA set-ups + {} steps voxels visited", ops.dda_setups, ops.dda_steps));
  return n;
}

const CostTermInfo& info(CostTerm t) { return kCostTerms[static_cast<int>(t)]; }

const char* profile_section(CostPayer p) { return p == CostPayer::Cell ? "cell_costs_us" : "host_costs_us"; }

std::string profile_key(CostTerm t) {
  const CostTermInfo& i = info(t);
  return fmt::format("{}.{}", profile_section(i.payer), i.key);
}

}  // namespace capsim::sim
