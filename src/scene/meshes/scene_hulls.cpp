// hull() and minkowski() over their children's points.

#include "scene/meshes/scene_hulls.h"

#include "scene/meshes/convex_decomposition.h"
#include "scene/meshes/convex_hull.h"
#include "scene/meshes/meshed_solids.h"
#include "scene/extrusions/extruded_region.h"
#include "scene/extrusions/openscad_tessellation.h"
#include "scene/reading/scene_args.h"
#include "scene/meshes/scene_meshes.h"
#include "scene/meshes/scene_resize.h"
#include "scene/reading/scene_modules.h"
#include "scene/meshes/scene_surface.h"

#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace capsim::scene_file {

namespace {

std::size_t point_count(const std::vector<std::vector<glm::dvec3>>& parts) {
  std::size_t n = 0;
  for (const auto& part : parts) n += part.size();
  return n;
}

// The points of one subtree as the convex parts whose union it is, each
// given by points whose hull it is: a primitive, a hull, each part of a
// minkowski, a convex mesh or extrusion outline, each convex piece of a
// non-convex one (only when the parts are to be summed: a hull takes every
// point alike).
struct Parts {
  std::vector<std::vector<glm::dvec3>> convex;
  std::size_t points() const { return point_count(convex); }
  std::vector<glm::dvec3> all_points() const {
    std::vector<glm::dvec3> all;
    all.reserve(points());
    for (const auto& part : convex) all.insert(all.end(), part.begin(), part.end());
    return all;
  }
};

bool drawn(const Call& call) {
  for (const Modifier& m : call.modifiers) {
    if (m.symbol == '!') throw SceneError(m.loc, "the '!' (root) modifier is not supported inside hull() or minkowski()");
    if (m.symbol == '%' || m.symbol == '*') return false;
  }
  return true;
}

void add_part(const std::vector<glm::dvec3>& points, const glm::dmat4& m, Parts& out) {
  std::vector<glm::dvec3>& part = out.convex.emplace_back();
  part.reserve(points.size());
  for (const glm::dvec3& p : points) part.push_back(glm::dvec3(m * glm::dvec4(p, 1.0)));
}

// Whether every vertex of the mesh lies on the inner side of every triangle's
// plane (within a tolerance relative to its size).
bool is_convex(const TriangleMesh& mesh) {
  const double tolerance = 1e-9 * glm::length(mesh.bounds.extent());
  for (const auto& t : mesh.triangles) {
    const glm::dvec3 a = mesh.vertices[t[0]];
    const glm::dvec3 n = glm::cross(mesh.vertices[t[1]] - a, mesh.vertices[t[2]] - a);
    const double len = glm::length(n);
    if (!(len > 0)) continue;
    for (const glm::dvec3& v : mesh.vertices)
      if (glm::dot(v - a, n) / len > tolerance) return false;
  }
  return true;
}

// The solid `solids` evaluates to, placed by m, evaluated by CGAL: its
// convex pieces when `split`, else all its corners as one part. `what`
// names it in a refusal at `call`.
void add_evaluated(const MeshedSolids& solids, const glm::dmat4& m, bool split, const Call& call,
                   std::string_view what, Parts& out) {
  const std::string subject = split ? fmt::format("minkowski() of this non-convex {}", what)
                                    : fmt::format("hull() of this {}", what);
  const EvaluationWords words{subject, "it", split ? "splits into convex pieces" : "evaluates with CGAL"};
  for (const auto& piece : evaluated_corners(solids, split, call, words)) add_part(piece, m, out);
}

// The solid a mesh bounds, less those of `holes` (inside it), placed by m:
// its points as one part (the holes' lie within), or, when `split` and the
// solid is not convex, its convex pieces. `what` names it in a refusal.
void add_solid(const TriangleMesh& mesh, const std::vector<const TriangleMesh*>& holes, const glm::dmat4& m,
               bool split, const Call& call, std::string_view what, Parts& out) {
  if (!split || (holes.empty() && is_convex(mesh))) return add_part(mesh.vertices, m, out);
  MeshedSolids solid;
  solid.meshes.push_back(mesh);
  solid.root.op = CsgOp::Difference;
  for (const TriangleMesh* hole : holes) solid.meshes.push_back(*hole);
  for (std::size_t k = 0; k < solid.meshes.size(); ++k) {
    CsgNode& leaf = solid.root.children.emplace_back();
    leaf.is_leaf = true;
    leaf.primitive = static_cast<int>(k);
  }
  add_evaluated(solid, m, split, call, what, out);
}

// A difference, intersection or rotate_extrude as OpenSCAD meshes and
// evaluates it, placed by m. Without a difference or intersection in it, its
// meshes' points are its points (a hull's one part) and a convex mesh is a
// part of its own; anything else is left to CGAL.
void add_meshed(const Call& call, const FileAccess& files, const glm::dmat4& m, bool split, Parts& out) {
  const MeshedSolids solids = read_meshed_solids(std::span(&call, 1), files, {"hull() or minkowski()", "meshes"});
  if (only_unions(solids.root) && (!split || std::all_of(solids.meshes.begin(), solids.meshes.end(), is_convex))) {
    for (const TriangleMesh& mesh : solids.meshes) add_part(mesh.vertices, m, out);
    return;
  }
  add_evaluated(solids, m, split, call, fmt::format("{}()", call.name), out);
}

void add_mesh(const Primitive& p, const glm::dmat4& m, bool split, const Call& call, Parts& out) {
  add_solid(*p.mesh, {}, m * p.to_world, split, call, "mesh", out);
}

std::vector<std::vector<glm::dvec3>> summed_parts(const Call& call, const FileAccess& files);

// Collects a subtree's parts; `split`: a non-convex mesh gives its convex
// pieces (for minkowski), else all its points as one part (for hull).
class PointCollector {
 public:
  PointCollector(const FileAccess& files, bool split) : files_(files), split_(split) {}

  void collect(const Call& call, const glm::dmat4& m, Parts& out) {
    if (!drawn(call)) return;
    const std::string_view n = call.name;
    if (n == "sphere" || n == "cube" || n == "cylinder") {
      no_children(call);
      add_part(tessellate_primitive(call).points, m, out);
    } else if (n == "import") {
      no_children(call);
      for (const Primitive& p : read_import(call, files_.import_dir, files_.max_bytes)) add_mesh(p, m, split_, call, out);
    } else if (n == "polyhedron" || n == "surface") {
      no_children(call);
      add_mesh(n == "polyhedron" ? read_polyhedron(call) : read_surface(call, files_.import_dir, files_.max_bytes),
               m, split_, call, out);
    } else if (n == "linear_extrude") {
      // Each outline less the holes directly in it, as projection() reads it.
      const ExtrudedRegion region =
          extruded_region(call, {files_.import_dir, files_.max_bytes}, "hull() or minkowski()");
      for (std::size_t k = 0; k < region.meshes.size(); ++k) {
        if (!region.outline(k)) continue;
        std::vector<const TriangleMesh*> holes;
        for (std::size_t h = 0; h < region.meshes.size(); ++h)
          if (region.parent[h] == static_cast<int>(k)) holes.push_back(&region.meshes[h]);
        add_solid(region.meshes[k], holes, m * region.to_call, split_, call, "extrusion", out);
      }
    } else if (n == "hull") {
      read_hull_arguments(call);
      PointCollector points(files_, false);
      Parts inner;
      for (const Call& child : call.children) points.collect(child, m, inner);
      if (std::vector<glm::dvec3> all = inner.all_points(); !all.empty()) out.convex.push_back(std::move(all));
    } else if (n == "minkowski") {
      read_hull_arguments(call);
      for (const auto& part : summed_parts(call, files_)) add_part(part, m, out);
    } else if (n == "multmatrix" || n == "translate" || n == "rotate" || n == "scale" || n == "mirror" ||
               n == "resize") {
      const glm::dmat4 inner = m * (n == "resize" ? read_resize(call, files_) : read_transform(call));
      for (const Call& child : call.children) collect(child, inner, out);
    } else if (n == "union" || n == "group" || n == "render" || n == "color" || n == "material") {
      if (n == "color") {
        read_color(call);  // the solid is drawn in the colour around it
      } else if (n == "material") {
        read_material(call, Material{});
      } else {
        read_pass_through(call);
      }
      for (const Call& child : call.children) collect(child, m, out);
    } else if (n == "difference" || n == "intersection" || n == "rotate_extrude") {
      add_meshed(call, files_, m, split_, out);
    } else {
      throw SceneError(call.loc, fmt::format("{}() under hull() or minkowski() is not supported: capsim takes the "
                                             "points of sphere, cube, cylinder, polyhedron, import, surface, hull, "
                                             "minkowski, linear_extrude and rotate_extrude, under transforms, resize, "
                                             "union, difference, intersection, color and render",
                                             n));
    }
  }

 private:
  static void no_children(const Call& call) {
    if (call.has_body)
      throw SceneError(call.body_loc, fmt::format("{}() takes no children (missing ';' after {}(...)?)", call.name,
                                                  call.name));
  }
  const FileAccess& files_;
  bool split_;
};

TriangleMesh hull_of(const std::vector<glm::dvec3>& points, const Call& call) {
  if (points.empty())
    throw SceneError(call.loc, fmt::format("{}() has no solid children: it encloses nothing", call.name));
  if (points.size() > kMaxTessellatedPoints)
    throw SceneError(call.loc, fmt::format("{}() has {} points, more than the {} capsim takes the hull of",
                                           call.name, points.size(), kMaxTessellatedPoints));
  HullBuild built = convex_hull(points);
  if (!built.mesh) throw SceneError(call.loc, fmt::format("{}() is not a solid: {}", call.name, built.flat_reason));
  return std::move(*built.mesh);
}

// The corners of each convex part of a minkowski: the sum distributes over
// union, so it is the union over every choice of one convex part per child
// of the hull of the chosen parts' point sums (OpenSCAD's way, its parts
// those of CGAL's convex decomposition). Refused beyond kMaxMinkowskiParts
// parts, or kMaxTessellatedPoints point sums in one step.
std::vector<std::vector<glm::dvec3>> summed_parts(const Call& call, const FileAccess& files) {
  PointCollector collector(files, true);
  std::vector<std::vector<glm::dvec3>> sums;
  for (const Call& child : call.children) {
    Parts parts;
    collector.collect(child, glm::dmat4(1.0), parts);
    if (parts.convex.empty()) continue;
    // Only the corners of each part's hull matter to the sum.
    for (auto& part : parts.convex)
      if (part.size() >= 4) part = hull_of(part, child).vertices;
    if (sums.empty()) {
      sums = std::move(parts.convex);
      continue;
    }
    if (sums.size() * parts.convex.size() > kMaxMinkowskiParts)
      throw SceneError(child.loc, fmt::format("minkowski() would sum {} convex parts by {}, more than the {} parts "
                                              "capsim makes of one minkowski",
                                              sums.size(), parts.convex.size(), kMaxMinkowskiParts));
    const std::size_t so_far = point_count(sums);
    const double pairs = static_cast<double>(so_far) * static_cast<double>(parts.points());
    if (pairs > static_cast<double>(kMaxTessellatedPoints))
      throw SceneError(child.loc, fmt::format("minkowski() would sum {} by {} points, more than the {} capsim takes "
                                              "the hull of",
                                              so_far, parts.points(), kMaxTessellatedPoints));
    std::vector<std::vector<glm::dvec3>> next;
    next.reserve(sums.size() * parts.convex.size());
    for (const auto& a : sums) {
      for (const auto& b : parts.convex) {
        std::vector<glm::dvec3> sum;
        sum.reserve(a.size() * b.size());
        for (const glm::dvec3& p : a)
          for (const glm::dvec3& q : b) sum.push_back(p + q);
        next.push_back(hull_of(sum, call).vertices);
      }
    }
    sums = std::move(next);
  }
  return sums;
}

Primitive mesh_leaf(TriangleMesh mesh, const Call& call) {
  Primitive p;
  p.kind = PrimitiveKind::Mesh;
  p.mesh = std::make_shared<const TriangleMesh>(std::move(mesh));
  p.loc = call.loc;
  return p;
}

}  // namespace

Primitive read_hull(const Call& call, const FileAccess& files) {
  read_hull_arguments(call);
  Parts parts;
  PointCollector collector(files, false);
  for (const Call& child : call.children) collector.collect(child, glm::dmat4(1.0), parts);
  return mesh_leaf(hull_of(parts.all_points(), call), call);
}

std::vector<Primitive> read_minkowski(const Call& call, const FileAccess& files) {
  read_hull_arguments(call);
  std::vector<std::vector<glm::dvec3>> parts = summed_parts(call, files);
  std::vector<Primitive> leaves;
  if (parts.empty()) leaves.push_back(mesh_leaf(hull_of({}, call), call));  // refused: nothing to sum
  for (const auto& part : parts) leaves.push_back(mesh_leaf(hull_of(part, call), call));
  return leaves;
}

}  // namespace capsim::scene_file
