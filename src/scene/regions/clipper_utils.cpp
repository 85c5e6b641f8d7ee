// OpenSCAD's ClipperUtils (clipper-utils.cc of 2021.01), step for step.

#include "scene/regions/clipper_utils.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace capsim::scene_file {

namespace {

ClipperLib::cInt to_integer(double v) {
  const double scaled = v * kClipperScale;
  if (!(std::abs(scaled) <= kMaxClippedCoordinate * kClipperScale))
    throw ClipperRangeError(fmt::format("a 2-D coordinate of {:g} is beyond the {:g} capsim's clipping holds", v,
                                        kMaxClippedCoordinate));
  return static_cast<ClipperLib::cInt>(scaled);  // truncated, as OpenSCAD's conversion does
}

ClipperLib::Path to_clipper(const Outline2d& outline, bool keep_orientation) {
  ClipperLib::Path p;
  p.reserve(outline.vertices.size());
  for (const glm::dvec2& v : outline.vertices) p.emplace_back(to_integer(v.x), to_integer(v.y));
  if (!keep_orientation && !ClipperLib::Orientation(p)) std::reverse(p.begin(), p.end());
  return p;
}

// Clipper signals a coordinate out of its range by throwing; the range was
// checked on the way in, so anything else is a fault of Clipper's own.
template <typename Run>
void run_clipper(Run&& run) {
  try {
    run();
  } catch (const ClipperLib::clipperException& e) {
    throw ClipperRangeError(fmt::format("clipping failed: {}", e.what()));
  }
}

ClipperLib::PolyTree sanitized_tree(const ClipperLib::Paths& paths) {
  ClipperLib::PolyTree result;
  ClipperLib::Clipper clipper;
  run_clipper([&] {
    clipper.AddPaths(paths, ClipperLib::ptSubject, true);
    clipper.Execute(ClipperLib::ctUnion, result, ClipperLib::pftEvenOdd);
  });
  return result;
}

}  // namespace

ClipperLib::Paths to_clipper(const Polygon2d& shape) {
  ClipperLib::Paths result;
  result.reserve(shape.outlines.size());
  for (const Outline2d& o : shape.outlines) result.push_back(to_clipper(o, shape.sanitized));
  return result;
}

Polygon2d from_clipper(const ClipperLib::PolyTree& tree) {
  Polygon2d result;
  for (const ClipperLib::PolyNode* node = tree.GetFirst(); node; node = node->GetNext()) {
    Outline2d outline;
    // As OpenSCAD: the winding, not the tree, says which contours are holes
    // (Clipper's hole flags are unreliable after an offset).
    outline.positive = ClipperLib::Orientation(node->Contour);
    ClipperLib::Path cleaned;
    ClipperLib::CleanPolygon(node->Contour, cleaned);
    if (cleaned.size() < 3) continue;
    for (const ClipperLib::IntPoint& p : cleaned)
      outline.vertices.emplace_back(static_cast<double>(p.X) / kClipperScale, static_cast<double>(p.Y) / kClipperScale);
    result.outlines.push_back(std::move(outline));
  }
  result.sanitized = true;
  return result;
}

Polygon2d sanitize(const Polygon2d& shape) { return from_clipper(sanitized_tree(to_clipper(shape))); }

Polygon2d clip_shapes(const std::vector<Polygon2d>& shapes, ClipperLib::ClipType type) {
  std::vector<ClipperLib::Paths> paths;
  for (const Polygon2d& s : shapes) {
    ClipperLib::Paths p = to_clipper(s);
    if (!s.sanitized) ClipperLib::PolyTreeToPaths(sanitized_tree(p), p);
    paths.push_back(std::move(p));
  }
  ClipperLib::Clipper clipper;
  ClipperLib::PolyTree result;
  if (type == ClipperLib::ctIntersection && paths.size() >= 2) {
    ClipperLib::Paths source = paths[0];
    for (std::size_t i = 1; i < paths.size(); ++i) {
      run_clipper([&] {
        clipper.AddPaths(source, ClipperLib::ptSubject, true);
        clipper.AddPaths(paths[i], ClipperLib::ptClip, true);
        clipper.Execute(type, result, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
      });
      if (i + 1 != paths.size()) {
        ClipperLib::PolyTreeToPaths(result, source);
        clipper.Clear();
      }
    }
    return from_clipper(result);
  }
  run_clipper([&] {
    for (std::size_t i = 0; i < paths.size(); ++i)
      clipper.AddPaths(paths[i], i == 0 ? ClipperLib::ptSubject : ClipperLib::ptClip, true);
    clipper.Execute(type, result, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  });
  return from_clipper(result);
}

Polygon2d apply_offset(const Polygon2d& shape, double delta, ClipperLib::JoinType join, double miter_limit,
                       double arc_tolerance) {
  ClipperLib::ClipperOffset offset(miter_limit, arc_tolerance * kClipperScale);
  ClipperLib::PolyTree result;
  const ClipperLib::Paths paths = to_clipper(shape);
  run_clipper([&] {
    offset.AddPaths(paths, join, ClipperLib::etClosedPolygon);
    offset.Execute(result, delta * kClipperScale);
  });
  return from_clipper(result);
}

namespace {

// The quadrilaterals that sweep outline `a` along every edge of outline `b`
// (both closed), each turned counter-clockwise: their union is the band the
// boundary of a + b lies in. Clipper's MinkowskiSum would also unite them;
// OpenSCAD unites them once with the insides instead, so that rounding in a
// first union cannot open cracks.
void add_swept_quads(const ClipperLib::Path& a, const ClipperLib::Path& b, ClipperLib::Paths& out) {
  if (a.empty() || b.empty()) return;
  std::vector<ClipperLib::Path> moved(b.size());  // a placed at each corner of b
  for (std::size_t i = 0; i < b.size(); ++i) {
    moved[i].reserve(a.size());
    for (const ClipperLib::IntPoint& p : a) moved[i].emplace_back(b[i].X + p.X, b[i].Y + p.Y);
  }
  for (std::size_t i = 0; i < b.size(); ++i) {
    const ClipperLib::Path& here = moved[i];
    const ClipperLib::Path& next = moved[(i + 1) % b.size()];
    for (std::size_t j = 0; j < a.size(); ++j) {
      const std::size_t k = (j + 1) % a.size();
      ClipperLib::Path quad{here[j], next[j], next[k], here[k]};
      if (!ClipperLib::Orientation(quad)) ClipperLib::ReversePath(quad);
      out.push_back(std::move(quad));
    }
  }
}

// The swept band leaves the middle of the sum empty where a component of
// one shape is larger than the other's outlines: the other shape placed at
// any one corner of each solid (counter-clockwise) outline of the first
// fills it, and lies within the sum.
void add_insides(const ClipperLib::Paths& shape, const ClipperLib::Paths& placed_at, ClipperLib::Paths& out) {
  for (const ClipperLib::Path& at : placed_at) {
    if (at.empty() || !ClipperLib::Orientation(at)) continue;
    for (const ClipperLib::Path& path : shape) {
      ClipperLib::Path& copy = out.emplace_back(path);
      for (ClipperLib::IntPoint& p : copy) {
        p.X += at.front().X;
        p.Y += at.front().Y;
      }
    }
  }
}

}  // namespace

Polygon2d minkowski_sum(const std::vector<Polygon2d>& shapes) {
  if (shapes.size() == 1) return shapes.front();
  ClipperLib::Clipper clipper;
  ClipperLib::Paths sum = to_clipper(shapes.front());
  ClipperLib::PolyTree result;
  for (std::size_t i = 1; i < shapes.size(); ++i) {
    const ClipperLib::Paths next = to_clipper(shapes[i]);
    ClipperLib::Paths terms;
    for (const ClipperLib::Path& b : next)
      for (const ClipperLib::Path& a : sum) add_swept_quads(a, b, terms);
    add_insides(sum, next, terms);
    add_insides(next, sum, terms);
    clipper.Clear();
    run_clipper([&] {
      clipper.AddPaths(terms, ClipperLib::ptSubject, true);
      if (i + 1 == shapes.size()) {
        clipper.Execute(ClipperLib::ctUnion, result, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
      } else {
        clipper.Execute(ClipperLib::ctUnion, sum, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
      }
    });
  }
  return from_clipper(result);
}

}  // namespace capsim::scene_file
