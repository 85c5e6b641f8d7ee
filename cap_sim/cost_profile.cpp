#include "cost_profile.h"

#include "builtin_profiles.h"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

namespace capsim::sim {

namespace {

using nlohmann::json;

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

// Microseconds -> whole cycles at clock_hz, rounded to nearest.
Cycles us_to_cycles(double us, std::uint64_t clock_hz) {
  return Cycles(static_cast<std::uint64_t>(std::llround(us * static_cast<double>(clock_hz) / 1e6)));
}

// ceil(a * b / c) without overflow for the sizes a simulation meets.
std::uint64_t ceil_mul_div(std::uint64_t a, std::uint64_t b, std::uint64_t c) {
  const unsigned __int128 p = static_cast<unsigned __int128>(a) * b;
  return static_cast<std::uint64_t>((p + c - 1) / c);
}

}  // namespace

Cycles CostProfile::bus_data_cycles(std::uint64_t bytes) const {
  return Cycles(ceil_mul_div(bytes, clock_hz, bus.bytes_per_second));
}

Cycles CostProfile::link_data_cycles(std::uint64_t bytes) const {
  return Cycles(ceil_mul_div(bytes * 8, clock_hz, link.bits_per_second));
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
  p.clock_hz = top.count("clock_hz");
  const std::uint64_t hz = p.clock_hz;

  ObjectReader cell(top.member("cell_costs_us"), "cell_costs_us", source);
  auto cell_us = [&](const char* key) { return us_to_cycles(cell.number(key, 0), hz); };
  p.cell.sphere_test = cell_us("sphere_test");
  p.cell.cone_test = cell_us("cone_test");
  p.cell.box_test = cell_us("box_test");
  p.cell.dda_setup = cell_us("dda_setup");
  p.cell.dda_step = cell_us("dda_step");
  p.cell.matvec = cell_us("matvec");
  p.cell.tree_visit = cell_us("tree_visit");
  p.cell.hit_sort = cell_us("hit_sort");
  p.cell.shading_eval = cell_us("shading_eval");
  p.cell.ray_other = cell_us("ray_other");
  p.cell.pixel_write = cell_us("pixel_write");
  p.cell.aa_square = cell_us("aa_square");
  cell.refuse_unknown_keys();

  ObjectReader host(top.member("host_costs_us"), "host_costs_us", source);
  auto host_us = [&](const char* key) { return us_to_cycles(host.number(key, 0), hz); };
  p.host.primitive = host_us("primitive");
  p.host.matmat = host_us("matmat");
  p.host.matvec = host_us("matvec");
  p.host.column = host_us("voxel_column");
  p.host.voxel_entry = host_us("voxel_entry");
  host.refuse_unknown_keys();

  ObjectReader bus(top.member("bus"), "bus", source);
  p.bus.bytes_per_second = bus.count("bytes_per_second");
  p.bus.arbitration = us_to_cycles(bus.number("arbitration_us", 0), hz);
  p.bus.latency = us_to_cycles(bus.number("latency_us", 0), hz);
  bus.refuse_unknown_keys();

  ObjectReader link(top.member("link"), "link", source);
  p.link.bits_per_second = link.count("bits_per_second");
  p.link.latency = us_to_cycles(link.number("latency_us", 0), hz);
  const std::string topology = link.text("topology");
  const std::optional<LinkTopology> t = parse_link_topology(topology);
  if (!t) link.fail(link.where("topology"), fmt::format("'{}' must be \"mesh\" or \"torus\"", topology));
  p.link.topology = *t;
  link.refuse_unknown_keys();

  p.cell_memory_bytes = top.count("cell_memory_bytes");
  p.program_bytes = top.count("program_bytes");
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

const char* to_string(CostCategory c) {
  switch (c) {
    case CostCategory::Intersection: return "intersection";
    case CostCategory::Dda: return "3DDDA (incl. set-up)";
    case CostCategory::Csg: return "CSG evaluation";
    case CostCategory::VoxelGeneration: return "voxel generation";
    case CostCategory::Other: return "other";
  }
  return "?";
}

const char* json_key(CostCategory c) {
  switch (c) {
    case CostCategory::Intersection: return "intersection";
    case CostCategory::Dda: return "dda";
    case CostCategory::Csg: return "csg";
    case CostCategory::VoxelGeneration: return "voxel_generation";
    case CostCategory::Other: return "other";
  }
  return "?";
}

CostBreakdown pixel_cost(const OpCounts& ops, const CellCosts& c) { return work_cost(ops, 1, c); }

CostBreakdown work_cost(const OpCounts& ops, std::uint64_t pixels, const CellCosts& c) {
  CostBreakdown b;
  b[CostCategory::Intersection] =
      ops.sphere_tests * c.sphere_test + ops.cone_tests * c.cone_test + ops.box_tests * c.box_test;
  b[CostCategory::Dda] = ops.dda_setups * c.dda_setup + ops.dda_steps * c.dda_step;
  b[CostCategory::Csg] = ops.tree_visits * c.tree_visit + ops.hits_sorted * c.hit_sort;
  b[CostCategory::Other] = ops.matvec * c.matvec + ops.shading_evals * c.shading_eval +
                           ops.rays * c.ray_other + ops.aa_squares * c.aa_square + pixels * c.pixel_write;
  return b;
}

CostBreakdown voxel_generation_cost(const VoxelGenCounts& n, const HostCosts& c) {
  CostBreakdown b;
  b[CostCategory::VoxelGeneration] = n.primitives * c.primitive + n.matmat * c.matmat +
                                     n.matvec * c.matvec + n.columns * c.column +
                                     n.voxel_entries * c.voxel_entry;
  return b;
}

}  // namespace capsim::sim
