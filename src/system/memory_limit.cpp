#include "capsim/system/memory_limit.h"

#include <fmt/core.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <fstream>
#include <sstream>

namespace capsim {

namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::optional<std::uint64_t> parse_u64(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.remove_suffix(1);
  std::uint64_t v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size() || text.empty()) return std::nullopt;
  return v;
}

std::vector<std::string_view> lines(std::string_view text) {
  std::vector<std::string_view> out;
  while (!text.empty()) {
    const auto nl = text.find('\n');
    out.push_back(text.substr(0, nl));
    if (nl == std::string_view::npos) break;
    text.remove_prefix(nl + 1);
  }
  return out;
}

// A limit file's value less a usage file's; nothing for "max" or unreadable files.
void add_cgroup_limit(std::vector<MemoryLimit>& limits, const std::string& limit_file,
                      const std::string& usage_file, const std::string& source) {
  const std::optional<std::uint64_t> limit = parse_u64(read_text(limit_file));
  if (!limit) return;  // absent, or "max"
  const std::uint64_t used = parse_u64(read_text(usage_file)).value_or(0);
  limits.push_back({*limit > used ? *limit - used : 0, source});
}

// RLIMIT_AS or RLIMIT_DATA less what the process already has of it.
void add_rlimit(std::vector<MemoryLimit>& limits, int resource, std::uint64_t in_use, const std::string& source) {
  rlimit r{};
  if (getrlimit(resource, &r) != 0 || r.rlim_cur == RLIM_INFINITY) return;
  const auto limit = static_cast<std::uint64_t>(r.rlim_cur);
  limits.push_back({limit > in_use ? limit - in_use : 0, source});
}

}  // namespace

std::optional<MemoryLimit> tightest(const std::vector<MemoryLimit>& limits) {
  if (limits.empty()) return std::nullopt;
  return *std::min_element(limits.begin(), limits.end(),
                           [](const MemoryLimit& a, const MemoryLimit& b) { return a.bytes < b.bytes; });
}

std::optional<std::uint64_t> meminfo_available(std::string_view meminfo) {
  for (std::string_view line : lines(meminfo)) {
    if (line.rfind("MemAvailable:", 0) != 0) continue;
    line.remove_prefix(13);
    const auto unit = line.find("kB");
    const std::optional<std::uint64_t> kib = parse_u64(line.substr(0, unit));
    if (!kib || unit == std::string_view::npos) return std::nullopt;
    return *kib * 1024;
  }
  return std::nullopt;
}

std::optional<std::string> cgroup_v2_path(std::string_view self_cgroup) {
  for (std::string_view line : lines(self_cgroup))
    if (line.rfind("0::", 0) == 0) return std::string(line.substr(3));
  return std::nullopt;
}

std::optional<std::string> cgroup_v1_memory_path(std::string_view self_cgroup) {
  for (std::string_view line : lines(self_cgroup)) {
    const auto first = line.find(':');
    const auto second = first == std::string_view::npos ? first : line.find(':', first + 1);
    if (second == std::string_view::npos) continue;
    const std::string controllers = fmt::format(",{},", line.substr(first + 1, second - first - 1));
    if (controllers.find(",memory,") != std::string::npos) return std::string(line.substr(second + 1));
  }
  return std::nullopt;
}

std::vector<MemoryLimit> process_memory_limits() {
  std::vector<MemoryLimit> limits;
  if (const auto available = meminfo_available(read_text("/proc/meminfo")))
    limits.push_back({*available, "of memory available (MemAvailable in /proc/meminfo)"});

  // /proc/self/statm: sizes in pages; the first is the address space, the
  // sixth the data segment, stack and private mappings.
  std::istringstream statm(read_text("/proc/self/statm"));
  std::uint64_t size = 0, resident = 0, shared = 0, text = 0, library = 0, data = 0;
  statm >> size >> resident >> shared >> text >> library >> data;
  const auto page = static_cast<std::uint64_t>(sysconf(_SC_PAGESIZE));
  add_rlimit(limits, RLIMIT_AS, size * page, "left under the address-space limit (ulimit -v)");
  add_rlimit(limits, RLIMIT_DATA, data * page, "left under the data-size limit (ulimit -d)");

  const std::string self_cgroup = read_text("/proc/self/cgroup");
  if (const auto path = cgroup_v2_path(self_cgroup)) {
    const std::string dir = fmt::format("/sys/fs/cgroup{}", *path == "/" ? "" : *path);
    add_cgroup_limit(limits, dir + "/memory.max", dir + "/memory.current",
                     "left under the cgroup's memory limit (memory.max)");
  }
  if (const auto path = cgroup_v1_memory_path(self_cgroup)) {
    // Inside a container the hierarchy is often mounted at the process's own
    // cgroup, so its path does not exist under the mount: then read the root.
    std::string dir = fmt::format("/sys/fs/cgroup/memory{}", *path == "/" ? "" : *path);
    if (read_text(dir + "/memory.limit_in_bytes").empty()) dir = "/sys/fs/cgroup/memory";
    add_cgroup_limit(limits, dir + "/memory.limit_in_bytes", dir + "/memory.usage_in_bytes",
                     "left under the cgroup's memory limit (memory.limit_in_bytes)");
  }
  return limits;
}

std::string format_bytes(std::uint64_t bytes) {
  constexpr const char* kUnits[] = {"KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  if (bytes < 1024) return fmt::format("{} {}", bytes, bytes == 1 ? "byte" : "bytes");
  double value = static_cast<double>(bytes) / 1024;
  int unit = 0;
  while (value >= 1024 && unit < 5) {
    value /= 1024;
    ++unit;
  }
  return fmt::format("{:.1f} {}", value, kUnits[unit]);
}

}  // namespace capsim
