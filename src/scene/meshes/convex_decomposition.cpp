// Convex decomposition by CGAL (Nef_polyhedron_3 and convex_decomposition_3).

#include "scene/meshes/convex_decomposition.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Nef_polyhedron_3.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_decomposition_3.h>
#include <fmt/format.h>

#include <map>
#include <numeric>

namespace capsim {

namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Nef = CGAL::Nef_polyhedron_3<Kernel>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

// Collects the points of a shell's vertices (the visitor
// Nef_polyhedron_3::visit_shell_objects calls for each of its objects).
struct ShellCorners {
  std::vector<glm::dvec3>* out;
  void visit(Nef::Vertex_const_handle v) const {
    const Kernel::Point_3& p = v->point();
    out->emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }
  void visit(Nef::Halfedge_const_handle) const {}
  void visit(Nef::Halffacet_const_handle) const {}
  void visit(Nef::SHalfedge_const_handle) const {}
  void visit(Nef::SHalfloop_const_handle) const {}
  void visit(Nef::SFace_const_handle) const {}
};

// The Nef polyhedron of one closed surface, given by the mesh's faces that
// form it: the volume it bounds, whichever way its faces turn (a mirrored
// mesh's face inwards). The surface takes only the points its faces name
// (CGAL's conversion fails on a vertex without faces).
Nef nef_of_shell(const std::vector<Kernel::Point_3>& points, std::vector<std::vector<std::size_t>> faces) {
  std::map<std::size_t, std::size_t> renumbered;
  std::vector<Kernel::Point_3> used;
  for (auto& face : faces)
    for (std::size_t& v : face) {
      auto [it, added] = renumbered.try_emplace(v, used.size());
      if (added) used.push_back(points[v]);
      v = it->second;
    }
  Mesh shell;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(used, faces, shell);
  return Nef(shell);
}

// The Nef polyhedron a mesh bounds: what lies inside an odd number of its
// closed surfaces (connected by shared corners); or empty with why CGAL
// cannot have it.
std::optional<Nef> nef_of(const TriangleMesh& mesh, std::string& reason) {
  std::vector<std::vector<std::size_t>> faces;
  faces.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) faces.push_back({t[0], t[1], t[2]});
  namespace PMP = CGAL::Polygon_mesh_processing;
  if (!PMP::is_polygon_soup_a_polygon_mesh(faces)) {
    reason = "its faces meet at an edge or corner shared by more than one sheet of surface (not a 2-manifold)";
    return std::nullopt;
  }
  std::vector<Kernel::Point_3> points;
  points.reserve(mesh.vertices.size());
  for (const glm::dvec3& v : mesh.vertices) points.emplace_back(v.x, v.y, v.z);
  Mesh surface;
  PMP::polygon_soup_to_polygon_mesh(points, faces, surface);
  // A Nef polyhedron of a surface that crosses itself is undefined.
  if (PMP::does_self_intersect(surface)) {
    reason = "its surface crosses itself";
    return std::nullopt;
  }
  // The shells: corners joined by the triangles, each shell's faces in the
  // mesh's order, the shells in the order of their first face.
  std::vector<std::size_t> root(mesh.vertices.size());
  std::iota(root.begin(), root.end(), std::size_t{0});
  auto find = [&](std::size_t v) {
    while (root[v] != v) v = root[v] = root[root[v]];
    return v;
  };
  for (const auto& f : faces) {
    const std::size_t first = find(f[0]);
    root[find(f[1])] = first;
    root[find(f[2])] = first;
  }
  std::map<std::size_t, std::vector<std::vector<std::size_t>>> shells;
  std::vector<std::size_t> order;
  for (const auto& f : faces) {
    auto [it, added] = shells.try_emplace(find(f[0]));
    if (added) order.push_back(it->first);
    it->second.push_back(f);
  }
  Nef solid;  // empty
  for (std::size_t key : order) solid ^= nef_of_shell(points, std::move(shells[key]));
  return solid;
}

// The Nef polyhedron of a CSG tree of meshes; empty when a leaf has none.
std::optional<Nef> evaluate(const CsgNode& node, const scene_file::MeshedSolids& solids, std::string& reason) {
  if (node.is_leaf) return nef_of(solids.meshes.at(static_cast<std::size_t>(node.primitive)), reason);
  std::optional<Nef> result;
  for (const CsgNode& child : node.children) {
    std::optional<Nef> operand = evaluate(child, solids, reason);
    if (!operand) return std::nullopt;
    if (!result) {
      result = std::move(operand);
    } else if (node.op == CsgOp::Union) {
      *result += *operand;
    } else if (node.op == CsgOp::Difference) {
      *result -= *operand;
    } else {
      *result *= *operand;
    }
  }
  if (!result) result.emplace();  // no operands: nothing
  return result;
}

}  // namespace

ConvexPieces solid_pieces(const scene_file::MeshedSolids& solids, bool split) {
  ConvexPieces pieces;
  try {
    std::optional<Nef> nef = evaluate(solids.root, solids, pieces.reason);
    if (!nef) return pieces;
    *nef = nef->regularization();
    std::vector<std::vector<glm::dvec3>> corners;
    if (!split) {
      std::vector<glm::dvec3>& all = corners.emplace_back();
      for (auto v = nef->vertices_begin(); v != nef->vertices_end(); ++v) ShellCorners{&all}.visit(v);
      if (all.empty()) corners.clear();
      pieces.corners = std::move(corners);
      return pieces;
    }
    CGAL::convex_decomposition_3(*nef);
    // The first volume is the unbounded outside; the marked ones after it
    // are the solid's convex pieces, each bounded by one shell.
    for (auto volume = ++nef->volumes_begin(); volume != nef->volumes_end(); ++volume) {
      if (!volume->mark()) continue;
      ShellCorners visitor{&corners.emplace_back()};
      nef->visit_shell_objects(Nef::SFace_const_handle(volume->shells_begin()), visitor);
    }
    pieces.corners = std::move(corners);
  } catch (const CGAL::Failure_exception& e) {
    pieces.reason = fmt::format("CGAL refused it ({})", e.message());
  }
  return pieces;
}

std::vector<std::vector<glm::dvec3>> evaluated_corners(const scene_file::MeshedSolids& solids, bool split,
                                                       const scene_file::Call& call, const EvaluationWords& words) {
  std::size_t triangles = 0;
  for (const TriangleMesh& mesh : solids.meshes) triangles += mesh.triangles.size();
  if (triangles > kMaxDecomposedTriangles)
    throw SceneError(call.loc, fmt::format("{} is not supported: {} has {} triangles, more than the {} capsim {}",
                                           words.subject, words.holder, triangles, kMaxDecomposedTriangles,
                                           words.action));
  ConvexPieces pieces = solid_pieces(solids, split);
  if (!pieces.corners)
    throw SceneError(call.loc, fmt::format("{} is not supported: {}; CGAL {} only a 2-manifold that does not cross "
                                           "itself",
                                           words.subject, pieces.reason, split ? "splits" : "evaluates"));
  return std::move(*pieces.corners);
}

}  // namespace capsim
