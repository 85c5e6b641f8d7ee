#pragma once
// OpenSCAD 2021.01's own meshes of sphere, cylinder and cube
// (primitives.cc): the same fragments ($fn, $fa, $fs through
// Calc::get_fragments_from_r), the same sphere rings and circle points
// (starting at angle 0, OpenSCAD's degree trigonometry), the same faces.
// hull() and minkowski() need them: OpenSCAD builds those solids out of
// these points, so capsim does too.

#include "capsim/scene/triangle_mesh.h"
#include "scene/reading/scene_syntax.h"
#include "scene/work_limits.h"

#include <glm/glm.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <vector>

namespace capsim::scene_file {

// OpenSCAD's PolySet building calls, so that a mesh reads as OpenSCAD's code
// writes it: a new polygon, then its corners added at its end or at its
// start. Points at equal coordinates (-0 and 0 alike) share an index.
class PolySetBuilder {
 public:
  void append_poly() { mesh_.faces.emplace_back(); }
  void append_vertex(double x, double y, double z) { mesh_.faces.back().push_back(index(x, y, z)); }
  void insert_vertex(double x, double y, double z) {
    auto& f = mesh_.faces.back();
    f.insert(f.begin(), index(x, y, z));
  }
  PolygonMesh take() { return std::move(mesh_); }

 private:
  std::uint32_t index(double x, double y, double z);
  std::map<std::array<double, 3>, std::uint32_t> ids_;
  PolygonMesh mesh_;
};

// OpenSCAD's special variables of one call, $fa and $fs clamped below at
// 0.01 as OpenSCAD clamps them for its primitives (not for rotate_extrude,
// which reads them as they are: clamped = false).
struct Resolution {
  double fn = 0, fa = 12, fs = 2;
};
Resolution read_resolution(const Call& call, bool clamped = true);

// How many points OpenSCAD puts on a circle of radius r. Refused past
// kMaxFragments (a zero $fa or $fs, a huge $fn) at `loc`.
int fragments_for(double r, const Resolution& res, const Loc& loc);

// The circle's points, counter-clockwise from angle 0.
std::vector<glm::dvec2> openscad_circle(double r, int fragments);

// The meshes, in the primitive's own space, faces as OpenSCAD winds them.
// Points at equal coordinates are one point (a cone's apex).
PolygonMesh openscad_sphere(double r, int fragments);
PolygonMesh openscad_cylinder(double h, double r1, double r2, bool center, int fragments);
PolygonMesh openscad_cube(const glm::dvec3& size, bool center);

// The mesh OpenSCAD makes of a sphere(), cylinder() or cube() call, its
// arguments checked as read_primitive checks them. Refused (at the call)
// when it would have more than kMaxTessellatedPoints points.
PolygonMesh tessellate_primitive(const Call& call);


}  // namespace capsim::scene_file
