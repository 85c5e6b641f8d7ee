#pragma once
// The paper's tracer: partial evaluation of the CSG scene along a ray, voxel by
// voxel (3DDDA + status tree), and Whitted shading on top of it. Pure: the same
// ray always gives the same answer and the same operation counts.

#include "capsim/trace/dda.h"
#include "capsim/trace/prepared_scene.h"

#include <cstdint>
#include <span>
#include <vector>

namespace capsim {

struct TraceOptions {
  bool primary_only = false;  // primary rays with local shading only: no shadow,
                              // reflection or refraction rays
  int max_depth = 5;          // reflection/refraction recursion limit
  // Tests only: crowded voxels of round spheres test every sphere in turn
  // instead of first asking the voxel's bounding volumes (tracer.cpp), the
  // reference the filtered walk must equal.
  bool unfiltered_crowded_voxels = false;
};

// The visible surface along a ray: the first crossing where the root status of the
// status tree changes.
struct Hit {
  double t = kInfinity;
  std::uint32_t primitive = 0;
  glm::dvec3 point{0};
  glm::dvec3 normal{0};  // outward normal of the CSG solid, unit length
  bool entering = true;  // the ray goes from outside the solid to inside here
  SurfaceId surface = 0;  // of the primitive, where the ray meets it
};

// What one pixel returns: linear colour, coverage, and the primary ray's visible
// distance from the eye (+inf on a miss) and primitive (-1 on a miss).
struct PixelSample {
  glm::dvec3 color{0};
  float alpha = 0;
  double depth = kInfinity;
  int primitive = -1;
  int samples = 1;  // primary samples traced for this pixel (antialiasing traces more)
};

class Tracer {
 public:
  // Per-thread working state: the status tree being evaluated and the mailbox of
  // primitives already intersected by the current ray.
  class Scratch {
   public:
    explicit Scratch(const PreparedScene& scene);
    StatusTree tree;
    std::vector<std::uint32_t> mailbox;  // ray stamp per primitive
    std::uint32_t stamp = 0;
    struct Crossing {
      double t;
      std::uint32_t primitive;
      std::int32_t surface;
      bool enter;  // entering the primitive; at equal t entries go first
    };
    std::vector<Crossing> pending;  // crossings met but not yet evaluated, latest first
    std::vector<Crossing> fresh;    // crossings met in the current voxel, not yet in pending
    std::vector<LineCrossing> leaf_crossings, leaf_work;  // one mesh's crossings, and its hits
    std::vector<std::uint32_t> candidates;  // a filtered voxel's spheres the line may meet
    std::vector<Hit> row_hits;              // shade_primary_row's hits, one a ray
  };

  Tracer(const PreparedScene& scene, TraceOptions options);

  // Partial evaluation: the first root transition in (ray.tmin, ray.tmax), if any.
  bool first_hit(const Ray& ray, Scratch& scratch, OpCounts& ops, Hit& hit) const;
  // Whether first_hit would find a transition, with the same counts added to
  // ops; the hit's point and normal are counted but not worked out (a shadow
  // ray needs neither).
  bool any_hit(const Ray& ray, Scratch& scratch, OpCounts& ops) const;

  // The primary ray through the centre of pixel (i, j), shaded; adds the
  // operations spent on it to ops (the caller sums them per row or per pixel, as
  // it needs, without a fresh set of counts per call).
  PixelSample trace_pixel(int i, int j, Scratch& scratch, OpCounts& ops) const {
    return shade_primary(primary_ray(i, j), scratch, ops);
  }
  // The primary ray through screen point (u, v) in pixel units ((0, 0) is the
  // screen's top-left corner, (W, H) its bottom-right), shaded, as trace_pixel.
  PixelSample trace_screen_point(double u, double v, Scratch& scratch, OpCounts& ops) const;
  // A primary ray shaded: trace_pixel's and trace_screen_point's work after
  // the ray (for rays made by primary_rays).
  PixelSample shade_primary(const Ray& ray, Scratch& scratch, OpCounts& ops) const;
  // out[i] = shade_primary(rays[i], scratch, ops) to the bit, with the same
  // counts, for a row of primary rays: every ray's hit first, then every hit's
  // point and normal, then the shading. A hit's normal and its shading are
  // chains of square roots and divisions that nothing else waits for; taken
  // one pixel after another, each is begun before the last one is done.
  // Precondition: out.size() == rays.size().
  void shade_primary_row(std::span<const Ray> rays, std::span<PixelSample> out, Scratch& scratch,
                         OpCounts& ops) const;
  // The same, each ray's operations added to its own ops[i].
  // Precondition: out.size() == ops.size() == rays.size().
  void shade_primary_row(std::span<const Ray> rays, std::span<PixelSample> out, Scratch& scratch,
                         std::span<OpCounts> ops) const;

  // screen_ray(i + 0.5, j + 0.5), to the bit: on the camera's screen, from
  // the offsets of the pixels' centres worked out once (two divisions fewer
  // a ray).
  Ray primary_ray(int i, int j) const {
    if (static_cast<unsigned>(i) < half_x_.size() / 2 && static_cast<unsigned>(j) < half_y_.size() / 2)
      return ray_through(half_x_[2 * static_cast<unsigned>(i) + 1], half_y_[2 * static_cast<unsigned>(j) + 1]);
    return screen_ray(i + 0.5, j + 0.5);
  }
  // screen_ray(u, v), to the bit: at the pixels' corners and centres on the
  // camera's screen (u and v whole or half, as antialiasing's corner samples
  // and the pixels' centres are) from the same offsets worked out once.
  Ray screen_point_ray(double u, double v) const;
  // The primary rays of row j, rays[i] = primary_ray(i, j) to the bit for i
  // below rays.size(), made together: one pixel's square root and division do
  // not wait for the last one's, and the compiler issues them two at a time
  // (SSE2's packed square root and division round as the scalar ones do).
  void primary_rays(int j, std::span<Ray> rays) const;
  // The rays through the pixel corners of corner row y (antialiasing's corner
  // samples), rays[x] = screen_point_ray(x, y) to the bit, made together as
  // primary_rays makes a row's.
  void corner_rays(int y, std::span<Ray> rays) const;
  Ray screen_ray(double u, double v) const;
  const PreparedScene& scene() const { return scene_; }
  const TraceOptions& options() const { return options_; }

  // A crowded voxel made only of round spheres: a bounding-volume hierarchy
  // over their boxes, which names the spheres a line may meet (tracer.cpp).
  struct SphereFilter {
    struct Node {
      glm::dvec3 lo, hi;
      std::uint32_t first = 0;  // leaf: its first entry in `order`; inner: its right child
      std::uint32_t count = 0;  // leaf: its spheres; 0: inner, its left child next
    };
    int voxel = 0;
    std::vector<Node> nodes;  // nodes[0] is the root
    std::vector<std::uint32_t> order;  // positions in the voxel's list, leaf by leaf
    // The voxel's primitives that some other voxel holds too, in the voxel's
    // order: the only ones a ray can have met before it comes here, or meet
    // again after it leaves.
    std::vector<std::uint32_t> shared;
    glm::dvec3 center{0};  // of the spheres' box, and
    double reach = 0;      // its half diagonal: the scale of the filter's rounding margin
  };

 private:
  // first_hit's walk; kMayBeCrowded: some voxel holds so many primitives that
  // their crossings are merged into the pending ones at once (tracer.cpp).
  // kWork: what the walk does at the visible crossing.
  enum class HitWork {
    kCount,     // count the hit's point and normal, work nothing out (any_hit)
    kFind,      // fill the hit's distance, primitive, surface and side, and
                // leave its point and normal to complete_hit (a row's pass)
    kComplete,  // fill the whole hit (first_hit)
  };
  template <bool kMayBeCrowded, HitWork kWork>
  bool walk(const Ray& ray, Scratch& scratch, OpCounts& ops, Hit& hit) const;
  // The point and the solid's normal of a hit the walk found along `ray`.
  void complete_hit(const Ray& ray, Hit& hit, OpCounts& ops) const;
  const SphereFilter* filter(int voxel) const;  // the voxel's, if it has one
  // The colour seen along the ray; primary, if given, also receives the
  // coverage, distance and primitive of what the ray meets (a miss leaves it).
  glm::dvec3 shade(const Ray& ray, int depth, Scratch& scratch, OpCounts& ops, PixelSample* primary) const;
  // shade_primary_row with ray i's operations added to ops_of(i).
  template <class OpsOf>
  void shade_row(std::span<const Ray> rays, std::span<PixelSample> out, Scratch& scratch, OpsOf ops_of) const;
  // shade's colour of a completed hit along the ray: lights, then reflection
  // and refraction below max_depth.
  glm::dvec3 shade_hit(const Ray& ray, const Hit& h, int depth, Scratch& scratch, OpCounts& ops) const;
  // The ray through the screen point at offsets (px, py) from the screen's
  // centre, in units of half_width_ and half_height_ (screen_ray's).
  Ray ray_through(double px, double py) const;
  // primary_rays (parity 1: the pixels' centres) and corner_rays (parity 0:
  // their corners): rays[i] through the tables' offsets 2i + parity and
  // 2 row + parity.
  void table_rays(unsigned parity, int row, std::span<Ray> rays) const;
  double screen_x(double u) const;  // screen_ray's offsets of screen point (u, v)
  double screen_y(double v) const;
  // Whether a surface lies on the segment from `from` along the unit
  // direction `dir` for `dist` (a shadow ray to a light that far away; shade
  // has the direction and the distance already); counts one shadow ray.
  bool occluded(const glm::dvec3& from, const glm::dvec3& dir, double dist, Scratch& scratch,
                OpCounts& ops) const;

  const PreparedScene& scene_;
  TraceOptions options_;
  glm::dvec3 cam_origin_, cam_forward_, cam_right_, cam_up_;
  double half_height_ = 1, half_width_ = 1;  // orthographic: in scene units, else per unit of depth
  // screen_ray's px of u = k / 2 and py of v = k / 2, for k = 0 .. 2W and 0 .. 2H:
  // the offsets of the pixels' corners (k even) and centres (k odd).
  std::vector<double> half_x_, half_y_;
  bool orthographic_ = false;
  double epsilon_ = 0;  // offset of spawned rays, relative to the universe size
  bool crowded_voxels_ = false;  // the walk must watch for crowded voxels
  std::vector<RoundSphereSlot> spheres_;  // per primitive, as scene_.prims
  std::vector<SphereFilter> filters_;     // in ascending voxel order
};

}  // namespace capsim
