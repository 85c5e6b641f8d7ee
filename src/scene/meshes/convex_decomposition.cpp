// Convex decomposition by CGAL (Nef_polyhedron_3 and convex_decomposition_3).

#include "scene/meshes/convex_decomposition.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Nef_polyhedron_3.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_decomposition_3.h>
#include <fmt/format.h>

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

// The Nef polyhedron a mesh bounds, or empty with why CGAL cannot have it.
std::optional<Nef> nef_of(const TriangleMesh& mesh, std::string& reason) {
  std::vector<Kernel::Point_3> points;
  points.reserve(mesh.vertices.size());
  for (const glm::dvec3& v : mesh.vertices) points.emplace_back(v.x, v.y, v.z);
  std::vector<std::vector<std::size_t>> faces;
  faces.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) faces.push_back({t[0], t[1], t[2]});
  namespace PMP = CGAL::Polygon_mesh_processing;
  if (!PMP::is_polygon_soup_a_polygon_mesh(faces)) {
    reason = "its faces meet at an edge or corner shared by more than one sheet of surface (not a 2-manifold)";
    return std::nullopt;
  }
  Mesh surface;
  PMP::polygon_soup_to_polygon_mesh(points, faces, surface);
  // A Nef polyhedron of a surface that crosses itself is undefined.
  if (PMP::does_self_intersect(surface)) {
    reason = "its surface crosses itself";
    return std::nullopt;
  }
  return Nef(surface);
}

}  // namespace

ConvexPieces convex_pieces(const TriangleMesh& mesh, const std::vector<const TriangleMesh*>& holes) {
  ConvexPieces pieces;
  try {
    std::optional<Nef> nef = nef_of(mesh, pieces.reason);
    for (const TriangleMesh* hole : holes) {
      if (!nef) break;
      if (std::optional<Nef> cut = nef_of(*hole, pieces.reason)) {
        *nef -= *cut;
      } else {
        nef.reset();
      }
    }
    if (!nef) return pieces;
    CGAL::convex_decomposition_3(*nef);
    std::vector<std::vector<glm::dvec3>> corners;
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

}  // namespace capsim
