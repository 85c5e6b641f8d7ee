// Scene files: tokens -> module calls -> Scene. This file walks the tree of calls:
// it applies modifiers, composes transforms, colours and materials down the
// tree, builds the CSG nodes and collects camera, lights and background.
// scene_modules.cpp knows what each call's arguments mean.

#include "capsim/scene/parser.h"

#include "capsim/scene/scene_limits.h"
#include "capsim/system/huge_pages.h"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <memory_resource>
#include <optional>
#include <span>

#include "scene/reading/scene_args.h"
#include "scene/extrusions/scene_extrusion.h"
#include "scene/meshes/scene_hulls.h"
#include "scene/reading/scene_lexer.h"
#include "scene/meshes/scene_meshes.h"
#include "scene/meshes/scene_resize.h"
#include "scene/reading/scene_modules.h"
#include "scene/meshes/scene_surface.h"
#include "scene/extrusions/scene_revolve.h"
#include "scene/reading/scene_syntax.h"
#include "scene/regions/region_2d.h"

namespace capsim {
namespace {

using scene_file::Call;
using scene_file::Loc;

constexpr std::string_view kSupported =
    "sphere, cube, cylinder, polyhedron, import (STL, OFF, AMF, 3MF), surface, hull, minkowski, linear_extrude and rotate_extrude of square, circle, polygon, text, offset, projection, hull, minkowski and import (DXF, SVG), 2-D shapes alone (drawn 1 unit thick), multmatrix, translate, rotate, scale, mirror, resize, union, difference, "
    "intersection, group, render, color, material, camera, light, background";

bool is_primitive(std::string_view n) {
  return n == "sphere" || n == "cube" || n == "cylinder" || n == "polyhedron" || n == "import" || n == "surface";
}
bool is_transform(std::string_view n) {
  return n == "multmatrix" || n == "translate" || n == "rotate" || n == "scale" || n == "mirror" || n == "resize";
}
// Solids built out of their children's points (scene_hulls.h).
bool is_point_hull(std::string_view n) { return n == "hull" || n == "minkowski"; }
bool is_setting(std::string_view n) { return n == "camera" || n == "light" || n == "background"; }
bool is_shape_2d(std::string_view n) { return n == "square" || n == "circle" || n == "polygon" || n == "text"; }
bool is_object(std::string_view n) {
  return is_primitive(n) || n == "linear_extrude" || n == "rotate_extrude" || is_transform(n) || n == "union" || n == "difference" ||
         n == "intersection" || n == "group" || n == "render" || n == "color" || n == "material";
}

// A 2-D affine transform (homogeneous, its last row 0 0 1) as the 3-D one
// it is on the plane z = 0: x and y map as in the plane, z is kept.
glm::dmat4 widened(const glm::dmat3& plane) {
  glm::dmat4 m(1.0);
  m[0] = glm::dvec4(glm::dvec2(plane[0]), 0, 0);
  m[1] = glm::dvec4(glm::dvec2(plane[1]), 0, 0);
  m[3] = glm::dvec4(glm::dvec2(plane[2]), 0, 1);
  return m;
}

// OpenSCAD modules outside the subset, with why they are refused: what the
// module would need that capsim does not have.
std::optional<std::string_view> unsupported_reason(std::string_view n) {
  if (is_shape_2d(n))
    return "a 2-D shape is drawn only extruded, under linear_extrude(); capsim renders solids, and a 2-D shape "
           "alone has none";
  for (std::string_view m : {"children", "parent_module", "import_stl", "import_off", "import_dxf",
                             "dxf_linear_extrude", "dxf_rotate_extrude"}) {
    if (n == m) return "it is not part of a plain CSG tree";
  }
  return std::nullopt;
}

[[gnu::noinline]] SceneError module_error(const Call& call) {
  if (auto reason = unsupported_reason(call.name)) {
    return SceneError(call.loc, fmt::format("'{}' is not supported: {}; supported: {}", call.name,
                                            *reason, kSupported));
  }
  std::vector<std::string> known;
  for (std::string_view n : {"sphere", "cube", "cylinder", "polyhedron", "import", "surface", "hull", "minkowski", "linear_extrude", "rotate_extrude", "offset", "projection", "multmatrix", "translate", "rotate",
                             "scale", "mirror", "resize", "union", "difference", "intersection", "group",
                             "render", "color", "material", "camera", "light", "background"}) {
    known.emplace_back(n);
  }
  std::string guess = scene_file::closest_name(call.name, known);
  return SceneError(
      call.loc,
      fmt::format("unknown module '{}'{}; supported: {}", call.name,
                  guess.empty() ? "" : fmt::format(" (did you mean '{}'?)", guess), kSupported));
}

// One error for several, in file order: the first's place, and a message
// that continues with each other error's own line, then "and N more errors".
SceneError listed(const std::vector<SceneError>& errors, std::size_t unlisted) {
  std::string message = errors.front().message();
  for (std::size_t i = 1; i < errors.size(); ++i) message += fmt::format("\n{}", errors[i].what());
  if (unlisted > 0) message += fmt::format("\nand {} more error{}", unlisted, unlisted == 1 ? "" : "s");
  return SceneError(errors.front().loc(), message);
}

// What the enclosing calls hand down to a subtree.
struct Context {
  glm::dmat4 transform{1.0};
  glm::dvec3 color = Primitive{}.color;
  double alpha = 1;
  Material material;
  bool dropped = false;  // inside a '%' or '*' subtree: parsed and checked, then discarded
};

// The walk recurses a few frames per level of the tree, and a tree may be
// scene_file::kMaxNestingDepth levels deep, so the recursive functions keep
// their frames small: contexts live in Interpreter::contexts_, and the work of
// a level that needs large locals (matrices, argument tables, messages) is
// done in helpers kept out of line, whose frames are gone before the walk goes
// a level deeper.
class Interpreter {
 public:
  Interpreter(std::shared_ptr<const std::string> file, const ParseLimits& limits, std::string import_dir)
      : file_(std::move(file)), max_primitives_(limits.max_primitives), max_file_bytes_(limits.max_file_bytes),
        import_dir_(std::move(import_dir)) {}

  // Every module outside the subset is reported, in file order, with the
  // first other error if one follows them (that one ends the walk).
  Scene run(std::span<const Call> calls, bool file_has_tokens, const Loc& end) {
    std::optional<Scene> scene;
    try {
      scene = walk(calls, file_has_tokens, end);
    } catch (const SceneError& e) {
      if (module_errors_.empty()) throw;
      note(e);
    }
    if (!module_errors_.empty()) throw listed(module_errors_, unlisted_errors_);
    return std::move(*scene);
  }

 private:
  Scene walk(std::span<const Call> calls, bool file_has_tokens, const Loc& end) {
    CsgNode root;
    root.op = CsgOp::Union;
    root.loc = SourceLoc{file_, 1, 1};
    root.children.reserve(calls.size());
    // Room for the primitives at once: a large scene's would otherwise be
    // copied at each doubling, each time into fresh memory.
    all_primitives_.reserve(std::min(primitive_calls(calls), max_primitives_));
    int objects = 0;
    contexts_.emplace_back();  // the top level's
    for (const Call& call : calls) {
      if (is_setting(call.name)) {
        setting(call);
        continue;
      }
      ++objects;
      if (auto node = object(call, 0, "")) root.children.push_back(std::move(*node));
    }
    if (!module_errors_.empty()) return {};  // reported by run
    if (objects == 0) {
      throw SceneError(end, file_has_tokens
                                ? fmt::format("scene has no objects; add at least one of {}",
                                              "sphere, cube or cylinder")
                                : "empty scene file: no objects; add at least one of sphere, cube "
                                  "or cylinder");
    }
    if (root_) root.children = {std::move(*root_)};
    // Keep only the primitives the final tree uses, numbered in file order:
    // usually all of them in the order made, and then the list is the scene's.
    if (std::size_t next = 0; numbers_all_in_order(root, next) && next == all_primitives_.size()) {
      scene_.primitives = std::move(all_primitives_);
    } else {
      scene_.primitives.reserve(all_primitives_.size());
      compact(root);
    }
    scene_.root = std::move(root);
    return std::move(scene_);
  }

  // An index into contexts_.
  using ContextId = std::size_t;

  void note(const SceneError& e) {
    if (module_errors_.size() < kMaxListedSceneErrors) {
      module_errors_.push_back(e);
    } else {
      ++unlisted_errors_;
    }
  }

  // A module outside the subset: noted, and its children walked as a dropped
  // subtree, so that every unsupported module under it is noted too.
  [[gnu::noinline]] void unsupported_module(const Call& call, ContextId ctx) {
    note(module_error(call));
    children(call, push_dropped(ctx));
    contexts_.pop_back();
  }

  // The context of a subtree that is read and checked, then left out.
  ContextId push_dropped(ContextId ctx) {
    Context inner = contexts_[ctx];
    inner.dropped = true;
    contexts_.push_back(inner);
    return contexts_.size() - 1;
  }

  void setting(const Call& call) {
    if (!call.modifiers.empty()) {
      throw SceneError(call.modifiers.front().loc,
                       fmt::format("modifier '{}' applies only to objects, not to {}()",
                                   call.modifiers.front().symbol, call.name));
    }
    no_children(call);
    if (call.name == "camera") {
      if (camera_loc_) {
        throw SceneError(call.loc, fmt::format("at most one camera() statement is allowed; the "
                                               "first is at {}:{}",
                                               camera_loc_->line, camera_loc_->col));
      }
      scene_.camera = scene_file::read_camera(call);
      camera_loc_ = call.loc;
    } else if (call.name == "light") {
      scene_.lights.push_back(scene_file::read_light(call));
    } else {
      if (background_loc_) {
        throw SceneError(call.loc, fmt::format("at most one background() statement is allowed; "
                                               "the first is at {}:{}",
                                               background_loc_->line, background_loc_->col));
      }
      scene_.background = scene_file::read_background(call);
      background_loc_ = call.loc;
    }
  }

  void no_children(const Call& call) {
    if (call.has_body) refuse_children(call);
  }

  [[noreturn, gnu::noinline]] void refuse_children(const Call& call) {
    throw SceneError(call.body_loc, fmt::format("{}() takes no children (missing ';' after "
                                                "{}(...)?)",
                                                call.name, call.name));
  }

  // A call with its modifiers applied; empty when it contributes nothing here.
  // `parent` is the enclosing call's name, "" at the top level.
  std::optional<CsgNode> object(const Call& call, ContextId ctx, std::string_view parent) {
    const scene_file::Modifier* drop = nullptr;
    const scene_file::Modifier* root = nullptr;
    for (const auto& m : call.modifiers) {
      if (m.symbol == '%' || m.symbol == '*') drop = drop ? drop : &m;
      if (m.symbol == '!') root = root ? root : &m;
      if (drop && root) refuse_modifiers(*drop, *root, m.loc);
    }
    if (is_setting(call.name)) refuse_setting_inside(call, parent);
    if (root && !contexts_[ctx].dropped) {
      root_subtree(call, *root);
      return std::nullopt;
    }
    if (drop) {
      dropped_subtree(call, ctx);
      return std::nullopt;
    }
    return build(call, ctx);
  }

  [[noreturn, gnu::noinline]] void refuse_modifiers(const scene_file::Modifier& drop,
                                                    const scene_file::Modifier& root,
                                                    const Loc& at) {
    throw SceneError(at, fmt::format("modifiers '{}' and '{}' contradict each other", drop.symbol,
                                     root.symbol));
  }

  [[noreturn, gnu::noinline]] void refuse_setting_inside(const Call& call,
                                                         std::string_view parent) {
    throw SceneError(call.loc, fmt::format("{}() must be at the top level of the file, not "
                                           "inside {}()",
                                           call.name, parent));
  }

  // A '!' subtree: as in OpenSCAD, the marked subtree alone is the scene, and
  // nothing above it (transforms, colours, materials) applies.
  [[gnu::noinline]] void root_subtree(const Call& call, const scene_file::Modifier& mark) {
    if (root_) {
      throw SceneError(mark.loc, fmt::format("only one '!' (root) modifier is allowed; the "
                                             "first is at {}:{}",
                                             root_loc_.line, root_loc_.col));
    }
    root_loc_ = mark.loc;
    contexts_.emplace_back();
    std::optional<CsgNode> node = build(call, contexts_.size() - 1);
    contexts_.pop_back();
    root_ = node ? std::move(*node) : empty_union(call.loc);
  }

  // A '%' or '*' subtree: read and checked, then left out.
  [[gnu::noinline]] void dropped_subtree(const Call& call, ContextId ctx) {
    build(call, push_dropped(ctx));
    contexts_.pop_back();
  }

  std::optional<CsgNode> build(const Call& call, ContextId ctx) {
    std::string_view name = call.name;
    if (is_flat_design(call)) return flat_design(call, ctx);
    if (is_primitive(name)) {
      no_children(call);
      return primitive(call, ctx);
    }
    if (is_point_hull(name)) return point_hull(call, ctx);
    if (!is_object(name)) {
      unsupported_module(call, ctx);
      return std::nullopt;
    }
    if (name == "linear_extrude") return extrusion(call, ctx);
    if (name == "rotate_extrude") return revolution(call, ctx);
    if (is_transform(name) || name == "color" || name == "material") {
      const ContextId inner = enter(call, ctx);
      CsgNode node = pass_through_children(call, inner);
      contexts_.pop_back();
      return node;
    }
    scene_file::read_pass_through(call);
    if (name == "render") return pass_through_children(call, ctx);
    CsgNode node;
    node.op = name == "difference"     ? CsgOp::Difference
              : name == "intersection" ? CsgOp::Intersection
                                       : CsgOp::Union;
    node.loc = call.loc;
    node.children = children(call, ctx);
    return node;
  }

  // The context a transform, color() or material() gives its children, pushed
  // onto contexts_.
  [[gnu::noinline]] ContextId enter(const Call& call, ContextId ctx) {
    Context inner = contexts_[ctx];
    if (call.name == "resize") {
      inner.transform = inner.transform * resize_matrix(call);
    } else if (is_transform(call.name)) {
      inner.transform = inner.transform * scene_file::read_transform(call);
    } else if (call.name == "color") {
      scene_file::ColorSetting c = scene_file::read_color(call);
      if (c.linear_rgb) inner.color = *c.linear_rgb;
      inner.alpha = c.alpha;
    } else {
      inner.material = scene_file::read_material(call, inner.material);
    }
    contexts_.push_back(inner);
    return contexts_.size() - 1;
  }

  // resize() among solids, or of a 2-D design drawn flat (its x and y).
  [[gnu::noinline]] glm::dmat4 resize_matrix(const Call& call) const {
    const scene_file::FileAccess files{import_dir_, max_file_bytes_};
    if (!starts_2d(call)) return scene_file::read_resize(call, files);
    return widened(scene_file::read_resize_2d(call, files));
  }

  std::vector<CsgNode> children(const Call& call, ContextId ctx) {
    std::vector<CsgNode> out;
    out.reserve(call.children.size());
    for (const Call& child : call.children) {
      if (auto node = object(child, ctx, call.name)) out.push_back(std::move(*node));
    }
    return out;
  }

  // Transforms, colours, materials and render() are not CSG operators: one child
  // passes through, several form their union (as in OpenSCAD).
  CsgNode pass_through_children(const Call& call, ContextId ctx) {
    // A single child, by far the most common case, needs no list of nodes.
    if (call.children.size() == 1) {
      std::optional<CsgNode> node = object(call.children.front(), ctx, call.name);
      return node ? std::move(*node) : empty_union(call.loc);
    }
    return pass_through(call, children(call, ctx));
  }

  CsgNode pass_through(const Call& call, std::vector<CsgNode> nodes) {
    if (nodes.size() == 1) return std::move(nodes.front());
    CsgNode node = empty_union(call.loc);
    node.children = std::move(nodes);
    return node;
  }

  CsgNode empty_union(const Loc& loc) {
    CsgNode node;
    node.op = CsgOp::Union;
    node.loc = loc;
    return node;
  }

  [[gnu::noinline]] CsgNode primitive(const Call& call, ContextId id) {
    if (call.name == "import") {
      // A file of several objects (AMF, 3MF) is their union, as in OpenSCAD.
      std::vector<CsgNode> leaves;
      for (Primitive& p : scene_file::read_import(call, import_dir_, max_file_bytes_))
        leaves.push_back(place(std::move(p), call, id));
      return pass_through(call, std::move(leaves));
    }
    return place(call.name == "polyhedron" ? scene_file::read_polyhedron(call)
                 : call.name == "surface"  ? scene_file::read_surface(call, import_dir_, max_file_bytes_)
                                           : scene_file::read_primitive(call),
                 call, id);
  }

  // hull() or minkowski(): mesh leaves made of the children's points (one
  // for a hull, the union of a minkowski's convex parts), in the colour and
  // material around it (OpenSCAD's too).
  [[gnu::noinline]] CsgNode point_hull(const Call& call, ContextId id) {
    const scene_file::FileAccess files{import_dir_, max_file_bytes_};
    if (call.name == "hull") return place(scene_file::read_hull(call, files), call, id);
    std::vector<CsgNode> leaves;
    for (Primitive& p : scene_file::read_minkowski(call, files)) leaves.push_back(place(std::move(p), call, id));
    return pass_through(call, std::move(leaves));
  }

  // A primitive read from `call`, placed by the context's transforms, with its
  // colour and material: a leaf.
  [[gnu::noinline]] CsgNode place(Primitive p, const Call& call, ContextId id) {
    if (all_primitives_.size() == max_primitives_) {
      throw SceneError(call.loc, fmt::format("more than {} primitives: capsim reads at most {} "
                                             "(each needs about 1.7 KB of memory until it is "
                                             "traced)",
                                             max_primitives_, max_primitives_));
    }
    const Context& ctx = contexts_[id];
    p.to_world = ctx.transform * p.to_world;
    bool finite = true;
    for (int c = 0; c < 4; ++c) {
      for (int r = 0; r < 4; ++r) finite = finite && std::isfinite(p.to_world[c][r]);
    }
    if (!finite || scene_file::is_singular(p.to_world)) {
      throw SceneError(call.loc, fmt::format("{} is placed by a singular or overflowing transform "
                                             "(the transforms around it flatten it or exceed the "
                                             "range of a double)",
                                             call.name));
    }
    check_placement(call, p);
    p.color = ctx.color;
    p.alpha = ctx.alpha;
    p.material = ctx.material;
    all_primitives_.push_back(std::move(p));
    CsgNode leaf;
    leaf.is_leaf = true;
    leaf.primitive = static_cast<int>(all_primitives_.size()) - 1;
    leaf.loc = call.loc;
    return leaf;
  }

  // The range of scene_limits.h a placed primitive must keep to, whatever the
  // transforms around it: its bounding box within kMaxLength of the origin,
  // and no dimension below kMinLength.
  static void check_placement(const Call& call, const Primitive& p) {
    static_assert(kMinLength == 1e-30 && kMaxLength == 1e30, "the messages name the range");
    const Aabb bounds = placed_bounds(p);
    const glm::dvec3 far = glm::max(glm::abs(bounds.lo), glm::abs(bounds.hi));
    const double reach = std::max({far.x, far.y, far.z});
    if (!(reach <= kMaxLength)) {
      throw SceneError(call.loc, fmt::format("{} is placed beyond the coordinates capsim traces: "
                                             "its bounding box reaches {:g} from the origin, past "
                                             "1e30",
                                             call.name, reach));
    }
    const double stretch = smallest_stretch(glm::dmat3(p.to_world));
    if (!(stretch >= kMinLength)) {
      throw SceneError(call.loc, fmt::format("{} is smaller than capsim traces: its smallest "
                                             "dimension is {:g}, below 1e-30",
                                             call.name, stretch));
    }
  }

  // linear_extrude: its 2-D tree as a 3-D one over extruded leaves
  // (scene_extrusion.h). With more than one leaf, a slab cut gives the caps.
  [[gnu::noinline]] std::optional<CsgNode> extrusion(const Call& call, ContextId ctx) {
    return extruded(call, call.children, ctx, scene_file::read_linear_extrude(call));
  }

  // The extrusion `e` of the 2-D calls `shapes`, named by `call`.
  std::optional<CsgNode> extruded(const Call& call, std::span<const Call> shapes, ContextId ctx,
                                  scene_file::Extrusion e) {
    const bool lone = shape_leaves(shapes) == 1;
    if (!lone) scene_file::extend_beyond_caps(e);
    if (e.curved() && e.slices == 0) e.slices = curved_extrusion_slices(shapes, ctx, e);
    const std::size_t first = all_primitives_.size();
    std::vector<CsgNode> kids;
    for (const Call& child : shapes) {
      // A 2-D-only design is its own shape, its modifiers already applied.
      auto node = &child == &call ? shape_node(child, ctx, glm::dmat3(1.0), e) : shape(child, ctx, glm::dmat3(1.0), e);
      if (node) kids.push_back(std::move(*node));
    }
    if (kids.empty()) return empty_union(call.loc);
    CsgNode tree = pass_through(call, std::move(kids));
    if (lone) return tree;
    const std::vector<Primitive> leaves(all_primitives_.begin() + static_cast<std::ptrdiff_t>(first),
                                        all_primitives_.end());
    glm::dmat4 inverse = glm::inverse(contexts_[ctx].transform);
    std::vector<Primitive> local;
    for (Primitive p : leaves) {
      p.to_world = inverse * p.to_world;
      local.push_back(std::move(p));
    }
    CsgNode cut;
    cut.op = CsgOp::Intersection;
    cut.loc = call.loc;
    cut.children.push_back(place(scene_file::extrusion_slab(local, e, call.loc), call, ctx));
    cut.children.push_back(std::move(tree));
    return cut;
  }

  // OpenSCAD's slices for a curved extrusion that names none: they depend on
  // the shape's points, so the shape is read once with one slice for them,
  // then left out (its leaves and any notes), to be read again.
  [[gnu::noinline]] int curved_extrusion_slices(std::span<const Call> shapes, ContextId ctx, scene_file::Extrusion e) {
    e.slices = 1;
    e.collars = false;
    const std::size_t first = all_primitives_.size(), noted = module_errors_.size(), unlisted = unlisted_errors_;
    for (const Call& child : shapes) shape(child, ctx, glm::dmat3(1.0), e);
    std::vector<glm::dvec2> bottom;  // the leaves' points at z = 0, as the shape has them
    for (std::size_t k = first; k < all_primitives_.size(); ++k)
      for (const glm::dvec3& v : all_primitives_[k].mesh->vertices)
        if (v.z == 0) bottom.emplace_back(v.x, v.y);
    all_primitives_.erase(all_primitives_.begin() + static_cast<std::ptrdiff_t>(first), all_primitives_.end());
    module_errors_.erase(module_errors_.begin() + static_cast<std::ptrdiff_t>(noted), module_errors_.end());
    unlisted_errors_ = unlisted;
    return scene_file::extrusion_slices(bottom, e);
  }

  // rotate_extrude: its 2-D tree as a 3-D one over revolved leaves
  // (scene_revolve.h), each leaf exact and the wedge part of each.
  [[gnu::noinline]] std::optional<CsgNode> revolution(const Call& call, ContextId ctx) {
    const scene_file::Revolve r = scene_file::read_rotate_extrude(call);
    revolve_ = r;
    std::vector<CsgNode> kids;
    for (const Call& child : call.children)
      if (auto node = shape(child, ctx, glm::dmat3(1.0), scene_file::Extrusion{})) kids.push_back(std::move(*node));
    revolve_.reset();
    if (kids.empty()) return empty_union(call.loc);
    CsgNode tree = pass_through(call, std::move(kids));
    scene_file::finish_revolution(tree, all_primitives_, r, call.loc);
    return tree;
  }

  // The 2-D leaves under an extrusion that are drawn (a polygon with holes
  // counts each path).
  static int shape_leaves(std::span<const Call> shapes) {
    int n = 0;
    for (const Call& child : shapes) {
      bool dropped = false;
      for (const auto& m : child.modifiers) dropped = dropped || m.symbol == '%' || m.symbol == '*';
      if (dropped) continue;
      if (child.name == "polygon" || child.name == "text" || scene_file::needs_clipping(child)) {
        n += 2;  // holes or not: the slab is harmless for one path
      } else if (is_shape_2d(child.name)) {
        ++n;
      } else {
        n += shape_leaves(child.children);
      }
    }
    return n;
  }

  // A call under linear_extrude, `plane` the 2-D transforms above it.
  std::optional<CsgNode> shape(const Call& call, ContextId ctx, const glm::dmat3& plane,
                               const scene_file::Extrusion& e) {
    for (const auto& m : call.modifiers) {
      if (m.symbol == '!')
        throw SceneError(m.loc, fmt::format("the '!' (root) modifier is not supported inside {}()",
                                            revolve_ ? "rotate_extrude" : "linear_extrude"));
      if (m.symbol == '%' || m.symbol == '*') {
        // Read and checked, then left out.
        shape_node(call, push_dropped(ctx), plane, e);
        contexts_.pop_back();
        return std::nullopt;
      }
    }
    return shape_node(call, ctx, plane, e);
  }

  [[gnu::noinline]] std::optional<CsgNode> shape_node(const Call& call, ContextId ctx, const glm::dmat3& plane,
                                                      const scene_file::Extrusion& e) {
    const std::string_view name = call.name;
    if (scene_file::needs_clipping(call)) return clipped_node(call, ctx, plane, e);
    if (revolve_ && is_shape_2d(name)) {
      no_children(call);
      return place(scene_file::revolve_shape(call, plane, *revolve_), call, ctx);
    }
    if (name == "circle" || name == "square") {
      no_children(call);
      return place(name == "circle" ? scene_file::extrude_circle(call, plane, e)
                                    : scene_file::extrude_square(call, plane, e),
                   call, ctx);
    }
    if (name == "polygon" || name == "text") {
      no_children(call);
      return polygon_node(call,
                          name == "polygon" ? scene_file::extrude_polygon(call, plane, e)
                                            : scene_file::extrude_text(call, plane, e),
                          ctx);
    }
    const bool is_group = name == "union" || name == "difference" || name == "intersection" || name == "group" ||
                          name == "render";
    if (!is_group && !is_transform(name) && name != "color" && name != "material") {
      if (name == "import") {
        throw SceneError(call.loc, fmt::format("import() of a mesh (STL, OFF, AMF, 3MF) is not a 2-D shape: {}() extrudes "
                                               "square, circle, polygon, text, offset, projection and 2-D imports "
                                               "(DXF, SVG)",
                                               revolve_ ? "rotate_extrude" : "linear_extrude"));
      }
      if (is_object(name) || is_setting(name)) {
        throw SceneError(call.loc, fmt::format("{}() is not a 2-D shape: {}() extrudes square, circle, "
                                               "polygon and text",
                                               name, revolve_ ? "rotate_extrude" : "linear_extrude"));
      }
      // Noted, and its 2-D children read as a dropped subtree, so that every
      // unsupported module under it is noted too.
      note(module_error(call));
      const ContextId dropped = push_dropped(ctx);
      for (const Call& child : call.children) shape(child, dropped, plane, e);
      contexts_.pop_back();
      return std::nullopt;
    }
    glm::dmat3 inner = plane;
    if (is_transform(name)) {
      inner = plane * (name == "resize" ? scene_file::read_resize_2d(call, {import_dir_, max_file_bytes_})
                                        : scene_file::read_transform_2d(call));
    } else if (name == "color") {
      scene_file::read_color(call);  // the extrusion is drawn in the colour around it
    } else if (name == "material") {
      scene_file::read_material(call, contexts_[ctx].material);
    } else {
      scene_file::read_pass_through(call);
    }
    std::vector<CsgNode> kids;
    for (const Call& child : call.children)
      if (auto node = shape(child, ctx, inner, e)) kids.push_back(std::move(*node));
    if (!is_group || name == "group" || name == "render" || name == "union") return pass_through(call, std::move(kids));
    CsgNode node;
    node.op = name == "difference" ? CsgOp::Difference : CsgOp::Intersection;
    node.loc = call.loc;
    node.children = std::move(kids);
    return node;
  }

  // A 2-D subtree that must be clipped (scene/regions/region_2d.h), extruded as
  // its region's paths.
  [[gnu::noinline]] CsgNode clipped_node(const Call& call, ContextId ctx, const glm::dmat3& plane,
                                         const scene_file::Extrusion& e) {
    const scene_file::NestedPaths region = scene_file::nested_region_paths(call, plane, {import_dir_, max_file_bytes_});
    if (revolve_) {
      return place(scene_file::revolve_region(region.paths, *revolve_, call.loc), call, ctx);
    }
    return polygon_node(call, scene_file::extrude_nested_paths(region.paths, region.parent, e, call.loc), ctx);
  }

  // A 2-D shape outside any extrusion (a 2-D-only design) is drawn as
  // OpenSCAD's preview draws it: 1 unit thick, centred on z = 0.
  static bool is_flat_design(const Call& call) {
    const std::string_view name = call.name;
    if (is_shape_2d(name) || name == "offset" || name == "projection") return true;
    if (name == "import") return scene_file::is_2d_import(call);
    if (name == "difference" || name == "intersection" || is_point_hull(name)) return starts_2d(call);
    return false;
  }

  // Whether a subtree's first drawn shape is 2-D (OpenSCAD takes a
  // boolean's dimension from its first child).
  static bool starts_2d(const Call& call) {
    for (const Call& child : call.children) {
      bool dropped = false;
      for (const auto& m : child.modifiers) dropped = dropped || m.symbol == '%' || m.symbol == '*';
      if (dropped) continue;
      if (is_shape_2d(child.name) || child.name == "offset" || child.name == "projection") return true;
      if (child.name == "import") return scene_file::is_2d_import(child);
      const bool passes = is_transform(child.name) || is_point_hull(child.name) || child.name == "union" ||
                          child.name == "difference" ||
                          child.name == "intersection" || child.name == "group" || child.name == "render" ||
                          child.name == "color" || child.name == "material";
      return passes && starts_2d(child);
    }
    return false;
  }

  [[gnu::noinline]] std::optional<CsgNode> flat_design(const Call& call, ContextId ctx) {
    scene_file::Extrusion e;
    e.height = 1;
    e.center = true;
    return extruded(call, std::span<const Call>(&call, 1), ctx, e);
  }

  // The even-odd rule as CSG: the union of the outlines (paths at even
  // depth), each less the paths directly inside it.
  [[gnu::noinline]] CsgNode polygon_node(const Call& call, scene_file::ExtrudedPaths paths, ContextId ctx) {
    const std::size_t n = paths.prisms.size();
    std::vector<int> depth(n, 0);
    for (std::size_t k = 0; k < n; ++k)
      for (int at = paths.parent[k]; at >= 0; at = paths.parent[static_cast<std::size_t>(at)]) ++depth[k];
    std::vector<std::optional<CsgNode>> leaf(n);
    for (std::size_t k = 0; k < n; ++k) leaf[k] = place(std::move(paths.prisms[k]), call, ctx);
    std::vector<CsgNode> outlines;
    for (std::size_t k = 0; k < n; ++k) {
      if (depth[k] % 2) continue;
      CsgNode outline;
      outline.op = CsgOp::Difference;
      outline.loc = call.loc;
      outline.children.push_back(std::move(*leaf[k]));
      for (std::size_t h = 0; h < n; ++h)
        if (paths.parent[h] == static_cast<int>(k)) outline.children.push_back(std::move(*leaf[h]));
      outlines.push_back(outline.children.size() == 1 ? std::move(outline.children.front()) : std::move(outline));
    }
    return pass_through(call, std::move(outlines));
  }

  // How many calls of primitives the calls hold, all levels down: the
  // primitives they make when no loop or module repeats any.
  static std::size_t primitive_calls(std::span<const Call> calls) {
    std::size_t count = 0;
    for (const Call& call : calls) count += (is_primitive(call.name) ? 1 : 0) + primitive_calls(call.children);
    return count;
  }

  // Whether the leaves of `node`, in order, number the primitives from `next` on.
  static bool numbers_all_in_order(const CsgNode& node, std::size_t& next) {
    if (node.is_leaf) return node.primitive == static_cast<int>(next++);
    for (const CsgNode& child : node.children)
      if (!numbers_all_in_order(child, next)) return false;
    return true;
  }

  void compact(CsgNode& node) {
    if (node.is_leaf) {
      scene_.primitives.push_back(std::move(all_primitives_[node.primitive]));
      node.primitive = static_cast<int>(scene_.primitives.size()) - 1;
      return;
    }
    for (CsgNode& child : node.children) compact(child);
  }

  std::shared_ptr<const std::string> file_;
  std::size_t max_primitives_;
  std::size_t max_file_bytes_;  // of a file import() reads
  std::string import_dir_;      // where import() looks first
  // The contexts of the calls being walked, outermost first. Levels refer to
  // them by index, never by reference across a call, as the list grows.
  std::vector<Context> contexts_;
  Scene scene_;
  LargeVector<Primitive> all_primitives_;  // including those of dropped subtrees
  std::optional<CsgNode> root_;            // the '!' subtree, if any
  std::optional<scene_file::Revolve> revolve_;  // inside rotate_extrude: its 2-D leaves are turned
  Loc root_loc_;
  std::optional<Loc> camera_loc_;
  std::optional<Loc> background_loc_;
  std::vector<SceneError> module_errors_;  // at most kMaxListedSceneErrors
  std::size_t unlisted_errors_ = 0;        // noted past that
};

}  // namespace

namespace {

[[noreturn]] void refuse_file_size(const std::shared_ptr<const std::string>& file,
                                   std::size_t max_bytes) {
  throw SceneError(SourceLoc{file, 0, 0},
                   fmt::format("the file is larger than {} bytes ({} MiB), the most capsim reads "
                               "(reading takes up to about 100 bytes of memory per byte)",
                               max_bytes, max_bytes >> 20));
}

}  // namespace

Scene parse_scene(std::string_view text, const std::string& file_name, const ParseLimits& limits,
                  double t, const std::string& import_dir) {
  auto file = std::make_shared<const std::string>(file_name);
  if (text.size() > limits.max_file_bytes) refuse_file_size(file, limits.max_file_bytes);
  scene_file::Tokens tokens = scene_file::tokenize(text, file);
  Loc end;
  // Holds the lists of the calls (see scene_syntax.h); declared first, so it
  // outlives them.
  std::pmr::monotonic_buffer_resource memory(huge_page_resource());
  std::pmr::vector<Call> calls = scene_file::read_calls(tokens, &memory, &end, t);
  const bool has_statements = tokens.size() > 1;
  // The calls view the text, not the tokens: the tokens' memory can go back
  // before the scene is built.
  tokens.clear();
  tokens.shrink_to_fit();
  const std::string dir =
      import_dir.empty() ? std::filesystem::path(file_name).parent_path().string() : import_dir;
  return Interpreter(file, limits, dir).run(calls, has_statements, end);
}

std::string read_scene_file(const std::string& path, const ParseLimits& limits) {
  auto file = std::make_shared<const std::string>(path);
  SourceLoc whole_file{file, 0, 0};
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!f) throw SceneError(whole_file, fmt::format("cannot read: {}", std::strerror(errno)));
  // A regular file's size is known before reading; others are refused when
  // the reading passes the limit.
  std::error_code size_error;
  const std::uintmax_t size = std::filesystem::file_size(path, size_error);
  if (!size_error && size > limits.max_file_bytes) refuse_file_size(file, limits.max_file_bytes);
  std::string text;
  // Room for the whole file at once: growing by doubling would copy the text,
  // each time into fresh memory.
  if (!size_error) text.reserve(static_cast<std::size_t>(size) + 1);
  char buffer[1 << 16];
  for (;;) {
    size_t n = std::fread(buffer, 1, sizeof buffer, f.get());
    text.append(buffer, n);
    // Stops one buffer past the limit: a larger file is never held whole.
    if (text.size() > limits.max_file_bytes) refuse_file_size(file, limits.max_file_bytes);
    if (n < sizeof buffer) break;
  }
  if (std::ferror(f.get()))
    throw SceneError(whole_file, fmt::format("cannot read: {}", std::strerror(errno)));
  return text;
}

Scene parse_scene_file(const std::string& path, const ParseLimits& limits, double t,
                       const std::string& import_dir) {
  return parse_scene(read_scene_file(path, limits), path, limits, t, import_dir);
}

}  // namespace capsim
