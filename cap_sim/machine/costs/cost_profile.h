#pragma once
// A cost profile: what each counted operation and each transfer costs on one
// machine, in integer cycles at the profile's clock. Profiles are data (JSON; the
// format is in docs/simulation.md, the figures in docs/calibration.md); `cap` and
// `m380` are compiled into the binary, any other file can be loaded by path.

#include "kernel/cycles.h"
#include "machine/costs/cost_terms.h"

#include "capsim/trace/op_counts.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace capsim::sim {

// What each cost term costs, in cycles of the profile's clock (cost_terms.h).
using CostTable = PerTerm<Cycles>;

struct BusCosts {
  std::uint64_t bytes_per_second = 0;
  Cycles arbitration;  // from the start of a grant to the first byte on the bus
  Cycles latency;      // from the last byte on the bus to the data in the receivers' memory
};

// How the edge cells of the grid are wired: a mesh has links only between
// adjacent cells; a torus also joins each row's ends and each column's ends, so
// that the cells of one edge are neighbours of the opposite edge's.
enum class LinkTopology { Mesh, Torus };
std::optional<LinkTopology> parse_link_topology(const std::string& text);
const char* to_string(LinkTopology t);

struct LinkCosts {
  std::uint64_t bits_per_second = 0;
  Cycles latency;  // per hop, from the last bit sent to the message in the next cell
  LinkTopology topology = LinkTopology::Mesh;
};

// A time the profile file gave in microseconds, and the whole cycles of the
// clock it became.
struct ProfileTime {
  std::string key;  // where in the file: "cell_costs_us.tree_visit"
  double us = 0;
  Cycles cycles;
  // us x clock_hz / 1e6, before rounding.
  double exact_cycles = 0;
  // How far rounding moved it, as a fraction of the exact cycles: 0 for a
  // time of 0, 1 for a time that became 0 cycles.
  double rounding_error() const;
};

struct CostProfile {
  std::string name;
  std::string description;
  std::string source;  // where it was read from: a built-in name or a path
  // SHA-256 of the JSON text it was parsed from (empty for a profile built in
  // code): the reports' provenance names the exact profile a run used.
  std::string text_sha256;
  std::uint64_t clock_hz = 0;
  CostTable costs;  // every term of kCostTerms, cell's and host's
  BusCosts bus;
  LinkCosts link;
  std::uint64_t cell_memory_bytes = 0;   // program + a unit's scene and voxel data must fit
  std::uint64_t video_memory_bytes = 0;  // a unit's pixels (and corner samples) must fit
  std::uint64_t program_bytes = 0;      // the tracer program every cell holds
  // Every time read from the file, in the file's order (empty for a profile
  // built in code).
  std::vector<ProfileTime> times;

  // The times whose rounding to whole cycles moved them by more than
  // `tolerance` (a fraction; 0.01 is 1 %): at a slow clock, a cost of a few
  // microseconds may become 0 cycles (free) or twice itself.
  std::vector<ProfileTime> rounding(double tolerance = 0.01) const;

  // Cycles to move `bytes` at the bus's and a link's rate (rounded up). Throw
  // CycleOverflow, naming the rate's field, beyond 2^64 - 1 cycles.
  Cycles bus_data_cycles(std::uint64_t bytes) const;
  Cycles link_data_cycles(std::uint64_t bytes) const;
};

// Parses a profile's JSON text. Throws std::runtime_error naming `source` and
// the offending key for malformed JSON, a missing or unknown key, or a value out
// of range. Times in the file are microseconds ("..._us"); each becomes
// round(us * clock_hz / 1e6) cycles, and a time whose cycles a 64-bit count
// cannot hold is out of range. program_bytes above cell_memory_bytes is too.
CostProfile parse_cost_profile(std::string_view json_text, const std::string& source);

// "cap" or "m380" (compiled in), or the path of a profile file.
CostProfile load_cost_profile(const std::string& name_or_path);
std::vector<std::string> builtin_profile_names();

// Cycles by category. total() and += throw CycleOverflow beyond 2^64 - 1 cycles.
struct CostBreakdown {
  std::array<Cycles, kCostCategories> cycles{};

  Cycles& operator[](CostCategory c) { return cycles[static_cast<int>(c)]; }
  Cycles operator[](CostCategory c) const { return cycles[static_cast<int>(c)]; }
  Cycles total() const {
    Cycles sum;
    for (Cycles c : cycles) sum += c;
    return sum;
  }
  CostBreakdown& operator+=(const CostBreakdown& o) {
    std::array<Cycles, kCostCategories> sum = cycles;  // unchanged if a sum overflows
    for (int i = 0; i < kCostCategories; ++i) sum[i] += o.cycles[i];
    cycles = sum;
    return *this;
  }
};

// The cycles one pixel costs a cell: each cell term's count times its cost
// (kCostTerms: the per-ray fixed work for every ray, one video-memory write,
// ...). Throws CycleOverflow naming the category and, for a product, the
// profile field.
CostBreakdown pixel_cost(const OpCounts& ops, const CostTable& costs);

// pixel_cost summed over `pixels` pixels whose operations add up to `ops` (it is
// linear in the counts, with one pixel_write a pixel): the same cycles, without
// a conversion per pixel. Throws CycleOverflow as pixel_cost.
CostBreakdown work_cost(const OpCounts& ops, std::uint64_t pixels, const CostTable& costs);

// The same cycles exactly, in 128 bits (they cannot overflow for counts below
// 2^64), to decide once whether a sum fits Cycles.
struct WideBreakdown {
  std::array<unsigned __int128, kCostCategories> cycles{};
  unsigned __int128 total() const {
    unsigned __int128 sum = 0;
    for (unsigned __int128 c : cycles) sum += c;
    return sum;
  }
  // The breakdown in Cycles, or nothing when the total exceeds Cycles::kMax
  // (then some category or the total would not fit).
  std::optional<CostBreakdown> narrow() const;
};
WideBreakdown wide_work_cost(const OpCounts& ops, std::uint64_t pixels, const CostTable& costs);

// The cycles of Algorithm-3's operations `counts` for the host (the whole
// grid) or for a cell (its share, payer CellVoxels): each of the payer's terms'
// count times its cost (all in CostCategory::VoxelGeneration). Throws
// CycleOverflow as pixel_cost does.
CostBreakdown voxel_generation_cost(const VoxelGenCounts& counts, const CostTable& costs,
                                    CostPayer payer = CostPayer::Host);

}  // namespace capsim::sim
