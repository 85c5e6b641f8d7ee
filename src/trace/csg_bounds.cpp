#include "capsim/trace/csg_bounds.h"

namespace capsim {

namespace {

Aabb intersection(const Aabb& a, const Aabb& b) {
  Aabb r;
  r.lo = glm::max(a.lo, b.lo);
  r.hi = glm::min(a.hi, b.hi);
  return r.empty() ? Aabb{} : r;
}

// A subtree as OpenSCAD's preview keeps it: the box its CSG node carries (a
// union's the union of its children's, an intersection's their common part, a
// difference's its first child's) and the union of its positively drawn solids' boxes
// (with the polarity flipped, the negatively drawn ones').
struct PreviewBoxes {
  Aabb node;
  Aabb drawn[2];  // [0]: drawn positively, [1]: negatively
};

PreviewBoxes preview(const CsgNode& n, std::span<const PreparedPrimitive> prims) {
  PreviewBoxes r;
  if (n.is_leaf) {
    r.node = prims[static_cast<std::size_t>(n.primitive)].world_bounds;
    r.drawn[0] = r.node;
    return r;
  }
  bool first = true;
  for (const CsgNode& child : n.children) {
    const PreviewBoxes c = preview(child, prims);
    if (first) {
      r = c;
      first = false;
      continue;
    }
    if (r.node.empty()) {
      // An empty left side: a union is its right side, anything else stays empty.
      if (n.op == CsgOp::Union) r = c;
      continue;
    }
    if (c.node.empty()) {
      if (n.op == CsgOp::Intersection) r = {};
      continue;
    }
    const Aabb common = intersection(r.node, c.node);
    switch (n.op) {
      case CsgOp::Union:
        r.node.extend(c.node);
        break;
      case CsgOp::Intersection:
        if (common.empty()) {
          r = {};
          continue;
        }
        r.node = common;
        break;
      case CsgOp::Difference:
        if (common.empty()) continue;  // the subtrahend is pruned
        break;
    }
    // Subtracted, the child's solids change polarity.
    const int flip = n.op == CsgOp::Difference ? 1 : 0;
    r.drawn[0].extend(c.drawn[flip]);
    r.drawn[1].extend(c.drawn[1 - flip]);
  }
  return r;
}

}  // namespace

Aabb openscad_preview_bounds(const CsgNode& node, std::span<const PreparedPrimitive> prims) {
  return preview(node, prims).drawn[0];
}

Aabb csg_result_bounds(const CsgNode& n, std::span<const PreparedPrimitive> prims) {
  if (n.is_leaf) return prims[static_cast<std::size_t>(n.primitive)].world_bounds;
  Aabb r;
  bool first = true;
  for (const CsgNode& child : n.children) {
    if (!first && n.op == CsgOp::Difference) break;
    const Aabb c = csg_result_bounds(child, prims);
    if (first || n.op == CsgOp::Union) {
      r.extend(c);
    } else {
      r = intersection(r, c);
    }
    first = false;
  }
  return r;
}

}  // namespace capsim
