#pragma once
// How much memory a run may take: the least of what the machine and the limits
// on this process leave. A command estimates what its image buffers need
// before it starts and refuses a run that would not fit, instead of failing
// part-way with the memory gone.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace capsim {

struct MemoryLimit {
  std::uint64_t bytes = 0;
  // What sets it, as messages go on after "more than the 2.0 GiB ":
  // "left under the address-space limit (ulimit -v)".
  std::string source;
};

// The least of the limits; nullopt if there are none.
std::optional<MemoryLimit> tightest(const std::vector<MemoryLimit>& limits);

// The limits on this process now, each less what is already in use where the
// limit counts it:
// - MemAvailable of /proc/meminfo: physical memory that can be had without swapping;
// - RLIMIT_AS (ulimit -v) less the process's address space, and RLIMIT_DATA
//   (ulimit -d) less its data segment and private mappings, when set;
// - the memory limit of the process's cgroup (v2 memory.max, or v1
//   memory.limit_in_bytes) less its usage, when set.
std::vector<MemoryLimit> process_memory_limits();

// MemAvailable of /proc/meminfo text, in bytes.
std::optional<std::uint64_t> meminfo_available(std::string_view meminfo);

// The cgroup v2 path ("0::/PATH") of /proc/self/cgroup text.
std::optional<std::string> cgroup_v2_path(std::string_view self_cgroup);

// The memory cgroup v1 path ("N:memory:/PATH" or "N:...,memory,...:/PATH").
std::optional<std::string> cgroup_v1_memory_path(std::string_view self_cgroup);

// "15.0 GiB", "512.0 MiB", "900 bytes": one decimal, binary units.
std::string format_bytes(std::uint64_t bytes);

}  // namespace capsim
