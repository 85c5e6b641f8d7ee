#pragma once
// Brute-force top-down classification (Roth 1982) of a ray against a CSG tree:
// sort every crossing of every primitive along the ray, and for the stretch after
// each crossing evaluate the whole tree from the root at a point of that stretch.
// The first crossing after tmin where the root's inside/outside answer changes is
// the visible surface. Nothing is shared with the tracer's bottom-up status tree
// (Algorithm-4), which it judges: no incremental state, no partial evaluation.

#include "oracle/oracle_embree.h"

#include "capsim/scene/scene.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace oracle {

// One end of a primitive's interval.
struct Crossing {
  double t = 0;
  std::uint32_t primitive = 0;
  bool entering = true;  // the ray enters the primitive here
  int surface = -1;
  double margin = kInfinity;  // t-gap to the runner-up constraint (near an edge if small)
};

// Membership of the tree at a point, given each primitive's membership. An
// operator with no children is the empty set; difference is the first child
// minus all the others.
inline bool classify(const capsim::CsgNode& node, const std::vector<char>& inside) {
  if (node.is_leaf) return inside[node.primitive] != 0;
  if (node.children.empty()) return false;
  switch (node.op) {
    case capsim::CsgOp::Union:
      for (const auto& c : node.children)
        if (classify(c, inside)) return true;
      return false;
    case capsim::CsgOp::Intersection:
      for (const auto& c : node.children)
        if (!classify(c, inside)) return false;
      return true;
    case capsim::CsgOp::Difference:
      if (!classify(node.children.front(), inside)) return false;
      for (std::size_t i = 1; i < node.children.size(); ++i)
        if (classify(node.children[i], inside)) return false;
      return true;
  }
  return false;
}

// The crossings of the collected spans in (tmin, +inf), sorted by t.
inline std::vector<Crossing> crossings_after(const std::vector<PrimSpan>& spans, double tmin) {
  std::vector<Crossing> out;
  for (const PrimSpan& ps : spans) {
    if (ps.span.t_enter > tmin)
      out.push_back({ps.span.t_enter, ps.primitive, true, ps.span.enter_surface, ps.span.enter_margin});
    if (ps.span.t_exit > tmin)
      out.push_back({ps.span.t_exit, ps.primitive, false, ps.span.exit_surface, ps.span.exit_margin});
  }
  std::sort(out.begin(), out.end(), [](const Crossing& a, const Crossing& b) {
    return a.t != b.t ? a.t < b.t : a.primitive < b.primitive;
  });
  return out;
}

struct Visible {
  bool hit = false;
  Crossing crossing;           // the crossing where the root changes
  bool root_entering = false;  // the ray goes from outside the solid to inside
  bool starts_inside = false;  // the root's status just after tmin
};

// Membership of every primitive at the point t of the line.
inline void memberships(const std::vector<PrimSpan>& spans, double t, std::vector<char>& inside) {
  std::fill(inside.begin(), inside.end(), 0);
  for (const PrimSpan& ps : spans)
    if (ps.span.t_enter < t && t < ps.span.t_exit) inside[ps.primitive] = 1;
}

// The first root transition in (tmin, tmax). spans must hold every primitive the
// line meets for t >= tmin (primitives absent from spans are outside everywhere).
inline Visible first_visible(const capsim::CsgNode& root, std::size_t primitive_count,
                             const std::vector<PrimSpan>& spans, double tmin, double tmax) {
  const std::vector<Crossing> cs = crossings_after(spans, tmin);
  Visible v;
  if (cs.empty()) return v;
  std::vector<char> inside(primitive_count, 0);
  memberships(spans, 0.5 * (tmin + cs.front().t), inside);
  bool state = classify(root, inside);
  v.starts_inside = state;
  for (std::size_t k = 0; k < cs.size(); ++k) {
    if (cs[k].t >= tmax) break;
    // Crossings at the same t form one step; the stretch after is classified once.
    std::size_t last = k;
    while (last + 1 < cs.size() && cs[last + 1].t == cs[k].t) ++last;
    const double t_after = last + 1 < cs.size()
                               ? 0.5 * (cs[k].t + cs[last + 1].t)
                               : cs[k].t + std::max(1.0, std::abs(cs[k].t));
    memberships(spans, t_after, inside);
    const bool next = classify(root, inside);
    if (next != state) {
      v.hit = true;
      v.crossing = cs[k];
      v.root_entering = next;
      return v;
    }
    k = last;
  }
  return v;
}

}  // namespace oracle
