// Algorithm-3 of the paper: voxel generation. Every primitive's bounding box goes
// to world space, is projected onto the X-Y plane, and in each voxel column the
// projection covers the box's faces, taken as infinite planes, bound Z.

#include "capsim/trace/voxel_grid.h"

#include "capsim/system/host_threads.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <stdexcept>

namespace capsim {

namespace {

// A bounding plane that is not vertical, as a height over the X-Y plane:
// z(x, y) = z0 + zx x + zy y on the plane (n.z != 0); front = the solid lies
// below it (n.z > 0), else above.
struct FacePlane {
  double z0, zx, zy;
  bool front;
};

// At most N values, kept in place: each primitive's hull and planes are built
// and dropped thousands of times a scene, where a heap allocation each would
// cost about as much as the arithmetic.
template <class T, std::size_t N>
class FixedList {
 public:
  void push_back(const T& v) { items_[size_++] = v; }  // precondition: size() < N
  void resize(std::size_t n) { size_ = n; }            // precondition: n <= N
  std::size_t size() const { return size_; }
  T& operator[](std::size_t i) { return items_[i]; }
  const T& operator[](std::size_t i) const { return items_[i]; }
  const T* begin() const { return items_.data(); }
  const T* end() const { return items_.data() + size_; }

 private:
  std::array<T, N> items_;
  std::size_t size_ = 0;
};

// 6 box faces, and for a sphere 20 more (make_bounding_directions).
constexpr std::size_t kMaxBoundingDirections = 26;

// A bounding plane's outward direction in object space.
struct BoundingDirection {
  glm::dvec3 u;
  // Worked out once rather than for every primitive: what the sphere's and
  // the cone's supports are made from, and the same bits either way.
  double length;  // |u|
  double radial;  // |(u.x, u.y)|
};

// The object-space directions whose supporting planes bound a primitive: the box
// faces always (a mesh's own box); for the curved primitives also the 45-degree planes, the extra
// circumscribing planes of the paper's fig. 2-2, which cut the corners of the box
// that the sphere and the cone leave empty.
std::vector<BoundingDirection> make_bounding_directions(PrimitiveKind kind) {
  std::vector<glm::dvec3> dirs = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0},
                                  {0, 1, 0},  {0, 0, -1}, {0, 0, 1}};
  if (kind == PrimitiveKind::Sphere || kind == PrimitiveKind::Cone) {
    for (int sx : {-1, 1})
      for (int sy : {-1, 1}) {
        dirs.push_back(glm::dvec3(sx, sy, 0));
        if (kind == PrimitiveKind::Sphere) {
          dirs.push_back(glm::dvec3(sx, 0, sy));
          dirs.push_back(glm::dvec3(0, sx, sy));
          for (int sz : {-1, 1}) dirs.push_back(glm::dvec3(sx, sy, sz));
        }
      }
  }
  if (dirs.size() > kMaxBoundingDirections) throw std::logic_error("more bounding directions than planes are kept");
  std::vector<BoundingDirection> out;
  for (const glm::dvec3& u : dirs) out.push_back({u, glm::length(u), std::hypot(u.x, u.y)});
  return out;
}

// The same, built once per kind.
const std::vector<BoundingDirection>& bounding_directions(PrimitiveKind kind) {
  static const std::vector<BoundingDirection> sphere = make_bounding_directions(PrimitiveKind::Sphere);
  static const std::vector<BoundingDirection> box = make_bounding_directions(PrimitiveKind::Box);
  static const std::vector<BoundingDirection> cone = make_bounding_directions(PrimitiveKind::Cone);
  switch (kind) {
    case PrimitiveKind::Sphere:
      return sphere;
    case PrimitiveKind::Box:
      return box;
    case PrimitiveKind::Cone:
      return cone;
    case PrimitiveKind::Mesh:
    case PrimitiveKind::Revolution:
      break;
  }
  return box;
}

// max over the canonical solid of u . p: the supporting plane's offset.
double support(const PreparedPrimitive& p, const BoundingDirection& d) {
  const glm::dvec3& u = d.u;
  switch (p.kind) {
    case PrimitiveKind::Sphere:
      return d.length;
    case PrimitiveKind::Box:
      return std::max(u.x, 0.0) + std::max(u.y, 0.0) + std::max(u.z, 0.0);
    case PrimitiveKind::Cone:
      return std::max(p.cone_r1 * d.radial, p.cone_r2 * d.radial + u.z);
    case PrimitiveKind::Mesh:
    case PrimitiveKind::Revolution: {
      // The mesh's (the revolution's) own box bounds it: its faces are the box
      // directions' planes.
      const Aabb b = object_bounds(p);
      double h = 0;
      for (int k = 0; k < 3; ++k) h += std::max(u[k] * b.lo[k], u[k] * b.hi[k]);
      return h;
    }
  }
  return 0;
}

// The bounding planes carried to world space: u . q <= h in object space with
// q = A^-1 (p - t) becomes (A^-T u) . p <= h + (A^-T u) . t. Only the planes that
// are not vertical bound Z; each is kept as its height over the X-Y plane.
using FacePlanes = FixedList<FacePlane, kMaxBoundingDirections>;
FacePlanes world_face_planes(const PreparedPrimitive& p) {
  FacePlanes faces;
  const glm::dvec3 t(p.to_world[3]);
  for (const BoundingDirection& dir : bounding_directions(p.kind)) {
    const glm::dvec3 n = p.normal_to_world * dir.u;
    const double d = support(p, dir) + glm::dot(n, t);
    if (n.z != 0) faces.push_back({d / n.z, -n.x / n.z, -n.y / n.z, n.z > 0});
  }
  return faces;
}

// The convex hull (counter-clockwise) of the projected box corners. Andrew's
// monotone chain holds at most twice the points while it builds the hull.
using Hull = FixedList<glm::dvec2, 16>;
Hull convex_hull(std::array<glm::dvec2, 8> pts) {
  std::sort(pts.begin(), pts.end(),
            [](const glm::dvec2& a, const glm::dvec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  Hull hull;
  hull.resize(2 * pts.size());
  std::size_t k = 0;
  auto cross = [](const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  };
  for (std::size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  for (std::size_t i = pts.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  hull.resize(k > 1 ? k - 1 : k);
  return hull;
}

// Separating-axis test: does the rectangle [lo, hi] meet the convex polygon?
// The rectangle's own axes are covered by the caller's column range.
bool rect_meets_hull(const glm::dvec2& lo, const glm::dvec2& hi, const Hull& hull) {
  const std::size_t m = hull.size();
  if (m < 3) return true;
  for (std::size_t i = 0; i < m; ++i) {
    const glm::dvec2 a = hull[i], b = hull[(i + 1) % m];
    const glm::dvec2 outward(b.y - a.y, a.x - b.x);  // right of a->b is outside (CCW)
    // The rectangle corner least far along the outward normal.
    const glm::dvec2 c(outward.x > 0 ? lo.x : hi.x, outward.y > 0 ? lo.y : hi.y);
    if (glm::dot(c - a, outward) > 0) return false;
  }
  return true;
}

int clamp_index(double v, int n) { return clamped_voxel_index(v, n); }

// Primitives per range of the parallel placement: enough that a range's
// scheduling is small against placing it, few enough that the smallest
// lattices (125 balls) still give every thread work.
constexpr std::size_t kPrimitivesPerRange = 32;

// The voxel entries of one primitive, as (voxel index) appended to out.
void place_primitive(const PreparedPrimitive& p, const Aabb& u, int n, const glm::dvec3& vs,
                     double eps, std::vector<std::uint32_t>& out, VoxelGenCounts* counts) {
  // 1. the bounding box in world coordinates: eight corners (one matrix x matrix
  //    to place the canonical box, one matrix x vector per corner).
  const Aabb ob = object_bounds(p);
  std::array<glm::dvec2, 8> projected;
  for (int k = 0; k < 8; ++k) {
    const glm::dvec3 c{(k & 1) ? ob.hi.x : ob.lo.x, (k & 2) ? ob.hi.y : ob.lo.y,
                       (k & 4) ? ob.hi.z : ob.lo.z};
    const glm::dvec3 w(p.to_world * glm::dvec4(c, 1.0));
    projected[k] = {w.x, w.y};  // 2. parallel projection onto X-Y
  }
  if (counts) {
    ++counts->primitives;
    ++counts->matmat;
    counts->matvec += 8;
  }
  const Hull hull = convex_hull(projected);
  const FacePlanes faces = world_face_planes(p);

  const Aabb& wb = p.world_bounds;
  const int x0 = clamp_index((wb.lo.x - eps - u.lo.x) / vs.x, n);
  const int x1 = clamp_index((wb.hi.x + eps - u.lo.x) / vs.x, n);
  const int y0 = clamp_index((wb.lo.y - eps - u.lo.y) / vs.y, n);
  const int y1 = clamp_index((wb.hi.y + eps - u.lo.y) / vs.y, n);
  for (int iy = y0; iy <= y1; ++iy) {
    for (int ix = x0; ix <= x1; ++ix) {
      const glm::dvec2 lo(u.lo.x + ix * vs.x - eps, u.lo.y + iy * vs.y - eps);
      const glm::dvec2 hi(u.lo.x + (ix + 1) * vs.x + eps, u.lo.y + (iy + 1) * vs.y + eps);
      if (counts) ++counts->columns;
      if (!rect_meets_hull(lo, hi, hull)) continue;
      // 3. Z bounds in this column, every bounding face an infinite plane:
      //    Zmax = min over front faces of the max over the column's corners,
      //    Zmin = max over back faces of the min over the column's corners.
      //    z is linear in x and y, so its max (min) over the four corners takes
      //    each axis's larger (smaller) term on its own.
      double zmin = wb.lo.z, zmax = wb.hi.z;
      for (const FacePlane& f : faces) {
        const double ax = f.zx * lo.x, bx = f.zx * hi.x, ay = f.zy * lo.y, by = f.zy * hi.y;
        if (f.front) {
          zmax = std::min(zmax, f.z0 + std::max(ax, bx) + std::max(ay, by));
        } else {
          zmin = std::max(zmin, f.z0 + std::min(ax, bx) + std::min(ay, by));
        }
      }
      zmin -= eps;
      zmax += eps;
      if (zmin > zmax) continue;
      const int z0 = clamp_index((zmin - u.lo.z) / vs.z, n);
      const int z1 = clamp_index((zmax - u.lo.z) / vs.z, n);
      for (int iz = z0; iz <= z1; ++iz) out.push_back(static_cast<std::uint32_t>((iz * n + iy) * n + ix));
    }
  }
}

// The voxel index range [lo, hi] per axis of a world-axis box b.
struct VoxelRange {
  glm::ivec3 lo, hi;
  std::size_t count() const {
    return static_cast<std::size_t>(hi.x - lo.x + 1) * static_cast<std::size_t>(hi.y - lo.y + 1) *
           static_cast<std::size_t>(hi.z - lo.z + 1);
  }
};

VoxelRange voxel_range(const Aabb& b, const Aabb& u, int n, const glm::dvec3& vs, double eps) {
  return {{clamp_index((b.lo.x - eps - u.lo.x) / vs.x, n),
           clamp_index((b.lo.y - eps - u.lo.y) / vs.y, n),
           clamp_index((b.lo.z - eps - u.lo.z) / vs.z, n)},
          {clamp_index((b.hi.x + eps - u.lo.x) / vs.x, n),
           clamp_index((b.hi.y + eps - u.lo.y) / vs.y, n),
           clamp_index((b.hi.z + eps - u.lo.z) / vs.z, n)}};
}

// The voxel entries of a world-axis box b, as (voxel index) appended to out: the
// plain bounding-box placement that Algorithm-3 is measured against.
void place_bounding_box(const Aabb& b, const Aabb& u, int n, const glm::dvec3& vs, double eps,
                        std::vector<std::uint32_t>& out) {
  const auto [lo, hi] = voxel_range(b, u, n, vs, eps);
  for (int z = lo.z; z <= hi.z; ++z)
    for (int y = lo.y; y <= hi.y; ++y)
      for (int x = lo.x; x <= hi.x; ++x) out.push_back(static_cast<std::uint32_t>((z * n + y) * n + x));
}

// The voxels of the primitives first, first + 1, ... in one array: primitive
// first + p's are voxels[start[p]] up to voxels[start[p + 1]].
struct Placements {
  std::size_t first = 0;
  std::vector<std::uint32_t> voxels;
  std::vector<std::size_t> start{0};
  void end_primitive() { start.push_back(voxels.size()); }
};

// Compressed rows from the placements of consecutive primitive ranges, in
// primitive order: primitives ascending in each voxel, whatever the ranges.
VoxelGrid build_grid(const Aabb& universe, int n, std::span<const Placements> ranges) {
  VoxelGrid g;
  g.universe = universe;
  g.n = n;
  g.voxel_size = universe.extent() / static_cast<double>(n);
  g.inv_voxel_size = static_cast<double>(n) / universe.extent();
  const std::size_t cells = static_cast<std::size_t>(n) * n * n;
  g.offsets.assign(cells + 1, 0);
  for (const Placements& placed : ranges)
    for (std::uint32_t v : placed.voxels) ++g.offsets[v + 1];
  g.largest_voxel = *std::max_element(g.offsets.begin(), g.offsets.end());
  for (std::size_t v = 0; v < cells; ++v) g.offsets[v + 1] += g.offsets[v];
  g.items.resize(g.offsets[cells]);
  std::vector<std::uint32_t> fill(g.offsets.begin(), g.offsets.end() - 1);
  for (const Placements& placed : ranges)
    for (std::size_t p = 0; p + 1 < placed.start.size(); ++p)
      for (std::size_t k = placed.start[p]; k < placed.start[p + 1]; ++k)
        g.items[fill[placed.voxels[k]]++] = static_cast<std::uint32_t>(placed.first + p);
  return g;
}

double grid_epsilon(const Aabb& universe) {
  const glm::dvec3 e = universe.extent();
  return 1e-9 * std::max({e.x, e.y, e.z});
}

}  // namespace

Aabb universe_of(std::span<const PreparedPrimitive> prims, const std::vector<bool>& placed) {
  Aabb u;
  for (std::size_t i = 0; i < prims.size(); ++i)
    if (placed[i]) u.extend(prims[i].world_bounds);
  if (u.empty()) return u;
  const glm::dvec3 e = u.extent();
  const double pad = 1e-6 * std::max({e.x, e.y, e.z});
  u.lo -= glm::dvec3(pad);
  u.hi += glm::dvec3(pad);
  return u;
}

VoxelGrid generate_voxels(std::span<const PreparedPrimitive> prims,
                          const std::vector<bool>& placed, const Aabb& universe, int n,
                          VoxelGenCounts* counts, int threads) {
  const glm::dvec3 vs = universe.extent() / static_cast<double>(n);
  const double eps = grid_epsilon(universe);
  // Ranges of a fixed size, placed in parallel: the grid is built from them in
  // primitive order, so it is the same for every thread count. Where the
  // bounding boxes, an upper bound of the entries, might pass the limit, one
  // range, so that placing stops at the primitive that passes it rather than
  // after every thread's range.
  const bool fits = bounding_box_entries(prims, placed, universe, n) <= kMaxVoxelEntries;
  const std::size_t range_size = fits ? kPrimitivesPerRange : std::max<std::size_t>(prims.size(), 1);
  const std::size_t range_count = (prims.size() + range_size - 1) / range_size;
  std::vector<Placements> ranges(range_count);
  std::vector<VoxelGenCounts> range_counts(range_count);
  parallel_rows(threads, static_cast<int>(range_count), [&](const tbb::blocked_range<int>& rs) {
    for (int r = rs.begin(); r != rs.end(); ++r) {
      Placements& out = ranges[r];
      out.first = static_cast<std::size_t>(r) * range_size;
      const std::size_t last = std::min(prims.size(), out.first + range_size);
      out.start.reserve(last - out.first + 1);
      for (std::size_t i = out.first; i < last; ++i) {
        if (placed[i]) place_primitive(prims[i], universe, n, vs, eps, out.voxels, &range_counts[r]);
        out.end_primitive();
        if (out.voxels.size() > kMaxVoxelEntries) {
          throw VoxelGridTooLarge(fmt::format(
              "a voxel grid of {0}x{0}x{0} would hold more than {1} (voxel, primitive) entries, "
              "the most capsim allows",
              n, kMaxVoxelEntries));
        }
      }
    }
  });
  VoxelGrid g = build_grid(universe, n, ranges);
  if (counts) {
    for (const VoxelGenCounts& c : range_counts) *counts += c;
    counts->voxel_entries += g.entries();
    counts->grid_voxels += static_cast<std::uint64_t>(n) * static_cast<std::uint64_t>(n) * static_cast<std::uint64_t>(n);
  }
  return g;
}

std::vector<VoxelGenCounts> voxel_counts_by_primitive(std::span<const PreparedPrimitive> prims,
                                                      const std::vector<bool>& placed, const Aabb& universe,
                                                      int n) {
  const glm::dvec3 vs = universe.extent() / static_cast<double>(n);
  const double eps = grid_epsilon(universe);
  std::vector<VoxelGenCounts> counts(prims.size());
  std::vector<std::uint32_t> voxels;
  for (std::size_t i = 0; i < prims.size(); ++i) {
    if (!placed[i]) continue;
    voxels.clear();
    place_primitive(prims[i], universe, n, vs, eps, voxels, &counts[i]);
    counts[i].voxel_entries = voxels.size();
  }
  return counts;
}

VoxelGrid generate_voxels_aabb(std::span<const PreparedPrimitive> prims,
                               const std::vector<bool>& placed, const Aabb& universe, int n) {
  const glm::dvec3 vs = universe.extent() / static_cast<double>(n);
  const double eps = grid_epsilon(universe);
  Placements placements;
  placements.start.reserve(prims.size() + 1);
  for (std::size_t i = 0; i < prims.size(); ++i) {
    if (placed[i]) place_bounding_box(prims[i].world_bounds, universe, n, vs, eps, placements.voxels);
    placements.end_primitive();
  }
  return build_grid(universe, n, std::span<const Placements>(&placements, 1));
}

std::size_t bounding_box_entries(std::span<const PreparedPrimitive> prims,
                                 const std::vector<bool>& placed, const Aabb& universe, int n) {
  const glm::dvec3 vs = universe.extent() / static_cast<double>(n);
  const double eps = grid_epsilon(universe);
  std::size_t entries = 0;
  for (std::size_t i = 0; i < prims.size(); ++i)
    if (placed[i]) entries += voxel_range(prims[i].world_bounds, universe, n, vs, eps).count();
  return entries;
}

int fitted_grid_divisions(std::span<const PreparedPrimitive> prims,
                          const std::vector<bool>& placed, const Aabb& universe) {
  const auto placed_count = static_cast<std::size_t>(std::count(placed.begin(), placed.end(), true));
  const std::size_t budget =
      std::min(kMaxVoxelEntries, kAutoVoxelEntriesPerPrimitive * placed_count);
  int n = auto_grid_divisions(placed_count);
  while (n > 1 && bounding_box_entries(prims, placed, universe, n) > budget) --n;
  return n;
}

int auto_grid_divisions(std::size_t placed_primitives) {
  // Table 4-2's optimum grows as the cube root of the object count, about twice
  // it (512 objects: 16; 1000: 16-32; 4096: 32; 6859: 32-48: about 8 voxels per
  // object), and is never below 8 (16 objects: 8), where the 3DDDA is still far
  // cheaper than the intersections it saves.
  const double n = std::round(2.0 * std::cbrt(static_cast<double>(placed_primitives)));
  return std::clamp(static_cast<int>(n), 8, 64);
}

}  // namespace capsim
