#include "machine/costs/cost_profile.h"

#include "machine/costs/builtin_profiles.h"
#include "capsim/system/sha256.h"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace capsim::sim {

namespace {

using nlohmann::json;

constexpr double kTwoTo64 = 18446744073709551616.0;  // Cycles::kMax + 1, exact in a double

// Reads one JSON object, refusing unknown and missing keys (a misspelt key is an
// error, never a silent default).
class ObjectReader {
 public:
  ObjectReader(const json& object, std::string path, const std::string& source)
      : object_(object), path_(std::move(path)), source_(source) {
    if (!object.is_object()) fail(path_, "must be a JSON object");
  }

  const json& member(const std::string& key) {
    const auto it = object_.find(key);
    if (it == object_.end()) fail(path_, fmt::format("missing key \"{}\"", key));
    seen_.insert(key);
    return *it;
  }

  double number(const std::string& key, double min) {
    const json& v = member(key);
    if (!v.is_number()) fail(where(key), "must be a number");
    const double d = v.get<double>();
    if (!std::isfinite(d) || d < min) fail(where(key), fmt::format("must be at least {}", min));
    return d;
  }

  // A time in microseconds ("..._us") as whole cycles at clock_hz, rounded to
  // nearest, and recorded in `times`; refused when a 64-bit cycle count
  // cannot hold it.
  Cycles cycles(const std::string& key, std::uint64_t clock_hz, std::vector<ProfileTime>& times) {
    const double us = number(key, 0);
    const double hz = static_cast<double>(clock_hz);
    const double cycles = std::round(us * hz / 1e6);
    if (!(cycles < kTwoTo64))
      fail(where(key), fmt::format("= {} us is {:.4g} cycles at clock_hz {}, more than a 64-bit "
                                   "cycle count holds ({} cycles, {:.6g} us at this clock)",
                                   us, cycles, clock_hz, Cycles::kMax, kTwoTo64 / hz * 1e6));
    times.push_back({where(key), us, Cycles(static_cast<std::uint64_t>(cycles)), us * hz / 1e6});
    return times.back().cycles;
  }

  std::uint64_t count(const std::string& key) {
    const json& v = member(key);
    if (!v.is_number_unsigned() || v.get<std::uint64_t>() == 0)
      fail(where(key), "must be a positive whole number");
    return v.get<std::uint64_t>();
  }

  std::string text(const std::string& key) {
    const json& v = member(key);
    if (!v.is_string()) fail(where(key), "must be a string");
    return v.get<std::string>();
  }

  // Call after reading every expected key.
  void refuse_unknown_keys() const {
    for (const auto& [key, value] : object_.items())
      if (!seen_.count(key))
        fail(where(key), "is not a known key (docs/simulation.md lists the profile format)");
  }

  std::string where(const std::string& key) const {
    return path_.empty() ? key : path_ + "." + key;
  }

  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw std::runtime_error(fmt::format("cost profile {}: {}{}{}", source_, where,
                                         where.empty() ? "" : " ", what));
  }

 private:
  const json& object_;
  std::string path_;
  const std::string& source_;
  std::set<std::string> seen_;
};

// ceil(a * b / c), or nothing when it exceeds 2^64 - 1. Exact: the product of
// two 64-bit numbers fits 128 bits.
std::optional<std::uint64_t> ceil_mul_div(std::uint64_t a, std::uint64_t b, std::uint64_t c) {
  const unsigned __int128 p = static_cast<unsigned __int128>(a) * b;
  const unsigned __int128 q = p / c + (p % c != 0);
  if (q > Cycles::kMax) return std::nullopt;
  return static_cast<std::uint64_t>(q);
}

// n x the term's cost, naming the operations and the profile field if the
// product overflows.
Cycles times(std::uint64_t n, const CostTermInfo& term, Cycles cost) {
  std::uint64_t product = 0;
  if (__builtin_mul_overflow(n, cost.count(), &product))
    throw CycleOverflow(
        fmt::format("{} {} x {} ({} cycles)", n, term.label, profile_key(term.term), cost.count()));
  return Cycles(product);
}

// The sum of one category's terms, an overflow located in that category.
template <class Terms>
Cycles category_cycles(CostCategory category, Terms terms) {
  try {
    return terms();
  } catch (const CycleOverflow& e) {
    throw e.inside(fmt::format("{} work", to_string(category)));
  }
}

}  // namespace

double ProfileTime::rounding_error() const {
  if (exact_cycles == 0) return 0;
  return std::abs(static_cast<double>(cycles.count()) - exact_cycles) / exact_cycles;
}

std::vector<ProfileTime> CostProfile::rounding(double tolerance) const {
  std::vector<ProfileTime> out;
  for (const ProfileTime& t : times)
    if (t.rounding_error() > tolerance) out.push_back(t);
  return out;
}

Cycles CostProfile::bus_data_cycles(std::uint64_t bytes) const {
  const std::optional<std::uint64_t> c = ceil_mul_div(bytes, clock_hz, bus.bytes_per_second);
  if (!c)
    throw CycleOverflow(fmt::format("{} bytes on the bus at bus.bytes_per_second {} and clock_hz {}",
                                    bytes, bus.bytes_per_second, clock_hz));
  return Cycles(*c);
}

Cycles CostProfile::link_data_cycles(std::uint64_t bytes) const {
  // The bit count must fit 64 bits; its product with clock_hz is exact in 128.
  std::optional<std::uint64_t> c;
  std::uint64_t bits = 0;
  if (!__builtin_mul_overflow(bytes, std::uint64_t{8}, &bits))
    c = ceil_mul_div(bits, clock_hz, link.bits_per_second);
  if (!c)
    throw CycleOverflow(fmt::format("{} bytes on a link at link.bits_per_second {} and clock_hz {}",
                                    bytes, link.bits_per_second, clock_hz));
  return Cycles(*c);
}

CostProfile parse_cost_profile(std::string_view json_text, const std::string& source) {
  json doc;
  try {
    doc = json::parse(json_text);
  } catch (const json::parse_error& e) {
    throw std::runtime_error(fmt::format("cost profile {}: not valid JSON: {}", source, e.what()));
  }
  ObjectReader top(doc, "", source);
  CostProfile p;
  p.name = top.text("name");
  p.description = top.text("description");
  p.source = source;
  p.text_sha256 = sha256_hex(json_text);
  p.clock_hz = top.count("clock_hz");
  const std::uint64_t hz = p.clock_hz;

  // Each payer's section holds its terms of kCostTerms, in microseconds.
  for (const CostPayer payer : kCostPayers) {
    const char* section = profile_section(payer);
    ObjectReader costs(top.member(section), section, source);
    for (const CostTermInfo& t : kCostTerms)
      if (t.payer == payer) p.costs[t.term] = costs.cycles(t.key, hz, p.times);
    costs.refuse_unknown_keys();
  }

  ObjectReader bus(top.member("bus"), "bus", source);
  p.bus.bytes_per_second = bus.count("bytes_per_second");
  p.bus.arbitration = bus.cycles("arbitration_us", hz, p.times);
  p.bus.latency = bus.cycles("latency_us", hz, p.times);
  bus.refuse_unknown_keys();

  ObjectReader link(top.member("link"), "link", source);
  p.link.bits_per_second = link.count("bits_per_second");
  p.link.latency = link.cycles("latency_us", hz, p.times);
  const std::string topology = link.text("topology");
  const std::optional<LinkTopology> t = parse_link_topology(topology);
  if (!t) link.fail(link.where("topology"), fmt::format("'{}' must be \"mesh\" or \"torus\"", topology));
  p.link.topology = *t;
  link.refuse_unknown_keys();

  p.cell_memory_bytes = top.count("cell_memory_bytes");
  p.program_bytes = top.count("program_bytes");
  p.video_memory_bytes = top.count("video_memory_bytes");
  if (p.program_bytes > p.cell_memory_bytes)
    top.fail("program_bytes", fmt::format("({}) must not exceed cell_memory_bytes ({})",
                                          p.program_bytes, p.cell_memory_bytes));
  top.refuse_unknown_keys();
  return p;
}

std::vector<std::string> builtin_profile_names() {
  std::vector<std::string> names;
  for (const BuiltinProfile& b : builtin_profiles()) names.emplace_back(b.name);
  return names;
}

CostProfile load_cost_profile(const std::string& name_or_path) {
  for (const BuiltinProfile& b : builtin_profiles())
    if (b.name == name_or_path) return parse_cost_profile(b.json, std::string(b.name));
  std::ifstream in(name_or_path, std::ios::binary);
  if (!in) {
    std::string known;
    for (const std::string& n : builtin_profile_names()) known += (known.empty() ? "" : ", ") + n;
    throw std::runtime_error(fmt::format(
        "cost profile '{}' is neither a built-in profile ({}) nor a readable file", name_or_path,
        known));
  }
  std::ostringstream text;
  text << in.rdbuf();
  return parse_cost_profile(text.str(), name_or_path);
}

std::optional<LinkTopology> parse_link_topology(const std::string& text) {
  if (text == "mesh") return LinkTopology::Mesh;
  if (text == "torus") return LinkTopology::Torus;
  return std::nullopt;
}

const char* to_string(LinkTopology t) { return t == LinkTopology::Torus ? "torus" : "mesh"; }

CostBreakdown pixel_cost(const OpCounts& ops, const CostTable& c) { return work_cost(ops, 1, c); }

CostBreakdown work_cost(const OpCounts& ops, std::uint64_t pixels, const CostTable& c) {
  CostBreakdown b;
  for (const CostCategoryInfo& category : kCostCategoryTable)
    b[category.category] = category_cycles(category.category, [&] {
      Cycles sum;
      for (const CostTermInfo& t : kCostTerms)
        if (t.payer == CostPayer::Cell && t.category == category.category)
          sum += times(t.cell_count(ops, pixels), t, c[t.term]);
      return sum;
    });
  return b;
}

namespace {

// Term I of kCostTerms, if a cell's, added to w. One function per term, so
// that its count is read in place rather than through a pointer: a float
// screen prices every pixel on its own.
template <std::size_t I>
void add_wide_term(WideBreakdown& w, const OpCounts& ops, std::uint64_t pixels, const CostTable& c) {
  constexpr CostTermInfo t = kCostTerms[I];
  if constexpr (t.payer == CostPayer::Cell) {
    // The voxels visited are counted as set-ups plus steps, which cannot
    // overflow in 128 bits.
    unsigned __int128 n;
    if constexpr (t.term == CostTerm::VoxelVisit)
      n = static_cast<unsigned __int128>(ops.dda_setups) + ops.dda_steps;
    else
      n = t.cell_count(ops, pixels);
    w.cycles[static_cast<int>(t.category)] += n * c[t.term].count();
  }
}

}  // namespace

WideBreakdown wide_work_cost(const OpCounts& ops, std::uint64_t pixels, const CostTable& c) {
  WideBreakdown w;
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (add_wide_term<I>(w, ops, pixels, c), ...);
  }(std::make_index_sequence<kCostTermCount>{});
  return w;
}

std::optional<CostBreakdown> WideBreakdown::narrow() const {
  if (total() > Cycles::kMax) return std::nullopt;
  CostBreakdown b;
  for (int i = 0; i < kCostCategories; ++i) b.cycles[i] = Cycles(static_cast<std::uint64_t>(cycles[i]));
  return b;
}

CostBreakdown voxel_generation_cost(const VoxelGenCounts& n, const CostTable& c, CostPayer payer) {
  if (payer == CostPayer::Cell) throw std::logic_error("a cell's tracing is not voxel generation");
  CostBreakdown b;
  b[CostCategory::VoxelGeneration] = category_cycles(CostCategory::VoxelGeneration, [&] {
    Cycles sum;
    for (const CostTermInfo& t : kCostTerms)
      if (t.payer == payer) sum += times(t.voxel_count(n), t, c[t.term]);
    return sum;
  });
  return b;
}

}  // namespace capsim::sim
