#pragma once
// Judging the tracer's first_hit against the oracle, ray by ray, with the
// tolerances of docs/testing.md ("Oracle test").
//
// Distances are compared as world lengths (|dt| * |dir|) relative to the ray's
// scale S = the universe's diagonal + the origin's distance from its centre: the
// size of the numbers both sides compute with. A disagreement is excused only at
// a grazing configuration, where the exact answer turns on a rounding error.

#include "oracle/oracle_roth.h"

#include "capsim/trace/tracer.h"

#include <fmt/core.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace oracle {

struct Tolerance {
  double t_rel = 1e-9;       // agreement: |dt| * |dir| <= t_rel * S
  double normal = 1e-6;      // agreement: |n_tracer - n_oracle|
  double graze_rel = 1e-7;   // grazing: lengths below graze_rel * S
  double graze_cos = 1e-5;   // grazing: |cos(normal, dir)| below this
  // Near a pointed cone's apex the quadric's two roots merge, so t loses digits
  // on both sides (observed: 1e-8 relative at 1e-7 from the apex) and the
  // normal turns with the azimuth. Object-space radius r(z) of the crossing
  // (the base radius is 1) below which t, and below which the normal, is not
  // judged.
  double apex_radius = 1e-5;
  double apex_normal_radius = 1e-3;
};

enum class Verdict { Agree, Grazing, Disagree };

struct Counts {
  std::uint64_t rays = 0;
  std::uint64_t oracle_hits = 0;     // rays whose visible surface the oracle found
  std::uint64_t agreements = 0;
  std::uint64_t grazing = 0;         // disagreements excused as grazing
  std::uint64_t disagreements = 0;   // disagreements outside the tolerance: failures
  std::uint64_t normals_at_edges = 0;  // agreements whose normal was not compared (edge, apex)
  Counts& operator+=(const Counts& o) {
    rays += o.rays;
    oracle_hits += o.oracle_hits;
    agreements += o.agreements;
    grazing += o.grazing;
    disagreements += o.disagreements;
    normals_at_edges += o.normals_at_edges;
    return *this;
  }
};

inline double ray_scale(const capsim::Ray& ray, const capsim::Aabb& universe) {
  return glm::length(universe.extent()) + glm::length(ray.origin - universe.center());
}

// What the oracle says about one ray: the spans it collected and the visible crossing.
struct OracleAnswer {
  std::vector<PrimSpan> spans;
  Visible visible;
  glm::dvec3 normal{0};  // outward normal of the CSG solid at the visible crossing
};

// The oracle for one scene: Embree's collector over the oracle's primitives and
// the CSG tree to classify with.
class Oracle {
 public:
  Oracle(std::vector<OraclePrimitive> prims, capsim::CsgNode root)
      : collector_(std::move(prims)), root_(std::move(root)) {}

  OracleAnswer answer(const capsim::Ray& ray) {
    OracleAnswer a;
    collector_.collect(ray, a.spans);
    a.visible = first_visible(root_, prims().size(), a.spans, ray.tmin, ray.tmax);
    if (a.visible.hit) {
      const Crossing& c = a.visible.crossing;
      const glm::dvec3 n = world_normal(prims()[c.primitive], ray, c.t, c.surface);
      // Entering a primitive while leaving the solid (or the reverse) means the
      // primitive is subtracted here: the solid's outward side is its inward side.
      a.normal = c.entering == a.visible.root_entering ? n : -n;
    }
    return a;
  }

  const std::vector<OraclePrimitive>& prims() const { return collector_.prims(); }

 private:
  EmbreeCollector collector_;
  capsim::CsgNode root_;
};

// Whether the crossing is one whose t, or whose order among the crossings, a
// rounding error can change.
inline bool ambiguous(const Crossing& c, const std::vector<Crossing>& all, std::size_t index,
                      const std::vector<PrimSpan>& spans, const std::vector<OraclePrimitive>& prims,
                      const capsim::Ray& ray, double g_t, const Tolerance& tol) {
  for (const PrimSpan& ps : spans)  // the ray only skims this primitive (silhouette)
    if (ps.primitive == c.primitive && ps.span.t_exit - ps.span.t_enter < g_t) return true;
  if (index > 0 && c.t - all[index - 1].t < g_t) return true;  // order with a neighbour
  if (index + 1 < all.size() && all[index + 1].t - c.t < g_t) return true;
  if (c.t - ray.tmin < g_t || std::abs(c.t - ray.tmax) < g_t) return true;  // at a ray end
  const OraclePrimitive& p = prims[c.primitive];
  const glm::dvec3 n = world_normal(p, ray, c.t, c.surface);
  if (std::abs(glm::dot(n, ray.dir)) < tol.graze_cos * glm::length(ray.dir)) return true;
  if (p.kind == capsim::PrimitiveKind::Cone && cone_radius_at(p, ray, c.t) < tol.apex_radius)
    return true;
  return false;
}

// Whether the normal at a visible crossing is well defined: not near an edge of
// the primitive (box edge, cone rim) and not near a cone's apex.
inline bool normal_defined(const OracleAnswer& a, const std::vector<OraclePrimitive>& prims,
                           const capsim::Ray& ray, double g_t, const Tolerance& tol) {
  const Crossing& c = a.visible.crossing;
  if (c.margin < g_t) return false;
  const OraclePrimitive& p = prims[c.primitive];
  if (p.kind == capsim::PrimitiveKind::Cone && cone_radius_at(p, ray, c.t) < tol.apex_normal_radius)
    return false;
  return true;
}

struct Judgement {
  Verdict verdict = Verdict::Agree;
  bool normal_compared = true;
  std::string detail;  // for a disagreement: both answers
};

// Whether the oracle gives the tracer's answer (hit or miss, primitive, side,
// and t within 1e-3 S) for the ray with its origin moved by g (world length)
// along some world axis: then the ray passes within g of a silhouette, an edge
// or a face it runs along, and the tracer's answer is exact for a ray within
// rounding of the given one. (The t bound is loose because moving a ray by g
// across a silhouette moves its crossings by up to about sqrt(g S).)
inline bool oracle_agrees_nearby(Oracle& oracle, const capsim::Ray& ray, bool tracer_hit,
                                 const capsim::Hit& h, double g, double scale) {
  const double dlen = glm::length(ray.dir);
  for (int axis = 0; axis < 3; ++axis) {
    for (const double sign : {-1.0, 1.0}) {
      capsim::Ray moved = ray;
      moved.origin[axis] += sign * g;
      const Visible w = oracle.answer(moved).visible;
      if (w.hit != tracer_hit) continue;
      if (!w.hit) return true;
      if (w.crossing.primitive == h.primitive && w.root_entering == h.entering &&
          std::abs(w.crossing.t - h.t) * dlen <= 1e-3 * scale)
        return true;
    }
  }
  return false;
}

inline Judgement judge(const OracleAnswer& a, Oracle& oracle, bool tracer_hit,
                       const capsim::Hit& h, const capsim::Ray& ray, const capsim::Aabb& universe,
                       const Tolerance& tol) {
  Judgement j;
  const std::vector<OraclePrimitive>& prims = oracle.prims();
  const double dlen = glm::length(ray.dir);
  const double scale = ray_scale(ray, universe);
  const double g_t = tol.graze_rel * scale / dlen;  // grazing length, in t
  const Visible& v = a.visible;

  bool same = v.hit == tracer_hit;
  if (same && v.hit) {
    j.normal_compared = normal_defined(a, prims, ray, g_t, tol);
    same = std::abs(v.crossing.t - h.t) * dlen <= tol.t_rel * scale &&
           v.crossing.primitive == h.primitive && v.root_entering == h.entering &&
           (!j.normal_compared || glm::length(h.normal - a.normal) <= tol.normal);
  }
  if (same) return j;

  // An ill-conditioned crossing at either answer (a miss answers tmax) or at the
  // ray's start.
  const double t_oracle = v.hit ? v.crossing.t : ray.tmax;
  const double t_tracer = tracer_hit ? h.t : ray.tmax;
  const std::vector<Crossing> all = crossings_after(a.spans, ray.tmin);
  for (std::size_t i = 0; i < all.size(); ++i) {
    const double t = all[i].t;
    const bool near = std::abs(t - t_oracle) <= g_t || std::abs(t - t_tracer) <= g_t ||
                      t - ray.tmin <= g_t;
    if (near && ambiguous(all[i], all, i, a.spans, prims, ray, g_t, tol)) {
      j.verdict = Verdict::Grazing;
      return j;
    }
  }
  // Or, where the answers differ in kind (hit or miss, primitive, side), the
  // tracer's answer is the oracle's for a ray within a grazing distance.
  const bool same_kind = v.hit == tracer_hit && (!v.hit || (v.crossing.primitive == h.primitive &&
                                                            v.root_entering == h.entering));
  if (!same_kind &&
      oracle_agrees_nearby(oracle, ray, tracer_hit, h, tol.graze_rel * scale, scale)) {
    j.verdict = Verdict::Grazing;
    return j;
  }
  j.verdict = Verdict::Disagree;
  j.detail = fmt::format(
      "ray o=({:.17g}, {:.17g}, {:.17g}) d=({:.17g}, {:.17g}, {:.17g}) tmin={:.17g} tmax={:.17g}\n"
      "  oracle: {} t={:.17g} prim={} entering={} n=({:.9f}, {:.9f}, {:.9f})\n"
      "  tracer: {} t={:.17g} prim={} entering={} n=({:.9f}, {:.9f}, {:.9f})",
      ray.origin.x, ray.origin.y, ray.origin.z, ray.dir.x, ray.dir.y, ray.dir.z, ray.tmin,
      ray.tmax, v.hit ? "hit" : "miss", v.crossing.t, v.crossing.primitive, v.root_entering,
      a.normal.x, a.normal.y, a.normal.z, tracer_hit ? "hit" : "miss", h.t, h.primitive,
      h.entering, h.normal.x, h.normal.y, h.normal.z);
  return j;
}

inline void tally(Counts& counts, const OracleAnswer& a, const Judgement& j) {
  ++counts.rays;
  if (a.visible.hit) ++counts.oracle_hits;
  switch (j.verdict) {
    case Verdict::Agree:
      ++counts.agreements;
      if (!j.normal_compared) ++counts.normals_at_edges;
      break;
    case Verdict::Grazing: ++counts.grazing; break;
    case Verdict::Disagree: ++counts.disagreements; break;
  }
}

}  // namespace oracle
