#pragma once
// A scene written back as OpenSCAD CSG text (multmatrix + sphere/cube/cylinder),
// so that a failing random case can be reproduced with the capsim command line
// and read by a person.

#include "capsim/scene/scene.h"

#include <fmt/core.h>

#include <string>

namespace oracle {

inline std::string matrix_text(const glm::dmat4& m) {
  std::string s = "multmatrix([";
  for (int row = 0; row < 4; ++row) {
    s += fmt::format("[{:.17g}, {:.17g}, {:.17g}, {:.17g}]", m[0][row], m[1][row], m[2][row],
                     m[3][row]);
    if (row < 3) s += ", ";
  }
  return s + "])";
}

inline void append_node(std::string& out, const capsim::Scene& scene, const capsim::CsgNode& node,
                        int indent) {
  const std::string pad(2 * indent, ' ');
  if (node.is_leaf) {
    const capsim::Primitive& p = scene.primitives[node.primitive];
    std::string shape;
    switch (p.kind) {
      case capsim::PrimitiveKind::Sphere: shape = "sphere(r=1);"; break;
      case capsim::PrimitiveKind::Box: shape = "cube([1, 1, 1]);"; break;
      case capsim::PrimitiveKind::Cone:
        shape = fmt::format("cylinder(h=1, r1={:.17g}, r2={:.17g});", p.cone_r1, p.cone_r2);
        break;
      case capsim::PrimitiveKind::Mesh:  // the oracle's random scenes hold none
        shape = "polyhedron();  // a mesh";
        break;
      case capsim::PrimitiveKind::Revolution:  // nor revolutions
        shape = "rotate_extrude();  // a revolution";
        break;
    }
    out += fmt::format("{}{} {}  // primitive {}\n", pad, matrix_text(p.to_world), shape,
                       node.primitive);
    return;
  }
  out += fmt::format("{}{}() {{\n", pad, capsim::to_string(node.op));
  for (const capsim::CsgNode& c : node.children) append_node(out, scene, c, indent + 1);
  out += pad + "}\n";
}

inline std::string csg_text(const capsim::Scene& scene) {
  std::string out;
  append_node(out, scene, scene.root, 0);
  return out;
}

}  // namespace oracle
