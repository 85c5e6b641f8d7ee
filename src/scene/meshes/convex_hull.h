#pragma once
// The convex hull of points in space, by Qhull (libqhull_r, the reentrant
// library Debian packages): hull() and minkowski() are closed meshes made of
// it. Qhull rather than CGAL's convex_hull_3 (which OpenSCAD uses): the hull
// is the same solid, Qhull is a small C library, and CGAL's header-only
// templates would multiply the build time of the scene layer.

#include "capsim/scene/triangle_mesh.h"

#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <vector>

namespace capsim {

// The hull's triangles, counter-clockwise seen from outside, over the points
// that are its corners; empty with the reason when the points span no volume
// (fewer than four, or all in one plane or on one line).
struct HullBuild {
  std::optional<TriangleMesh> mesh;
  std::string flat_reason;
};
HullBuild convex_hull(const std::vector<glm::dvec3>& points);

}  // namespace capsim
