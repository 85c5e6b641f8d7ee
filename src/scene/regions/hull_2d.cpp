// The 2-D hull by CGAL.

#include "scene/regions/hull_2d.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_2.h>

#include <iterator>

namespace capsim::scene_file {

std::optional<Polygon2d> hull_2d(const std::vector<Polygon2d>& shapes) {
  using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_2;
  std::vector<Point> points;
  for (const Polygon2d& shape : shapes)
    for (const Outline2d& o : shape.outlines)
      for (const glm::dvec2& v : o.vertices) points.emplace_back(v.x, v.y);
  std::vector<Point> hull;
  CGAL::convex_hull_2(points.begin(), points.end(), std::back_inserter(hull));
  if (hull.size() < 3) return std::nullopt;
  Polygon2d result;
  Outline2d& outline = result.outlines.emplace_back();
  for (const Point& p : hull) outline.vertices.emplace_back(p.x(), p.y());
  return result;
}

}  // namespace capsim::scene_file
