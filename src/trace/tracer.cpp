// The tracer: partial evaluation along a ray (3DDDA + status tree, voxel by
// voxel) and Whitted shading.

#include "capsim/tracer.h"

#include <algorithm>
#include <cmath>
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
// the back, after any equal ones.
void insert_sorted(std::vector<Crossing>& pending, const Crossing& c) {
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
template <typename AddCrossing>
void take_span(std::uint32_t p, const LineSpan& span, const Ray& ray, Tracer::Scratch& s, OpCounts& ops,
               AddCrossing add) {
  if (span.t_exit <= ray.tmin || span.t_enter >= ray.tmax) return;
  if (span.t_enter <= ray.tmin) {
    // The ray starts inside this primitive: its leaf is inside from the
    // start. Every such primitive holds the start point, so it is met in the
    // first voxel, before any crossing is evaluated.
    s.tree.toggle(p, ops);
  } else {
    add(Crossing{span.t_enter, p, span.enter_surface, true});
    ++ops.hits_sorted;
  }
  if (span.t_exit < ray.tmax) {
    add(Crossing{span.t_exit, p, span.exit_surface, false});
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
                     const std::vector<PreparedPrimitive>& prims, const std::vector<RoundSphereSlot>& spheres,
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
                                          const std::vector<PreparedPrimitive>& prims,
                                          const std::vector<RoundSphereSlot>& spheres, const Ray& ray,
                                          Tracer::Scratch& s, OpCounts& ops) {
  meet_primitives(voxel, prims, spheres, ray, s, ops, [&](const Crossing& c) { s.fresh.push_back(c); });
  merge_fresh(s.pending, s.fresh);
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
  epsilon_ = scene_epsilon(scene);
  crowded_voxels_ = scene.grid.largest_voxel > kCrowdedVoxel;
  spheres_.reserve(scene.prims.size());
  for (const PreparedPrimitive& p : scene.prims) spheres_.push_back(round_sphere_slot(p));
}

Ray Tracer::screen_ray(double u, double v) const {
  const Camera& c = scene_.camera;
  const double px = (2.0 * u / c.width - 1.0) * half_width_;
  const double py = (1.0 - 2.0 * v / c.height) * half_height_;
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

bool Tracer::first_hit(const Ray& ray, Scratch& s, OpCounts& ops, Hit& hit) const {
  return crowded_voxels_ ? walk<true>(ray, s, ops, hit) : walk<false>(ray, s, ops, hit);
}

template <bool kMayBeCrowded>
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
      meet_crowded_voxel(voxel, scene_.prims, spheres_, ray, s, ops);
    } else {
      meet_primitives(voxel, scene_.prims, spheres_, ray, s, ops,
                      [&](const Crossing& c) { insert_sorted(s.pending, c); });
    }
    // Evaluate, nearest first, the crossings inside this voxel; later ones wait
    // for their voxel, where primitives not yet met may come before them.
    const double t_out = dda.t_out();
    while (!s.pending.empty() && s.pending.back().t <= t_out) {
      const Crossing c = s.pending.back();
      s.pending.pop_back();
      if (!s.tree.toggle(c.primitive, ops)) continue;
      hit.t = c.t;
      hit.primitive = c.primitive;
      hit.point = ray.at(c.t);
      hit.entering = s.tree.root_inside();
      const glm::dvec3 n = world_normal(scene_.prims[c.primitive], hit.point, c.surface, ops);
      // The primitive's outward normal, turned to be the solid's: against the
      // ray where the ray enters the solid, along it where it leaves (surfaces
      // that a subtracted primitive contributes face the other way).
      const bool against = glm::dot(n, ray.dir) < 0;
      hit.normal = (against == hit.entering) ? n : -n;
      return true;
    }
    if (!dda.step()) return false;
    ++ops.dda_steps;
  } while (true);
}

bool Tracer::occluded(const glm::dvec3& from, const glm::dvec3& to, Scratch& scratch,
                      OpCounts& ops) const {
  const glm::dvec3 d = to - from;
  const double dist = glm::length(d);
  Ray r{from, d / dist, epsilon_, dist - epsilon_};
  ++ops.rays;
  ++ops.shadow_rays;
  Hit h;
  return first_hit(r, scratch, ops, h);
}

glm::dvec3 Tracer::shade(const Ray& ray, int depth, Scratch& scratch, OpCounts& ops,
                         Hit* first) const {
  ++ops.rays;
  Hit h;
  if (!first_hit(ray, scratch, ops, h)) return scene_.scene.background;
  if (first) *first = h;

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
    if (!options_.primary_only && occluded(h.point, light.position, scratch, ops)) continue;
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
  PixelSample s;
  Hit h;
  h.t = kInfinity;
  ++ops.primary_rays;
  s.color = shade(screen_ray(u, v), 0, scratch, ops, &h);
  if (h.t < kInfinity) {
    s.alpha = 1;
    s.depth = h.t;
    s.primitive = static_cast<int>(h.primitive);
  }
  return s;
}

}  // namespace capsim
