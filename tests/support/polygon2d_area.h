#pragma once
// The area of a 2-D shape (scene/regions/clipper_utils.h) by the shoelace formula:
// solids count positive, holes negative (Clipper's windings).

#include "scene/regions/clipper_utils.h"

namespace capsim::testing {

inline double area(const scene_file::Polygon2d& p) {
  double a = 0;
  for (const auto& o : p.outlines)
    for (std::size_t i = 0; i < o.vertices.size(); ++i) {
      const glm::dvec2 u = o.vertices[i], v = o.vertices[(i + 1) % o.vertices.size()];
      a += (u.x * v.y - u.y * v.x) / 2;
    }
  return a;
}

}  // namespace capsim::testing
