#pragma once
// The cost terms: every operation a machine pays cycles for, each one row of
// kCostTerms with its profile key, its Table 4-3 process, what it counts and
// how to count it. The profile reader, the cost of a cell's work and of the
// host's voxel generation, the calibration's fit and the reports all read this
// table: adding a counted operation is one row here (and its count in the
// tracer's OpCounts, or the host's VoxelGenCounts).

#include "capsim/trace/op_counts.h"

#include <array>
#include <cstdint>
#include <string>

namespace capsim::sim {

// Table 4-3's processes, in its order.
enum class CostCategory { Intersection, Dda, Csg, VoxelGeneration, Other };
inline constexpr int kCostCategories = 5;

struct CostCategoryInfo {
  CostCategory category;
  const char* name;      // as Table 4-3 names it: "3DDDA (incl. set-up)"
  const char* json_key;  // "dda"
};
inline constexpr std::array<CostCategoryInfo, kCostCategories> kCostCategoryTable = {{
    {CostCategory::Intersection, "intersection", "intersection"},
    {CostCategory::Dda, "3DDDA (incl. set-up)", "dda"},
    {CostCategory::Csg, "CSG evaluation", "csg"},
    {CostCategory::VoxelGeneration, "voxel generation", "voxel_generation"},
    {CostCategory::Other, "other", "other"},
}};
const char* to_string(CostCategory c);  // kCostCategoryTable's name
const char* json_key(CostCategory c);   // kCostCategoryTable's json_key

// Who pays a term: a cell for the pixels it traces, the host for the voxel
// grid (Algorithm-3, "done on the host today", §5), or a cell for its share of
// the voxel grid when the cells generate it (--voxel-generation cells,
// machine/parts/voxel_shares.h): the host's operations at a cell's speed.
enum class CostPayer { Cell, Host, CellVoxels };

enum class CostTerm {
  SphereTest, ConeTest, BoxTest, MeshTest, MeshNodeTest, TriangleTest, RevolutionTest, RevolutionEdgeTest, QuarticTest, DdaSetup, DdaStep, VoxelVisit, Matvec, VoxelPass, TreeVisit, HitSort,
  ShadingEval, RayOther, AaSquare, PixelWrite,
  HostPrimitive, HostMatmat, HostMatvec, HostColumn, HostEntry, HostGridVoxel,
  CellPrimitive, CellMatmat, CellMatvec, CellColumn, CellEntry, CellGridVoxel,
};
inline constexpr int kCostTermCount = 32;

// Where the shipped profiles' value of a term comes from.
enum class CostSource {
  Table41,  // the paper's Table 4-1 measured it
  Fitted,   // fitted to the paper's published times (docs/calibration.md)
  Reasoned, // set from Table 4-1's costs of similar work (docs/calibration.md)
};

struct CostTermInfo {
  CostTerm term;
  CostPayer payer;
  const char* key;        // its key in the profile's section: "sphere_test"
  CostCategory category;  // the Table 4-3 process it belongs to
  const char* label;      // what is counted, plural: "sphere tests"
  const char* unit;       // one of them: "test"
  CostSource source;
  // How many a cell's work holds (payer Cell): from the tracer's counts and
  // the pixels written. Throws CycleOverflow if the count exceeds 64 bits.
  std::uint64_t (*cell_count)(const OpCounts& ops, std::uint64_t pixels);
  // How many a voxel generation holds (payer Host or CellVoxels): the host's
  // whole grid, or a cell's share of it.
  std::uint64_t (*voxel_count)(const VoxelGenCounts& counts);
};

// The voxels a ray's 3DDDA visited: the set-up's first voxel and one per step.
// Throws CycleOverflow beyond 2^64 - 1.
std::uint64_t voxels_visited(const OpCounts& ops);

// Every term, in the order a profile lists them and a category sums them.
inline constexpr std::array<CostTermInfo, kCostTermCount> kCostTerms = {{
    {CostTerm::SphereTest, CostPayer::Cell, "sphere_test", CostCategory::Intersection, "sphere tests", "test",
     CostSource::Table41, [](const OpCounts& o, std::uint64_t) { return o.sphere_tests; }, nullptr},
    {CostTerm::ConeTest, CostPayer::Cell, "cone_test", CostCategory::Intersection, "cone tests", "test",
     CostSource::Table41, [](const OpCounts& o, std::uint64_t) { return o.cone_tests; }, nullptr},
    {CostTerm::BoxTest, CostPayer::Cell, "box_test", CostCategory::Intersection, "box tests", "test",
     CostSource::Table41, [](const OpCounts& o, std::uint64_t) { return o.box_tests; }, nullptr},
    // A mesh leaf (docs/calibration.md gives the reasoning): the ray carried
    // into its space once, then the boxes of its hierarchy and the triangles
    // in the boxes the ray meets.
    {CostTerm::MeshTest, CostPayer::Cell, "mesh_test", CostCategory::Intersection, "mesh tests", "test",
     CostSource::Reasoned, [](const OpCounts& o, std::uint64_t) { return o.mesh_tests; }, nullptr},
    {CostTerm::MeshNodeTest, CostPayer::Cell, "mesh_node_test", CostCategory::Intersection, "mesh box tests",
     "test", CostSource::Reasoned, [](const OpCounts& o, std::uint64_t) { return o.mesh_node_tests; }, nullptr},
    {CostTerm::TriangleTest, CostPayer::Cell, "triangle_test", CostCategory::Intersection, "triangle tests",
     "test", CostSource::Reasoned, [](const OpCounts& o, std::uint64_t) { return o.triangle_tests; }, nullptr},
    // A revolution leaf (docs/calibration.md): the ray carried into its space
    // once, then a quadratic per profile edge and a quartic per ellipse.
    {CostTerm::RevolutionTest, CostPayer::Cell, "revolution_test", CostCategory::Intersection, "revolution tests",
     "test", CostSource::Reasoned, [](const OpCounts& o, std::uint64_t) { return o.revolution_tests; }, nullptr},
    {CostTerm::RevolutionEdgeTest, CostPayer::Cell, "revolution_edge_test", CostCategory::Intersection,
     "revolved edge tests", "test", CostSource::Reasoned,
     [](const OpCounts& o, std::uint64_t) { return o.revolution_edge_tests; }, nullptr},
    {CostTerm::QuarticTest, CostPayer::Cell, "quartic_test", CostCategory::Intersection, "revolved ellipse tests",
     "test", CostSource::Reasoned, [](const OpCounts& o, std::uint64_t) { return o.quartic_tests; }, nullptr},
    {CostTerm::DdaSetup, CostPayer::Cell, "dda_setup", CostCategory::Dda, "3DDDA set-ups", "set-up",
     CostSource::Table41, [](const OpCounts& o, std::uint64_t) { return o.dda_setups; }, nullptr},
    {CostTerm::DdaStep, CostPayer::Cell, "dda_step", CostCategory::Dda, "3DDDA steps", "step", CostSource::Table41,
     [](const OpCounts& o, std::uint64_t) { return o.dda_steps; }, nullptr},
    // The other work in each voxel a ray visits (its list fetched, its
    // primitives checked against the ray's mailbox): RO per voxel of eq. (2).
    {CostTerm::VoxelVisit, CostPayer::Cell, "voxel_visit", CostCategory::Dda, "voxels visited", "voxel",
     CostSource::Fitted, [](const OpCounts& o, std::uint64_t) { return voxels_visited(o); }, nullptr},
    // 4x4 matrix x vector outside the intersection tests (two per normal).
    {CostTerm::Matvec, CostPayer::Cell, "matvec", CostCategory::Other, "matrix-vector products", "product",
     CostSource::Table41, [](const OpCounts& o, std::uint64_t) { return o.matvec; }, nullptr},
    // Partial evaluation (§2.3): in each voxel that holds primitives, its list
    // fetched, its crossings put in order and handed to the status tree.
    {CostTerm::VoxelPass, CostPayer::Cell, "voxel_pass", CostCategory::Csg, "voxel passes", "voxel",
     CostSource::Fitted, [](const OpCounts& o, std::uint64_t) { return o.voxel_passes; }, nullptr},
    {CostTerm::TreeVisit, CostPayer::Cell, "tree_visit", CostCategory::Csg, "status-tree visits", "node visit",
     CostSource::Reasoned, [](const OpCounts& o, std::uint64_t) { return o.tree_visits; }, nullptr},
    {CostTerm::HitSort, CostPayer::Cell, "hit_sort", CostCategory::Csg, "crossings sorted", "crossing",
     CostSource::Reasoned, [](const OpCounts& o, std::uint64_t) { return o.hits_sorted; }, nullptr},
    {CostTerm::ShadingEval, CostPayer::Cell, "shading_eval", CostCategory::Other, "shading evaluations",
     "evaluation", CostSource::Reasoned, [](const OpCounts& o, std::uint64_t) { return o.shading_evals; }, nullptr},
    // The per-ray fixed work: RO of equations (1) and (2).
    {CostTerm::RayOther, CostPayer::Cell, "ray_other", CostCategory::Other, "rays", "ray", CostSource::Fitted,
     [](const OpCounts& o, std::uint64_t) { return o.rays; }, nullptr},
    {CostTerm::AaSquare, CostPayer::Cell, "aa_square", CostCategory::Other, "antialiasing squares", "square",
     CostSource::Reasoned, [](const OpCounts& o, std::uint64_t) { return o.aa_squares; }, nullptr},
    {CostTerm::PixelWrite, CostPayer::Cell, "pixel_write", CostCategory::Other, "pixel writes", "pixel",
     CostSource::Reasoned, [](const OpCounts&, std::uint64_t pixels) { return pixels; }, nullptr},
    {CostTerm::HostPrimitive, CostPayer::Host, "primitive", CostCategory::VoxelGeneration, "primitives",
     "primitive", CostSource::Reasoned, nullptr, [](const VoxelGenCounts& n) { return n.primitives; }},
    {CostTerm::HostMatmat, CostPayer::Host, "matmat", CostCategory::VoxelGeneration, "matrix-matrix products",
     "product", CostSource::Table41, nullptr, [](const VoxelGenCounts& n) { return n.matmat; }},
    {CostTerm::HostMatvec, CostPayer::Host, "matvec", CostCategory::VoxelGeneration, "matrix-vector products",
     "product", CostSource::Table41, nullptr, [](const VoxelGenCounts& n) { return n.matvec; }},
    {CostTerm::HostColumn, CostPayer::Host, "voxel_column", CostCategory::VoxelGeneration, "voxel columns",
     "column", CostSource::Reasoned, nullptr, [](const VoxelGenCounts& n) { return n.columns; }},
    {CostTerm::HostEntry, CostPayer::Host, "voxel_entry", CostCategory::VoxelGeneration, "voxel entries",
     "entry", CostSource::Reasoned, nullptr, [](const VoxelGenCounts& n) { return n.voxel_entries; }},
    // The grid itself: every voxel set up and given its (possibly empty) list.
    {CostTerm::HostGridVoxel, CostPayer::Host, "grid_voxel", CostCategory::VoxelGeneration, "grid voxels",
     "voxel", CostSource::Fitted, nullptr, [](const VoxelGenCounts& n) { return n.grid_voxels; }},
    // The same operations on a cell (docs/calibration.md): the products at
    // Table 4-1's CAP costs, the fitted host costs times the cell's slowness.
    {CostTerm::CellPrimitive, CostPayer::CellVoxels, "primitive", CostCategory::VoxelGeneration, "primitives",
     "primitive", CostSource::Reasoned, nullptr, [](const VoxelGenCounts& n) { return n.primitives; }},
    {CostTerm::CellMatmat, CostPayer::CellVoxels, "matmat", CostCategory::VoxelGeneration, "matrix-matrix products",
     "product", CostSource::Table41, nullptr, [](const VoxelGenCounts& n) { return n.matmat; }},
    {CostTerm::CellMatvec, CostPayer::CellVoxels, "matvec", CostCategory::VoxelGeneration, "matrix-vector products",
     "product", CostSource::Table41, nullptr, [](const VoxelGenCounts& n) { return n.matvec; }},
    {CostTerm::CellColumn, CostPayer::CellVoxels, "voxel_column", CostCategory::VoxelGeneration, "voxel columns",
     "column", CostSource::Reasoned, nullptr, [](const VoxelGenCounts& n) { return n.columns; }},
    {CostTerm::CellEntry, CostPayer::CellVoxels, "voxel_entry", CostCategory::VoxelGeneration, "voxel entries",
     "entry", CostSource::Reasoned, nullptr, [](const VoxelGenCounts& n) { return n.voxel_entries; }},
    {CostTerm::CellGridVoxel, CostPayer::CellVoxels, "grid_voxel", CostCategory::VoxelGeneration, "grid voxels",
     "voxel", CostSource::Reasoned, nullptr, [](const VoxelGenCounts& n) { return n.grid_voxels; }},
}};

const CostTermInfo& info(CostTerm t);
// "cell_costs_us.sphere_test": the term's path in a profile file.
std::string profile_key(CostTerm t);
// "cell_costs_us", "host_costs_us" or "cell_voxel_costs_us": the profile
// section of a payer's terms.
const char* profile_section(CostPayer p);
inline constexpr CostPayer kCostPayers[] = {CostPayer::Cell, CostPayer::Host, CostPayer::CellVoxels};

// The cells' term for the same operation as a host term (its key in the
// cells' voxel section). Precondition: t is paid by the host.
CostTerm cell_voxel_twin(CostTerm host_term);

// A value for each term.
template <class T>
struct PerTerm {
  std::array<T, kCostTermCount> values{};
  T& operator[](CostTerm t) { return values[static_cast<int>(t)]; }
  const T& operator[](CostTerm t) const { return values[static_cast<int>(t)]; }
};

static_assert([] {
  for (int i = 0; i < kCostTermCount; ++i)
    if (static_cast<int>(kCostTerms[i].term) != i) return false;
  return true;
}(), "kCostTerms lists the terms in the order of CostTerm");
static_assert([] {
  for (int i = 0; i < kCostCategories; ++i)
    if (static_cast<int>(kCostCategoryTable[i].category) != i) return false;
  return true;
}(), "kCostCategoryTable lists the categories in the order of CostCategory");

}  // namespace capsim::sim
