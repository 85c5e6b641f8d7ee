#pragma once
// Small scenes built in code for unit tests.

#include "capsim/trace/prepared_scene.h"

#include <glm/gtc/matrix_transform.hpp>

#include <iterator>
#include <vector>

namespace capsim::testing {

inline Primitive sphere(glm::dvec3 c, double r) {
  Primitive p;
  p.kind = PrimitiveKind::Sphere;
  p.to_world = glm::scale(glm::translate(glm::dmat4(1.0), c), glm::dvec3(r));
  return p;
}

inline Primitive box(glm::dvec3 lo, glm::dvec3 size) {
  Primitive p;
  p.kind = PrimitiveKind::Box;
  p.to_world = glm::scale(glm::translate(glm::dmat4(1.0), lo), size);
  return p;
}

// Axis along +z from base, radii r1 at the base and r2 at the top.
inline Primitive cone(glm::dvec3 base, double h, double r1, double r2) {
  Primitive p;
  p.kind = PrimitiveKind::Cone;
  const double rmax = std::max(r1, r2);
  p.to_world = glm::scale(glm::translate(glm::dmat4(1.0), base), glm::dvec3(rmax, rmax, h));
  p.cone_r1 = r1 / rmax;
  p.cone_r2 = r2 / rmax;
  return p;
}

inline CsgNode leaf(int p) {
  CsgNode n;
  n.is_leaf = true;
  n.primitive = p;
  return n;
}

inline CsgNode op(CsgOp o, std::vector<CsgNode> kids) {
  CsgNode n;
  n.op = o;
  n.children = std::move(kids);
  return n;
}

// A scene of the given primitives under root (default: their union).
inline Scene make_scene(std::vector<Primitive> prims, std::optional<CsgNode> root = std::nullopt) {
  Scene s;
  s.primitives.assign(std::make_move_iterator(prims.begin()), std::make_move_iterator(prims.end()));
  if (root) {
    s.root = op(CsgOp::Union, {*root});
  } else {
    std::vector<CsgNode> kids;
    for (std::size_t i = 0; i < s.primitives.size(); ++i) kids.push_back(leaf(static_cast<int>(i)));
    s.root = op(CsgOp::Union, kids);
  }
  return s;
}

// A grid of n x n x n unit voxels over [0, n]^3, for walking by hand.
inline VoxelGrid unit_voxel_grid(int n) {
  VoxelGrid g;
  g.universe = {glm::dvec3(0), glm::dvec3(n)};
  g.n = n;
  g.voxel_size = glm::dvec3(1);
  g.inv_voxel_size = glm::dvec3(1);
  return g;
}

// A CSG difference of every kind of primitive (a round sphere, a stretched
// one, a box, a cylinder, a cone, a mesh and a revolution) less a sphere, as
// scene-file text, about the origin within 6 units.
inline constexpr const char* kEveryKindDifference =
    "difference() {\n"
    "  union() {\n"
    "    sphere(r = 1.5);\n"
    "    translate([3, 0, 0]) scale([1, 2, 0.5]) sphere(r = 1);\n"
    "    translate([-4, -1, -1]) cube([2, 2, 2]);\n"
    "    translate([0, 3, -1]) cylinder(h = 2, r = 1);\n"
    "    translate([0, -3, -1]) cylinder(h = 2, r1 = 1, r2 = 0);\n"
    "    translate([0, 0, 3]) polyhedron(points = [[0,0,0],[2,0,0],[0,2,0],[0,0,2]],\n"
    "                                    faces = [[0,2,1],[0,1,3],[0,3,2],[1,2,3]]);\n"
    "    translate([0, 0, -4]) rotate_extrude() translate([2, 0, 0]) circle(r = 0.5);\n"
    "  }\n"
    "  translate([0.5, 0, 0]) sphere(r = 0.8);\n"
    "}\n";

}  // namespace capsim::testing
