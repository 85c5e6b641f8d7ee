// The tracer: partial evaluation along a ray (3DDDA + status tree, voxel by
// voxel) and Whitted shading.

#include "capsim/trace/tracer.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>

namespace capsim {

namespace {

using Crossing = Tracer::Scratch::Crossing;

// The order crossings are evaluated in: nearest first; at equal t entries before
// exits (solids that touch in a union leave no gap), then by primitive index, so
// the order depends on nothing but the scene.
bool later(const Crossing& a, const Crossing& b) {
  if (a.t != b.t) return a.t > b.t;
  if (a.enter != b.enter) return b.enter;
  return a.primitive > b.primitive;
}

// Pending crossings are few (those of the primitives met so far that lie
// beyond the current voxel), so a vector kept sorted latest-first, with the
// nearest at the back, beats a heap; a new crossing enters by insertion from
// the back, after any equal ones. Always inline: the crossing was built a
// moment before, field by field, and a call passes it through memory, where
// the copy's wide loads wait for all of those stores to be done.
[[gnu::always_inline]] inline void insert_sorted(std::vector<Crossing>& pending, const Crossing& c) {
  pending.push_back(c);
  std::size_t k = pending.size() - 1;
  for (; k > 0 && later(c, pending[k - 1]); --k) pending[k] = pending[k - 1];
  pending[k] = c;
}

// Moves `fresh` (crossings in no order) into `pending` (sorted latest-first):
// sorted, then merged from the back, in O(m log m) plus the pending crossings
// nearer than the latest new one. `later` orders the crossings of a ray
// strictly (a primitive's crossings along a ray lie at distinct t), so the result is
// the one that inserting them one by one gives.
void merge_fresh(std::vector<Crossing>& pending, std::vector<Crossing>& fresh) {
  std::sort(fresh.begin(), fresh.end(), [](const Crossing& a, const Crossing& b) { return later(a, b); });
  std::size_t old_end = pending.size(), next = fresh.size();
  pending.resize(old_end + next);
  std::size_t out = pending.size();
  while (next > 0) {
    if (old_end > 0 && later(fresh[next - 1], pending[old_end - 1])) {
      pending[--out] = pending[--old_end];
    } else {
      pending[--out] = fresh[--next];
    }
  }
  fresh.clear();
}

// A mesh or a revolution met by the ray: a leaf with any number of intervals along it. As a
// convex primitive's, a crossing at or before the ray's start sets the leaf's
// state there, and every crossing ahead goes to `add`.
template <typename AddCrossing>
void meet_many_intervals(std::uint32_t p, const PreparedPrimitive& prim, const Ray& ray, Tracer::Scratch& s, OpCounts& ops,
               AddCrossing add) {
  leaf_crossings(prim, ray, s.leaf_crossings, s.leaf_work, ops);
  bool inside_at_start = false;
  for (const LineCrossing& c : s.leaf_crossings) {
    if (c.t <= ray.tmin) {
      inside_at_start = c.enter;
    } else if (c.t < ray.tmax) {
      add(Crossing{c.t, p, c.surface, c.enter});
      ++ops.hits_sorted;
    }
  }
  if (inside_at_start) s.tree.toggle(p, ops);
}

// A convex primitive's span along the ray: one the ray starts in toggles
// its leaf at once, every crossing ahead goes to `add`.
//
// The exit goes first. The pending crossings' order is the one `later`
// sets whatever order they come in, and an entry added after its exit
// usually belongs at the back, where the nearest crossing is. Added the
// other way, the exit had to move the entry up a place, just after the
// entry's stores, which the moving loads must wait for.
template <typename AddCrossing>
void take_span(std::uint32_t p, const LineSpan& span, const Ray& ray, Tracer::Scratch& s, OpCounts& ops,
               AddCrossing add) {
  if (span.t_exit <= ray.tmin || span.t_enter >= ray.tmax) return;
  const bool starts_inside = span.t_enter <= ray.tmin;
  if (starts_inside) {
    // The ray starts inside this primitive: its leaf is inside from the
    // start. Every such primitive holds the start point, so it is met in the
    // first voxel, before any crossing is evaluated.
    s.tree.toggle(p, ops);
  }
  if (span.t_exit < ray.tmax) {
    add(Crossing{span.t_exit, p, span.exit_surface, false});
    ++ops.hits_sorted;
  }
  if (!starts_inside) {
    add(Crossing{span.t_enter, p, span.enter_surface, true});
    ++ops.hits_sorted;
  }
}

// A round sphere, from its packed slot.
template <typename AddCrossing>
void meet_round_sphere(std::uint32_t p, const RoundSphereSlot& sphere, const Ray& ray, Tracer::Scratch& s,
                       OpCounts& ops, AddCrossing add) {
  LineSpan span;
  if (intersect_round_sphere(ray.origin - sphere.center, ray.dir, sphere.r2, span)) take_span(p, span, ray, s, ops, add);
}

// Any primitive but a round sphere.
template <typename AddCrossing>
void meet_other(std::uint32_t p, const PreparedPrimitive& prim, const Ray& ray, Tracer::Scratch& s, OpCounts& ops,
                AddCrossing add) {
  if (has_many_intervals(prim.kind)) return meet_many_intervals(p, prim, ray, s, ops, add);
  LineSpan span;
  if (intersect_line(prim, ray, span, ops)) take_span(p, span, ray, s, ops, add);
}

// Intersects the primitives of one voxel that the ray has not met yet (the
// mailbox), in the voxel's order.
template <typename AddCrossing>
void meet_primitives(std::span<const std::uint32_t> voxel,
                     std::span<const PreparedPrimitive> prims, const std::vector<RoundSphereSlot>& spheres,
                     const Ray& ray, Tracer::Scratch& s, OpCounts& ops, AddCrossing add) {
  for (const std::uint32_t p : voxel) {
    if (s.mailbox[p] == s.stamp) continue;
    s.mailbox[p] = s.stamp;
    if (const RoundSphereSlot& sphere = spheres[p]; sphere.r2 >= 0) {
      ++ops.sphere_tests;
      meet_round_sphere(p, sphere, ray, s, ops, add);
    } else {
      meet_other(p, prims[p], ray, s, ops, add);
    }
  }
}

// A voxel usually holds a few primitives, whose crossings enter the pending
// ones one by one. One that holds more (up to thousands of coincident
// primitives) has its crossings gathered and merged at once: one by one, the
// m crossings would cost O(m^2).
constexpr std::size_t kCrowdedVoxel = 8;

[[gnu::noinline]] void meet_crowded_voxel(std::span<const std::uint32_t> voxel,
                                          std::span<const PreparedPrimitive> prims,
                                          const std::vector<RoundSphereSlot>& spheres, const Ray& ray,
                                          Tracer::Scratch& s, OpCounts& ops) {
  meet_primitives(voxel, prims, spheres, ray, s, ops, [&](const Crossing& c) { s.fresh.push_back(c); });
  merge_fresh(s.pending, s.fresh);
}

// A voxel of this many round spheres or more (the paper's lattices on coarse
// grids put up to 6,859 in one) has a SphereFilter: a line meets few of
// them, and testing each in turn took most of `capsim repro`'s time.
constexpr std::size_t kFilteredVoxel = 32;
constexpr std::uint32_t kFilterLeaf = 4;
using SphereFilter = Tracer::SphereFilter;

// The filter of a voxel whose entries are all round spheres, or none. Median
// splits along the longest axis of the centres keep the depth at most
// log2 of the spheres, well within traverse()'s stack. `placements` counts,
// per primitive, its entries in the whole grid.
std::optional<SphereFilter> build_sphere_filter(int v, std::span<const std::uint32_t> voxel,
                                                const std::vector<RoundSphereSlot>& spheres,
                                                const std::vector<std::uint32_t>& placements) {
  SphereFilter f;
  f.voxel = v;
  std::vector<Aabb> boxes;
  boxes.reserve(voxel.size());
  for (const std::uint32_t p : voxel) {
    const RoundSphereSlot& slot = spheres[p];
    if (slot.r2 < 0) return std::nullopt;
    const double r = std::sqrt(slot.r2);
    boxes.push_back(Aabb{slot.center - r, slot.center + r});
    if (placements[p] > 1) f.shared.push_back(p);
  }
  f.order.resize(voxel.size());
  for (std::uint32_t k = 0; k < f.order.size(); ++k) f.order[k] = k;
  const auto bounds = [&](std::uint32_t first, std::uint32_t count) {
    Aabb b{boxes[f.order[first]].lo, boxes[f.order[first]].hi};
    for (std::uint32_t k = first + 1; k < first + count; ++k) {
      b.lo = glm::min(b.lo, boxes[f.order[k]].lo);
      b.hi = glm::max(b.hi, boxes[f.order[k]].hi);
    }
    return b;
  };
  const auto build = [&](auto& self, std::uint32_t first, std::uint32_t count) -> void {
    const std::uint32_t node = static_cast<std::uint32_t>(f.nodes.size());
    const Aabb b = bounds(first, count);
    f.nodes.push_back({b.lo, b.hi, first, count});
    if (count <= kFilterLeaf) return;
    glm::dvec3 lo = boxes[f.order[first]].center(), hi = lo;
    for (std::uint32_t k = first + 1; k < first + count; ++k) {
      lo = glm::min(lo, boxes[f.order[k]].center());
      hi = glm::max(hi, boxes[f.order[k]].center());
    }
    const glm::dvec3 spread = hi - lo;
    const int axis = spread.x >= spread.y && spread.x >= spread.z ? 0 : (spread.y >= spread.z ? 1 : 2);
    const std::uint32_t half = count / 2;
    const auto begin = f.order.begin() + first;
    std::nth_element(begin, begin + half, begin + count, [&](std::uint32_t a, std::uint32_t b) {
      const double ca = boxes[a].center()[axis], cb = boxes[b].center()[axis];
      return ca != cb ? ca < cb : a < b;
    });
    f.nodes[node].count = 0;
    self(self, first, half);
    f.nodes[node].first = static_cast<std::uint32_t>(f.nodes.size());
    self(self, first + half, count - half);
  };
  build(build, 0, static_cast<std::uint32_t>(voxel.size()));
  f.center = 0.5 * (f.nodes[0].lo + f.nodes[0].hi);
  f.reach = 0.5 * glm::length(f.nodes[0].hi - f.nodes[0].lo);
  return f;
}

// Calls visit(k) for every position k of the filter's voxel whose sphere's box,
// grown by `margin` on every side, the whole line origin + t dir meets.
template <typename Visit>
void traverse(const SphereFilter& f, const Ray& ray, double margin, Visit visit) {
  glm::dvec3 inv;
  bool parallel[3];
  for (int i = 0; i < 3; ++i) {
    inv[i] = 1.0 / ray.dir[i];
    // A direction component too small to invert leaves the line within the
    // margin of its slab's plane over the whole filter: tested by the origin.
    parallel[i] = !std::isfinite(inv[i]);
  }
  const auto meets = [&](const SphereFilter::Node& n) {
    double near = -kInfinity, far = kInfinity;
    for (int i = 0; i < 3; ++i) {
      const double lo = n.lo[i] - margin, hi = n.hi[i] + margin;
      if (parallel[i]) {
        if (!(ray.origin[i] >= lo && ray.origin[i] <= hi)) return false;
        continue;
      }
      const double t1 = (lo - ray.origin[i]) * inv[i], t2 = (hi - ray.origin[i]) * inv[i];
      near = std::max(near, std::min(t1, t2));
      far = std::min(far, std::max(t1, t2));
    }
    return near <= far;
  };
  std::uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const SphereFilter::Node& n = f.nodes[stack[--top]];
    if (!meets(n)) continue;
    if (n.count == 0) {
      const std::uint32_t here = static_cast<std::uint32_t>(&n - f.nodes.data());
      stack[top++] = n.first;
      stack[top++] = here + 1;
    } else {
      for (std::uint32_t k = n.first; k < n.first + n.count; ++k) visit(f.order[k]);
    }
  }
}

// meet_crowded_voxel for a voxel with a filter, to the bit: the same
// crossings in the same order, the same toggles and counts. Every sphere the
// ray has not met yet counts as a test, as the machine makes one; only those
// the filter names are intersected, in the voxel's order. Only the shared
// spheres are looked up and stamped in the mailbox: a sphere no other voxel
// holds cannot have been met before this voxel, and the walk never asks for
// it again (on the coarsest grids, the lattice's thousands of spheres in one
// voxel, that is all of them).
// The margin covers the rounding of the filter's boxes and slab tests and of
// intersect_round_sphere, each within a few ulps of the coordinates' scale
// (the origin's, the spheres'); a sphere whose exact test succeeds is never
// passed over.
[[gnu::noinline]] void meet_filtered_voxel(std::span<const std::uint32_t> voxel, const SphereFilter& f,
                                           const std::vector<RoundSphereSlot>& spheres, const Ray& ray,
                                           Tracer::Scratch& s, OpCounts& ops) {
  const double scale = glm::length(ray.origin) + glm::length(f.center) + f.reach;
  std::vector<std::uint32_t>& candidates = s.candidates;
  candidates.clear();
  traverse(f, ray, 1e-8 * scale, [&](std::uint32_t k) {
    if (s.mailbox[voxel[k]] != s.stamp) candidates.push_back(k);
  });
  const std::uint32_t stamp = s.stamp;
  std::uint32_t* const mailbox = s.mailbox.data();
  std::uint64_t met = 0;
  for (const std::uint32_t p : f.shared) {
    met += mailbox[p] == stamp;
    mailbox[p] = stamp;
  }
  ops.sphere_tests += voxel.size() - met;
  std::sort(candidates.begin(), candidates.end());
  const auto add = [&](const Crossing& c) { s.fresh.push_back(c); };
  for (const std::uint32_t k : candidates) meet_round_sphere(voxel[k], spheres[voxel[k]], ray, s, ops, add);
  merge_fresh(s.pending, s.fresh);
}

// What a primary sample keeps of the surface its ray sees, besides the colour.
void record_visible(const Hit& h, PixelSample& s) {
  s.alpha = 1;
  s.depth = h.t;
  s.primitive = static_cast<int>(h.primitive);
}

// x^e for the Phong highlight. Whole exponents (as materials usually give) go by
// repeated squaring, a few multiplications where pow() costs some seventy
// instructions per light per hit; others fall back to pow().
double highlight_power(double x, double e) {
  if (e >= 0 && e <= 1024 && e == static_cast<double>(static_cast<unsigned>(e))) {
    auto n = static_cast<unsigned>(e);
    double result = 1, base = x;
    while (n) {
      if (n & 1u) result *= base;
      base *= base;
      n >>= 1;
    }
    return result;
  }
  return std::pow(x, e);
}

double scene_epsilon(const PreparedScene& s) {
  return 1e-7 * glm::length(s.grid.universe.extent());
}

// Tracer::complete_hit: the point and the solid's normal of a hit the walk
// found along `ray`. Always inlined: at the end of first_hit's walk it is
// what the normal's chain of operations starts from.
[[gnu::always_inline]] inline void complete(const Ray& ray, Hit& hit, const std::vector<RoundSphereSlot>& spheres,
                                            std::span<const PreparedPrimitive> prims, OpCounts& ops) {
  hit.point = ray.at(hit.t);
  // A round sphere's normal comes from the packed slot the walk reads
  // already, not from the primitive's record.
  const RoundSphereSlot& sphere = spheres[hit.primitive];
  const glm::dvec3 n = sphere.r2 >= 0 ? round_sphere_normal(sphere.center, hit.point, ops)
                                      : world_normal(prims[hit.primitive], hit.point, hit.surface, ops);
  // The primitive's outward normal, turned to be the solid's: against the
  // ray where the ray enters the solid, along it where it leaves (surfaces
  // that a subtracted primitive contributes face the other way).
  const bool against = glm::dot(n, ray.dir) < 0;
  hit.normal = (against == hit.entering) ? n : -n;
}

}  // namespace

Tracer::Scratch::Scratch(const PreparedScene& scene)
    : tree(scene.tree_template), mailbox(scene.prims.size(), 0) {}

Tracer::Tracer(const PreparedScene& scene, TraceOptions options)
    : scene_(scene), options_(options) {
  const Camera& c = scene.camera;
  cam_origin_ = c.eye;
  cam_forward_ = glm::normalize(c.center - c.eye);
  cam_right_ = glm::normalize(glm::cross(cam_forward_, c.up));
  cam_up_ = glm::cross(cam_right_, cam_forward_);
  half_height_ = std::tan(0.5 * c.fov_deg * std::acos(-1.0) / 180.0);
  orthographic_ = c.projection == Projection::Orthographic;
  if (orthographic_) half_height_ *= glm::length(c.center - c.eye);
  half_width_ = half_height_ * static_cast<double>(c.width) / c.height;
  half_x_.resize(2 * static_cast<std::size_t>(std::max(c.width, 0)) + 1);
  half_y_.resize(2 * static_cast<std::size_t>(std::max(c.height, 0)) + 1);
  for (std::size_t k = 0; k < half_x_.size(); ++k) half_x_[k] = screen_x(0.5 * static_cast<double>(k));
  for (std::size_t k = 0; k < half_y_.size(); ++k) half_y_[k] = screen_y(0.5 * static_cast<double>(k));
  epsilon_ = scene_epsilon(scene);
  crowded_voxels_ = scene.grid.largest_voxel > kCrowdedVoxel;
  spheres_.reserve(scene.prims.size());
  for (const PreparedPrimitive& p : scene.prims) spheres_.push_back(round_sphere_slot(p));
  if (!crowded_voxels_ || options.unfiltered_crowded_voxels || scene.grid.largest_voxel < kFilteredVoxel) return;
  const VoxelGrid& grid = scene.grid;
  const int voxels = grid.n * grid.n * grid.n;
  std::vector<std::uint32_t> placements(scene.prims.size(), 0);
  for (const std::uint32_t p : grid.items) ++placements[p];
  for (int v = 0; v < voxels; ++v) {
    if (grid.offsets[v + 1] - grid.offsets[v] < kFilteredVoxel) continue;
    if (auto f = build_sphere_filter(v, grid.voxel(v), spheres_, placements)) filters_.push_back(std::move(*f));
  }
}

const Tracer::SphereFilter* Tracer::filter(int v) const {
  const auto it = std::lower_bound(filters_.begin(), filters_.end(), v,
                                   [](const SphereFilter& f, int voxel) { return f.voxel < voxel; });
  return it != filters_.end() && it->voxel == v ? &*it : nullptr;
}

double Tracer::screen_x(double u) const { return (2.0 * u / scene_.camera.width - 1.0) * half_width_; }
double Tracer::screen_y(double v) const { return (1.0 - 2.0 * v / scene_.camera.height) * half_height_; }

Ray Tracer::screen_ray(double u, double v) const { return ray_through(screen_x(u), screen_y(v)); }

Ray Tracer::screen_point_ray(double u, double v) const {
  // 2u and 2v are exact; a whole one in the tables' range is a table's index.
  const double ku = 2.0 * u, kv = 2.0 * v;
  if (ku >= 0 && kv >= 0 && ku < static_cast<double>(half_x_.size()) && kv < static_cast<double>(half_y_.size())) {
    const auto iu = static_cast<std::size_t>(ku), iv = static_cast<std::size_t>(kv);
    if (static_cast<double>(iu) == ku && static_cast<double>(iv) == kv) return ray_through(half_x_[iu], half_y_[iv]);
  }
  return screen_ray(u, v);
}

void Tracer::primary_rays(int j, std::span<Ray> rays) const { table_rays(1, j, rays); }

void Tracer::corner_rays(int y, std::span<Ray> rays) const { table_rays(0, y, rays); }

void Tracer::table_rays(unsigned parity, int row, std::span<Ray> rays) const {
  // One ray as primary_ray (pixel centres) or screen_point_ray (corners) makes
  // it; those take the same offsets from the tables wherever the loop below does.
  const auto single = [&](std::size_t i) {
    return parity ? primary_ray(static_cast<int>(i), row) : screen_point_ray(static_cast<double>(i), row);
  };
  const std::size_t ky = 2 * static_cast<std::size_t>(row) + parity;
  if (orthographic_ || row < 0 || ky >= half_y_.size()) {
    for (std::size_t i = 0; i < rays.size(); ++i) rays[i] = single(i);
    return;
  }
  const std::size_t columns = std::min(rays.size(), (half_x_.size() + 1 - parity) / 2);
  // ray_through's arithmetic in its order, written out per component:
  // glm::normalize(v) is v * (1 / sqrt(dot(v, v))), dot(v, v) is
  // (x * x + y * y) + z * z, and the row's py * cam_up_ is the same for every
  // ray. A block's scales first, in a loop of nothing else, which the
  // compiler vectorizes; then its rays, their directions worked out again the
  // same way.
  const glm::dvec3 up = half_y_[ky] * cam_up_;
  const auto direction = [&](std::size_t i) {
    const double p = half_x_[2 * i + parity];
    return glm::dvec3((cam_forward_.x + p * cam_right_.x) + up.x, (cam_forward_.y + p * cam_right_.y) + up.y,
                      (cam_forward_.z + p * cam_right_.z) + up.z);
  };
  constexpr std::size_t kBlock = 64;
  double scale[kBlock];
  for (std::size_t first = 0; first < columns; first += kBlock) {
    const std::size_t count = std::min(kBlock, columns - first);
    for (std::size_t k = 0; k < count; ++k) {
      const glm::dvec3 v = direction(first + k);
      scale[k] = 1.0 / std::sqrt((v.x * v.x + v.y * v.y) + v.z * v.z);
    }
    for (std::size_t k = 0; k < count; ++k) {
      Ray& r = rays[first + k];
      r.origin = cam_origin_;
      r.dir = direction(first + k) * scale[k];
      r.tmin = 0;
      r.tmax = kInfinity;
    }
  }
  for (std::size_t i = columns; i < rays.size(); ++i) rays[i] = single(i);
}

Ray Tracer::ray_through(double px, double py) const {
  Ray r;
  if (orthographic_) {
    r.origin = cam_origin_ + px * cam_right_ + py * cam_up_;
    r.dir = cam_forward_;
  } else {
    r.origin = cam_origin_;
    r.dir = glm::normalize(cam_forward_ + px * cam_right_ + py * cam_up_);
  }
  return r;
}

void Tracer::complete_hit(const Ray& ray, Hit& hit, OpCounts& ops) const {
  complete(ray, hit, spheres_, scene_.prims, ops);
}

bool Tracer::first_hit(const Ray& ray, Scratch& s, OpCounts& ops, Hit& hit) const {
  return crowded_voxels_ ? walk<true, HitWork::kComplete>(ray, s, ops, hit)
                         : walk<false, HitWork::kComplete>(ray, s, ops, hit);
}

bool Tracer::any_hit(const Ray& ray, Scratch& s, OpCounts& ops) const {
  Hit unused;
  return crowded_voxels_ ? walk<true, HitWork::kCount>(ray, s, ops, unused)
                         : walk<false, HitWork::kCount>(ray, s, ops, unused);
}

template <bool kMayBeCrowded, Tracer::HitWork kWork>
bool Tracer::walk(const Ray& ray, Scratch& s, OpCounts& ops, Hit& hit) const {
  const VoxelGrid& grid = scene_.grid;
  if (++s.stamp == 0) {
    std::fill(s.mailbox.begin(), s.mailbox.end(), 0);
    s.stamp = 1;
  }
  s.tree.reset();
  s.pending.clear();

  Dda3 dda;
  if (!dda.setup(grid, ray)) return false;
  ++ops.dda_setups;
  do {
    // Intersect only this voxel's primitives, each once per ray (the mailbox).
    const std::span<const std::uint32_t> voxel = grid.voxel(dda.voxel());
    if (!voxel.empty()) ++ops.voxel_passes;  // Algorithm-4 applied in this voxel (§2.3)
    if (kMayBeCrowded && voxel.size() > kCrowdedVoxel) {
      const SphereFilter* f = voxel.size() >= kFilteredVoxel ? filter(dda.voxel()) : nullptr;
      if (f) {
        meet_filtered_voxel(voxel, *f, spheres_, ray, s, ops);
      } else {
        meet_crowded_voxel(voxel, scene_.prims, spheres_, ray, s, ops);
      }
    } else {
      meet_primitives(voxel, scene_.prims, spheres_, ray, s, ops,
                      [&](const Crossing& c) { insert_sorted(s.pending, c); });
    }
    // Evaluate, nearest first, the crossings inside this voxel; later ones wait
    // for their voxel, where primitives not yet met may come before them.
    const double t_out = dda.t_out();
    while (!s.pending.empty() && s.pending.back().t <= t_out) {
      // Only the fields used, read one by one: the crossing may have been
      // written a moment ago, field by field, and a load spanning fields
      // would wait for all of its stores.
      const double t = s.pending.back().t;
      const std::uint32_t primitive = s.pending.back().primitive;
      const SurfaceId surface = s.pending.back().surface;
      s.pending.pop_back();
      if (!s.tree.toggle(primitive, ops)) continue;
      if constexpr (kWork == HitWork::kCount) {
        ops.matvec += spheres_[primitive].r2 >= 0 ? kRoundSphereNormalMatvecs
                                                  : world_normal_matvecs(scene_.prims[primitive], surface);
        return true;
      }
      hit.t = t;
      hit.primitive = primitive;
      hit.surface = surface;
      hit.entering = s.tree.root_inside();
      if constexpr (kWork == HitWork::kComplete) complete(ray, hit, spheres_, scene_.prims, ops);
      return true;
    }
    if (!dda.step()) return false;
    ++ops.dda_steps;
  } while (true);
}

bool Tracer::occluded(const glm::dvec3& from, const glm::dvec3& dir, double dist, Scratch& scratch,
                      OpCounts& ops) const {
  Ray r{from, dir, epsilon_, dist - epsilon_};
  ++ops.rays;
  ++ops.shadow_rays;
  return any_hit(r, scratch, ops);
}

glm::dvec3 Tracer::shade(const Ray& ray, int depth, Scratch& scratch, OpCounts& ops,
                         PixelSample* primary) const {
  ++ops.rays;
  Hit h;
  if (!first_hit(ray, scratch, ops, h)) return scene_.scene.background;
  if (primary) record_visible(h, *primary);
  return shade_hit(ray, h, depth, scratch, ops);
}

glm::dvec3 Tracer::shade_hit(const Ray& ray, const Hit& h, int depth, Scratch& scratch, OpCounts& ops) const {
  const Primitive& prim = scene_.scene.primitives[h.primitive];
  const Material& m = prim.material;
  const glm::dvec3 facing = glm::dot(h.normal, ray.dir) < 0 ? h.normal : -h.normal;
  const glm::dvec3 view = -ray.dir;

  glm::dvec3 local = m.ambient * prim.color;
  for (const Light& light : scene_.lights) {
    ++ops.shading_evals;
    const glm::dvec3 to_light = light.position - h.point;
    const double dist = glm::length(to_light);
    if (dist == 0) continue;
    const glm::dvec3 l = to_light / dist;
    const double ndl = glm::dot(facing, l);
    if (ndl <= 0) continue;
    if (!options_.primary_only && occluded(h.point, l, dist, scratch, ops)) continue;
    const glm::dvec3 r = glm::reflect(-l, facing);
    const double spec = highlight_power(std::max(0.0, glm::dot(r, view)), m.shininess);
    local += light.color * (m.diffuse * ndl * prim.color + m.specular * spec);
  }
  if (options_.primary_only || depth >= options_.max_depth || (m.reflect == 0 && m.transmit == 0))
    return local;

  glm::dvec3 color = (1.0 - m.reflect - m.transmit) * local;
  const glm::dvec3 mirror = glm::reflect(ray.dir, facing);
  if (m.reflect > 0) {
    ++ops.secondary_rays;
    color += m.reflect * shade(Ray{h.point, mirror, epsilon_}, depth + 1, scratch, ops, nullptr);
  }
  if (m.transmit > 0) {
    // Snell's law across the solid's surface; the hit says which side is inside.
    const double eta = h.entering ? 1.0 / m.ior : m.ior;
    const double cos_i = -glm::dot(facing, ray.dir);
    const double k = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
    const glm::dvec3 dir = k < 0 ? mirror  // total internal reflection
                                 : glm::normalize(eta * ray.dir + (eta * cos_i - std::sqrt(k)) * facing);
    ++ops.secondary_rays;
    color += m.transmit * shade(Ray{h.point, dir, epsilon_}, depth + 1, scratch, ops, nullptr);
  }
  return color;
}

PixelSample Tracer::trace_screen_point(double u, double v, Scratch& scratch, OpCounts& ops) const {
  return shade_primary(screen_point_ray(u, v), scratch, ops);
}

PixelSample Tracer::shade_primary(const Ray& ray, Scratch& scratch, OpCounts& ops) const {
  PixelSample s;
  ++ops.primary_rays;
  s.color = shade(ray, 0, scratch, ops, &s);
  return s;
}

void Tracer::shade_primary_row(std::span<const Ray> rays, std::span<PixelSample> out, Scratch& scratch,
                               OpCounts& ops) const {
  shade_row(rays, out, scratch, [&](std::size_t) -> OpCounts& { return ops; });
}

void Tracer::shade_primary_row(std::span<const Ray> rays, std::span<PixelSample> out, Scratch& scratch,
                               std::span<OpCounts> ops) const {
  shade_row(rays, out, scratch, [&](std::size_t i) -> OpCounts& { return ops[i]; });
}

template <class OpsOf>
void Tracer::shade_row(std::span<const Ray> rays, std::span<PixelSample> out, Scratch& scratch,
                       OpsOf ops_of) const {
  // shade_primary's work, pixel by pixel, in three passes; a miss keeps the
  // sample's primitive at -1.
  std::vector<Hit>& hits = scratch.row_hits;
  hits.resize(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) {
    OpCounts& ops = ops_of(i);
    ++ops.primary_rays;
    ++ops.rays;
    PixelSample& s = out[i];
    s = PixelSample{};
    Hit& h = hits[i];
    const bool found = crowded_voxels_ ? walk<true, HitWork::kFind>(rays[i], scratch, ops, h)
                                       : walk<false, HitWork::kFind>(rays[i], scratch, ops, h);
    if (found) record_visible(h, s);
  }
  for (std::size_t i = 0; i < rays.size(); ++i)
    if (out[i].primitive >= 0) complete_hit(rays[i], hits[i], ops_of(i));
  for (std::size_t i = 0; i < rays.size(); ++i)
    out[i].color =
        out[i].primitive >= 0 ? shade_hit(rays[i], hits[i], 0, scratch, ops_of(i)) : scene_.scene.background;
}

}  // namespace capsim
