#include "machine/costs/cost_terms.h"

#include "kernel/cycles.h"

#include <fmt/core.h>

#include <stdexcept>
#include <string_view>

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

const char* profile_section(CostPayer p) {
  switch (p) {
    case CostPayer::Cell: return "cell_costs_us";
    case CostPayer::Host: return "host_costs_us";
    case CostPayer::CellVoxels: return "cell_voxel_costs_us";
  }
  return "";
}

CostTerm cell_voxel_twin(CostTerm host_term) {
  const CostTermInfo& h = info(host_term);
  if (h.payer != CostPayer::Host) throw std::logic_error(fmt::format("{} is not a host term", profile_key(host_term)));
  for (const CostTermInfo& t : kCostTerms)
    if (t.payer == CostPayer::CellVoxels && std::string_view(t.key) == h.key) return t.term;
  throw std::logic_error(fmt::format("{} has no term in {}", profile_key(host_term),
                                     profile_section(CostPayer::CellVoxels)));
}

std::string profile_key(CostTerm t) {
  const CostTermInfo& i = info(t);
  return fmt::format("{}.{}", profile_section(i.payer), i.key);
}

}  // namespace capsim::sim
