// Solids read as OpenSCAD's meshes of them, under their CSG tree.

#include "scene/meshes/meshed_solids.h"

#include "scene/extrusions/extruded_region.h"
#include "scene/extrusions/openscad_tessellation.h"
#include "scene/extrusions/revolved_mesh.h"
#include "scene/extrusions/scene_revolve.h"
#include "scene/meshes/scene_meshes.h"
#include "scene/meshes/scene_resize.h"
#include "scene/meshes/scene_surface.h"
#include "scene/reading/scene_args.h"
#include "scene/reading/scene_modules.h"
#include "scene/regions/region_2d.h"

#include <fmt/format.h>

#include <cstdint>
#include <optional>
#include <string>

namespace capsim::scene_file {
namespace {

class SolidReader {
 public:
  SolidReader(const FileAccess& files, const MeshingContext& context) : files_(files), context_(context) {}

  // The call's solid placed by m, or nullopt when it is left out.
  std::optional<CsgNode> read(const Call& call, const glm::dmat4& m) {
    for (const Modifier& mod : call.modifiers) {
      if (mod.symbol == '!')
        throw SceneError(mod.loc, fmt::format("the '!' (root) modifier is not supported inside {}", context_.inside));
      if (mod.symbol == '%' || mod.symbol == '*') return std::nullopt;
    }
    const std::string_view n = call.name;
    if (n == "sphere" || n == "cube" || n == "cylinder") {
      no_children(call);
      MeshBuild built = build_closed_mesh(tessellate_primitive(call));
      if (!built.mesh) throw SceneError(call.loc, fmt::format("{}() under {} has no volume", n, context_.inside));
      return leaf(*built.mesh, m, call);
    }
    if (n == "import") {
      no_children(call);
      return union_of(read_import(call, files_.import_dir, files_.max_bytes), m, call);  // the file's objects
    }
    if (n == "polyhedron" || n == "surface" || n == "hull") {
      if (n != "hull") no_children(call);
      const Primitive p = n == "polyhedron" ? read_polyhedron(call)
                          : n == "surface"  ? read_surface(call, files_.import_dir, files_.max_bytes)
                                            : read_hull(call, files_);
      return leaf(*p.mesh, m * p.to_world, call);
    }
    if (n == "minkowski") return union_of(read_minkowski(call, files_), m, call);  // its convex parts
    if (n == "linear_extrude") return extrusion(call, m);
    if (n == "rotate_extrude") return revolution(call, m);
    if (n == "multmatrix" || n == "translate" || n == "rotate" || n == "scale" || n == "mirror") {
      return group(call, m * read_transform(call), CsgOp::Union);
    }
    if (n == "resize") return group(call, m * read_resize(call, files_), CsgOp::Union);
    if (n == "union" || n == "group" || n == "render" || n == "color" || n == "material") {
      if (n == "color") {
        read_color(call);
      } else if (n == "material") {
        read_material(call, Material{});
      } else {
        read_pass_through(call);
      }
      return group(call, m, CsgOp::Union);
    }
    if (n == "difference" || n == "intersection") {
      read_pass_through(call);
      return group(call, m, n == "difference" ? CsgOp::Difference : CsgOp::Intersection);
    }
    throw SceneError(call.loc, fmt::format("{}() under {} is not supported: capsim {} sphere, cube, "
                                           "cylinder, polyhedron, import, surface, hull, minkowski, "
                                           "linear_extrude and rotate_extrude, under transforms, union, difference and intersection",
                                           n, context_.inside, context_.does));
  }

  std::vector<TriangleMesh> meshes;
  std::vector<bool> hole;

 private:
  static void no_children(const Call& call) {
    if (call.has_body)
      throw SceneError(call.body_loc, fmt::format("{}() takes no children (missing ';' after {}(...)?)", call.name,
                                                  call.name));
  }

  CsgNode leaf(const TriangleMesh& mesh, const glm::dmat4& m, const Call& call) {
    TriangleMesh placed;
    placed.triangles = mesh.triangles;
    placed.vertices.reserve(mesh.vertices.size());
    for (const glm::dvec3& v : mesh.vertices) {
      placed.vertices.push_back(glm::dvec3(m * glm::dvec4(v, 1.0)));
      placed.bounds.extend(placed.vertices.back());
    }
    meshes.push_back(std::move(placed));
    hole.push_back(false);
    CsgNode node;
    node.is_leaf = true;
    node.primitive = static_cast<int>(meshes.size()) - 1;
    node.loc = call.loc;
    return node;
  }

  // The union of mesh primitives' leaves.
  CsgNode union_of(const std::vector<Primitive>& meshes, const glm::dmat4& m, const Call& call) {
    CsgNode node;
    node.op = CsgOp::Union;
    node.loc = call.loc;
    for (const Primitive& p : meshes) node.children.push_back(leaf(*p.mesh, m * p.to_world, call));
    return node;
  }

  // linear_extrude: its region's paths swept, and the region's even-odd
  // rule as CSG: each outline less the paths directly in it.
  CsgNode extrusion(const Call& call, const glm::dmat4& m) {
    const ExtrudedRegion region = extruded_region(call, {files_.import_dir, files_.max_bytes}, context_.inside);
    const glm::dmat4 placed = m * region.to_call;
    const std::size_t n = region.meshes.size();
    std::vector<CsgNode> leaves;
    for (const TriangleMesh& mesh : region.meshes) leaves.push_back(leaf(mesh, placed, call));
    CsgNode node;
    node.op = CsgOp::Union;
    node.loc = call.loc;
    for (std::size_t k = 0; k < n; ++k) {
      if (!region.outline(k)) continue;
      CsgNode outline;
      outline.op = CsgOp::Difference;
      outline.loc = call.loc;
      outline.children.push_back(leaves[k]);
      for (std::size_t h = 0; h < n; ++h) {
        if (region.parent[h] != static_cast<int>(k)) continue;
        outline.children.push_back(leaves[h]);
        hole[static_cast<std::size_t>(leaves[h].primitive)] = true;
      }
      node.children.push_back(std::move(outline));
    }
    return node;
  }

  // rotate_extrude: OpenSCAD's polyhedron of it (scene/extrusions/revolved_mesh.h)
  // from OpenSCAD's 2-D shape of the children, unrounded (no clipping past
  // OpenSCAD's own). Each outline's surface is closed, and they go into one
  // mesh: a vertical line's crossings, paired, then meet the solid under the
  // even-odd rule the outlines are read by, with no nesting to find.
  CsgNode revolution(const Call& call, const glm::dmat4& m) {
    const Revolve r = read_rotate_extrude(call);
    const Polygon2d shape = evaluate_region(as_union(call), {files_.import_dir, files_.max_bytes});
    const RevolvedMeshing plan = plan_revolved_mesh(shape, r.angle, read_resolution(call, false), call.loc);
    TriangleMesh all;
    for (const Outline2d& o : shape.outlines) {
      MeshBuild built = build_closed_mesh(revolved_outline_mesh(o.vertices, plan));
      if (!built.mesh)
        throw SceneError(call.loc, fmt::format("rotate_extrude() under {}: {}", context_.inside, built.defect.reason));
      const auto base = static_cast<std::uint32_t>(all.vertices.size());
      all.vertices.insert(all.vertices.end(), built.mesh->vertices.begin(), built.mesh->vertices.end());
      for (const auto& t : built.mesh->triangles) all.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    }
    return leaf(all, m, call);
  }

  // An extrusion's children as one 2-D union.
  static Call as_union(const Call& call) {
    Call shape = call;
    shape.name = "union";
    shape.args.clear();
    shape.modifiers.clear();
    return shape;
  }

  // An operator over the children; a difference or intersection's first
  // child decides, so a dropped first child leaves the rest to the next.
  CsgNode group(const Call& call, const glm::dmat4& m, CsgOp op) {
    CsgNode node;
    node.op = op;
    node.loc = call.loc;
    for (const Call& child : call.children)
      if (std::optional<CsgNode> c = read(child, m)) node.children.push_back(std::move(*c));
    return node;
  }

  const FileAccess& files_;
  const MeshingContext& context_;
};

}  // namespace

MeshedSolids read_meshed_solids(std::span<const Call> calls, const FileAccess& files, const MeshingContext& context) {
  SolidReader reader(files, context);
  MeshedSolids solids;
  solids.root.op = CsgOp::Union;
  for (const Call& call : calls)
    if (std::optional<CsgNode> c = reader.read(call, glm::dmat4(1.0))) solids.root.children.push_back(std::move(*c));
  solids.meshes = std::move(reader.meshes);
  solids.hole = std::move(reader.hole);
  return solids;
}

namespace {

std::optional<Aabb> bounds_of(const CsgNode& node, const MeshedSolids& solids) {
  if (node.is_leaf) return solids.meshes.at(static_cast<std::size_t>(node.primitive)).bounds;
  if (node.op == CsgOp::Difference && !node.children.empty()) {
    for (std::size_t k = 1; k < node.children.size(); ++k) {
      const CsgNode& cut = node.children[k];
      if (!cut.is_leaf || !solids.hole.at(static_cast<std::size_t>(cut.primitive))) return std::nullopt;
    }
    return bounds_of(node.children.front(), solids);
  }
  if (node.op != CsgOp::Union) return std::nullopt;
  Aabb box;
  for (const CsgNode& child : node.children) {
    const std::optional<Aabb> b = bounds_of(child, solids);
    if (!b) return std::nullopt;
    box.extend(*b);
  }
  return box;
}

}  // namespace

std::optional<Aabb> known_bounds(const MeshedSolids& solids) { return bounds_of(solids.root, solids); }

bool only_unions(const CsgNode& node) {
  if (node.is_leaf) return true;
  if (node.op != CsgOp::Union) return false;
  for (const CsgNode& child : node.children)
    if (!only_unions(child)) return false;
  return true;
}

}  // namespace capsim::scene_file
