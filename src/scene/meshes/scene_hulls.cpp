// hull() and minkowski() over their children's points.

#include "scene/meshes/scene_hulls.h"

#include "scene/meshes/convex_hull.h"
#include "scene/extrusions/openscad_tessellation.h"
#include "scene/reading/scene_args.h"
#include "scene/meshes/scene_meshes.h"
#include "scene/reading/scene_modules.h"
#include "scene/meshes/scene_surface.h"

#include <fmt/format.h>

#include <memory>
#include <vector>

namespace capsim::scene_file {

namespace {

// The points of one subtree, and whether they are a convex solid's corners
// (a lone convex solid: a primitive, a hull, a minkowski, a convex mesh).
struct Points {
  std::vector<glm::dvec3> at;
  bool convex = true;
  int solids = 0;  // solids met, for the convexity of a union
};

bool drawn(const Call& call) {
  for (const Modifier& m : call.modifiers) {
    if (m.symbol == '!') throw SceneError(m.loc, "the '!' (root) modifier is not supported inside hull() or minkowski()");
    if (m.symbol == '%' || m.symbol == '*') return false;
  }
  return true;
}

void add_transformed(const std::vector<glm::dvec3>& points, const glm::dmat4& m, Points& out) {
  for (const glm::dvec3& p : points) out.at.push_back(glm::dvec3(m * glm::dvec4(p, 1.0)));
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

void add_mesh(const Primitive& p, const glm::dmat4& m, Points& out) {
  add_transformed(p.mesh->vertices, m * p.to_world, out);
  out.convex = out.convex && is_convex(*p.mesh);
  ++out.solids;
}

std::vector<glm::dvec3> summed_points(const Call& call, const FileAccess& files);
void read_hull_arguments(const Call& call);

class PointCollector {
 public:
  explicit PointCollector(const FileAccess& files) : files_(files) {}

  void collect(const Call& call, const glm::dmat4& m, Points& out) {
    if (!drawn(call)) return;
    const std::string_view n = call.name;
    if (n == "sphere" || n == "cube" || n == "cylinder") {
      no_children(call);
      add_transformed(tessellate_primitive(call).points, m, out);
      ++out.solids;
    } else if (n == "import") {
      no_children(call);
      for (const Primitive& p : read_import(call, files_.import_dir, files_.max_bytes)) add_mesh(p, m, out);
    } else if (n == "polyhedron" || n == "surface") {
      no_children(call);
      add_mesh(n == "polyhedron" ? read_polyhedron(call) : read_surface(call, files_.import_dir, files_.max_bytes),
               m, out);
    } else if (n == "hull") {
      read_hull_arguments(call);
      Points inner;
      for (const Call& child : call.children) collect(child, m, inner);
      out.at.insert(out.at.end(), inner.at.begin(), inner.at.end());
      ++out.solids;
    } else if (n == "minkowski") {
      read_hull_arguments(call);
      add_transformed(summed_points(call, files_), m, out);
      ++out.solids;
    } else if (n == "multmatrix" || n == "translate" || n == "rotate" || n == "scale" || n == "mirror") {
      const glm::dmat4 inner = m * read_transform(call);
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
    } else if (n == "difference" || n == "intersection") {
      throw SceneError(call.loc, fmt::format("{}() under hull() or minkowski() is not supported: its points are "
                                             "those of the solid it evaluates, and capsim traces CSG exactly without "
                                             "ever meshing it",
                                             n));
    } else {
      throw SceneError(call.loc, fmt::format("{}() under hull() or minkowski() is not supported: capsim takes the "
                                             "points of sphere, cube, cylinder, polyhedron, import, surface, hull and "
                                             "minkowski, under transforms, union, color and render",
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

// The corners of the hull of a minkowski's children's point sums.
std::vector<glm::dvec3> summed_points(const Call& call, const FileAccess& files) {
  PointCollector collector(files);
  std::vector<glm::dvec3> sum;
  bool first = true;
  for (const Call& child : call.children) {
    Points part;
    collector.collect(child, glm::dmat4(1.0), part);
    if (part.at.empty()) continue;
    if (!part.convex || part.solids > 1)
      throw SceneError(child.loc, fmt::format("minkowski() of this child is not supported: it is not a single convex "
                                              "solid ({}), and capsim sums convex solids only (the hull of their "
                                              "points' sums); wrap it in hull() if its hull is meant",
                                              part.solids > 1 ? "a union of several solids" : "a non-convex mesh"));
    // Only the corners of each part's hull matter to the sum.
    std::vector<glm::dvec3> corners = part.at.size() >= 4 ? hull_of(part.at, child).vertices : part.at;
    if (first) {
      sum = std::move(corners);
      first = false;
      continue;
    }
    if (static_cast<double>(sum.size()) * static_cast<double>(corners.size()) > static_cast<double>(kMaxTessellatedPoints))
      throw SceneError(child.loc, fmt::format("minkowski() would sum {} by {} points, more than the {} capsim takes "
                                              "the hull of",
                                              sum.size(), corners.size(), kMaxTessellatedPoints));
    std::vector<glm::dvec3> next;
    next.reserve(sum.size() * corners.size());
    for (const glm::dvec3& a : sum)
      for (const glm::dvec3& b : corners) next.push_back(a + b);
    sum = hull_of(next, call).vertices;
  }
  return sum;
}

// hull() and minkowski() take only OpenSCAD's preview hint.
void read_hull_arguments(const Call& call) {
  Args args(call, {}, {"convexity"});
  args.number("convexity", 1);
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
  Points points;
  PointCollector collector(files);
  for (const Call& child : call.children) collector.collect(child, glm::dmat4(1.0), points);
  return mesh_leaf(hull_of(points.at, call), call);
}

Primitive read_minkowski(const Call& call, const FileAccess& files) {
  read_hull_arguments(call);
  return mesh_leaf(hull_of(summed_points(call, files), call), call);
}

}  // namespace capsim::scene_file
