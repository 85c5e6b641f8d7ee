#pragma once
// The cost profiles compiled into the binary: the JSON text of every file in
// cap_sim/profiles/, embedded at build time (cap_sim/machine/costs/embed_profiles.cmake), so
// capsim works from any directory.

#include <span>
#include <string_view>

namespace capsim::sim {

struct BuiltinProfile {
  std::string_view name;  // the file name without ".json"
  std::string_view json;
};

// Sorted by name.
std::span<const BuiltinProfile> builtin_profiles();

}  // namespace capsim::sim
