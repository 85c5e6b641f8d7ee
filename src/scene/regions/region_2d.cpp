// The 2-D tree walk of OpenSCAD's GeometryEvaluator (2021.01) over Clipper.

#include "scene/regions/region_2d.h"

#include "scene/regions/scene_projection.h"

#include "capsim/scene/scene.h"
#include "scene/regions/dxf_import.h"
#include "scene/regions/hull_2d.h"
#include "scene/meshes/mesh_files.h"
#include "scene/reading/scene_args.h"
#include "scene/reading/scene_expression.h"
#include "scene/extrusions/scene_extrusion.h"
#include "scene/meshes/scene_meshes.h"
#include "scene/meshes/scene_resize.h"
#include "scene/reading/scene_modules.h"
#include "scene/regions/svg_import.h"
#include "scene/regions/text_glyphs.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <optional>
#include <stdexcept>

namespace capsim::scene_file {

namespace {

std::size_t vertex_count(const Polygon2d& shape) {
  std::size_t n = 0;
  for (const Outline2d& o : shape.outlines) n += o.vertices.size();
  return n;
}

void check_size(const Polygon2d& shape, const Call& call) {
  if (vertex_count(shape) > kMaxRegionVertices)
    throw SceneError(call.loc, fmt::format("{}() gives a 2-D shape of more than {} vertices, more than capsim clips",
                                           call.name, kMaxRegionVertices));
}

int fragments(const Call& call, const Args& args, double r) {
  try {
    return openscad_fragments(r, args.number("$fn", 0), args.number("$fs", 2), args.number("$fa", 12));
  } catch (const TextError& e) {
    throw SceneError(call.loc, fmt::format("{}(): {}", call.name, e.what()));
  }
}

// square(size, center): its four corners, counter-clockwise (primitives.cc).
Polygon2d square(const Call& call) {
  Args args(call, {"size", "center"});
  glm::dvec2 size(1);
  if (args.has("size")) {
    const Value& v = args.value("size");
    if (v.kind == Value::Kind::Number) {
      size = glm::dvec2(v.number);
    } else if (v.kind == Value::Kind::Vector && v.items.size() == 2 && v.items[0].kind == Value::Kind::Number &&
               v.items[1].kind == Value::Kind::Number) {
      size = {v.items[0].number, v.items[1].number};
    } else {
      args.fail_type("size", "a number or a vector of 2 numbers");
    }
  }
  if (!(size.x > 0 && size.y > 0 && size.x <= kMaxClippedCoordinate && size.y <= kMaxClippedCoordinate))
    args.fail_value("size", fmt::format("a clipped square's size must be positive and at most {:g} in both "
                                        "dimensions, got [{}, {}]",
                                        kMaxClippedCoordinate, size.x, size.y));
  const glm::dvec2 lo = args.boolean("center", false) ? -size / 2.0 : glm::dvec2(0);
  const glm::dvec2 hi = lo + size;
  return {{{{lo, {hi.x, lo.y}, hi, {lo.x, hi.y}}, true}}, true};
}

// circle(r | d): Calc::get_fragments_from_r points at 360 i / n degrees.
Polygon2d circle(const Call& call) {
  Args args(call, {"r"}, {"d"});
  if (args.has("r") && args.has("d")) throw SceneError(args.name_loc("d"), "circle takes either r or d, not both");
  const std::string_view given = args.has("d") ? "d" : "r";
  const double v = args.number(given, given == "d" ? 2 : 1);
  const double r = given == "d" ? v / 2 : v;
  if (!(r > 0 && r <= kMaxClippedCoordinate))
    args.fail_value(given, fmt::format("{} must be positive and the radius at most {:g}, got {}", args.what(given),
                                       kMaxClippedCoordinate, v));
  const int n = fragments(call, args, r);
  Outline2d o;
  for (int i = 0; i < n; ++i) {
    const double phi = (360.0 * i) / n;
    o.vertices.emplace_back(r * cos_degrees(phi), r * sin_degrees(phi));
  }
  return {{std::move(o)}, true};
}

Polygon2d from_paths(const std::vector<std::vector<glm::dvec2>>& paths) {
  Polygon2d shape;
  for (const auto& p : paths) shape.outlines.push_back({p, true});
  return shape;
}

glm::dvec2 apply(const glm::dmat3& m, const glm::dvec2& p) { return glm::dvec2(m * glm::dvec3(p, 1.0)); }

void transform(Polygon2d& shape, const glm::dmat3& m) {
  for (Outline2d& o : shape.outlines)
    for (glm::dvec2& v : o.vertices) v = apply(m, v);
}

std::string lower_extension(const std::string& file) {
  std::string e = std::filesystem::path(file).extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return e;
}

// import() of a DXF or SVG file, as drawn (import.cc).
Polygon2d import_2d(const Call& call, const RegionSources& sources) {
  Args args(call, {"file", "layer", "convexity", "origin", "scale"}, {"timestamp", "dpi", "center", "id"});
  if (!args.has("file")) throw SceneError(call.loc, "import needs the file to read: import(\"drawing.dxf\")");
  const Value& f = args.value("file");
  if (f.kind != Value::Kind::String) args.fail_type("file", "a string");
  const std::string file(f.string);
  args.number("convexity", 1);
  args.number("timestamp", 0);
  const std::string path = resolve_import(args, file, sources.import_dir);
  std::string text;
  try {
    text = read_whole(path, sources.max_file_bytes);
  } catch (const MeshFileError& e) {
    args.fail_value("file", fmt::format("cannot import '{}': {}", file, e.what()));
  }
  try {
    if (lower_extension(file) == ".svg") {
      SvgOptions o;
      o.dpi = args.number("dpi", 72);
      if (!(o.dpi >= 0.001 && o.dpi <= 1e9)) args.fail_value("dpi", "the dpi must be between 0.001 and 1e9");
      o.center = args.boolean("center", false);
      try {
        return read_svg(text, o);  // its curves are cut into fixed numbers of segments, not by $fn
      } catch (const SvgError&) {
        throw;
      } catch (const std::runtime_error& e) {  // libxml2 cannot be loaded (scene/libxml2_library.h)
        args.fail_value("file", fmt::format("cannot import '{}': {}: {}", file, path, e.what()));
      }
    }
    DxfOptions o;
    if (args.has("layer")) {
      const Value& layer = args.value("layer");
      if (layer.kind != Value::Kind::String) args.fail_type("layer", "a string");
      o.layer = std::string(layer.string);
    }
    if (args.has("origin")) {
      const Value& v = args.value("origin");
      if (v.kind != Value::Kind::Vector || v.items.size() != 2 || v.items[0].kind != Value::Kind::Number ||
          v.items[1].kind != Value::Kind::Number)
        args.fail_type("origin", "a vector of 2 numbers");
      o.origin = {v.items[0].number, v.items[1].number};
    }
    o.scale = args.number("scale", 1);
    if (o.scale <= 0) o.scale = 1;  // as OpenSCAD
    o.fn = args.number("$fn", 0), o.fs = args.number("$fs", 2), o.fa = args.number("$fa", 12);
    return read_dxf(text, o);
  } catch (const DxfError& e) {
    args.fail_value("file", fmt::format("cannot import '{}': {}:{}", file, path, e.what()));
  } catch (const SvgError& e) {
    args.fail_value("file", fmt::format("cannot import '{}': {}:{}", file, path, e.what()));
  }
}

// offset(r | delta, chamfer): OffsetNode's joins and GeometryEvaluator's arc
// tolerance (the fragments of a circle of radius |r|).
struct OffsetSpec {
  double delta = 1;
  ClipperLib::JoinType join = ClipperLib::jtRound;
  double arc_tolerance = 0;
};

OffsetSpec read_offset(const Call& call) {
  Args args(call, {"r"}, {"delta", "chamfer"});
  OffsetSpec s;
  if (args.has("r")) {
    s.delta = args.number("r", 1);
  } else if (args.has("delta")) {
    s.delta = args.number("delta", 1);
    s.join = args.boolean("chamfer", false) ? ClipperLib::jtSquare : ClipperLib::jtMiter;
  }
  args.boolean("chamfer", false);
  const std::string_view given = args.has("r") ? "r" : "delta";
  if (!(std::abs(s.delta) <= kMaxClippedCoordinate / 4))
    args.fail_value(given, fmt::format("an offset of {} is beyond the {:g} capsim's clipping holds", s.delta,
                                       kMaxClippedCoordinate / 4));
  const double n = fragments(call, args, std::abs(s.delta));
  s.arc_tolerance = std::abs(s.delta) * (1 - cos_degrees(180 / n));
  return s;
}

// OffsetNode's miter limit: high enough that jtMiter never squares a corner.
constexpr double kOffsetMiterLimit = 1000000.0;

class Evaluator {
 public:
  explicit Evaluator(const RegionSources& sources) : sources_(sources) {}

  // The call's shape; nullopt for nothing (an empty group, a dropped child).
  std::optional<Polygon2d> shape(const Call& call) {
    for (const auto& m : call.modifiers) {
      if (m.symbol == '!') throw SceneError(m.loc, "the '!' (root) modifier is not supported inside a 2-D shape");
      if (m.symbol == '%' || m.symbol == '*') {
        node(call);  // read and checked, then left out
        return std::nullopt;
      }
    }
    return node(call);
  }

 private:
  std::optional<Polygon2d> node(const Call& call) {
    try {
      std::optional<Polygon2d> s = evaluate(call);
      if (s) check_size(*s, call);
      return s;
    } catch (const ClipperRangeError& e) {
      throw SceneError(call.loc, fmt::format("{}(): {}", call.name, e.what()));
    }
  }

  std::optional<Polygon2d> evaluate(const Call& call) {
    const std::string_view name = call.name;
    // Leaves: sanitized as GeometryEvaluator's LeafNode visit does.
    if (name == "square" || name == "circle" || name == "polygon" || name == "text" || name == "import") {
      if (!call.children.empty()) throw SceneError(call.body_loc, fmt::format("{}() takes no children", name));
      Polygon2d leaf = name == "square"   ? square(call)
                       : name == "circle" ? circle(call)
                       : name == "import" ? (is_2d_import(call) ? import_2d(call, sources_)
                                                                : throw SceneError(call.loc, "import() of a mesh "
                                                                                             "is a 3-D object, not "
                                                                                             "a 2-D shape"))
                       : name == "polygon" ? from_paths(read_polygon_paths(call, glm::dmat3(1.0)).paths)
                                           : from_paths(read_text_paths(call, glm::dmat3(1.0)));
      check_size(leaf, call);
      return leaf.sanitized ? leaf : sanitize(leaf);
    }
    if (name == "projection") {
      const Polygon2d leaf = from_paths(read_projection(call, {sources_.import_dir, sources_.max_file_bytes}));
      check_size(leaf, call);
      return sanitize(leaf);
    }
    if (name == "multmatrix" || name == "translate" || name == "rotate" || name == "scale" || name == "mirror") {
      std::optional<Polygon2d> s = union_of_children(call);
      if (!s) return s;
      const glm::dmat3 m = read_transform_2d(call);
      transform(*s, m);
      // A mirror turns the outlines' winding: sanitized again, as OpenSCAD.
      const double det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
      if (s->sanitized && det <= 0) *s = sanitize(*s);
      return s;
    }
    if (name == "resize") {
      // OpenSCAD's Polygon2d::resize: the factors from the box of the
      // children's outlines, about the origin.
      const ResizeSpec spec = read_resize_spec(call);
      std::optional<Polygon2d> s = union_of_children(call);
      if (!s) return s;
      transform(*s, resize_matrix_2d(spec, s->outlines));
      return s;
    }
    if (name == "hull" || name == "minkowski") {
      read_hull_arguments(call);
      const std::vector<Polygon2d> kids = children(call);
      if (kids.empty()) return std::nullopt;
      return name == "hull" ? hull_2d(kids) : minkowski_sum(kids);
    }
    if (name == "offset") {
      const OffsetSpec spec = read_offset(call);
      std::optional<Polygon2d> s = union_of_children(call);
      if (!s) return s;
      return apply_offset(*s, spec.delta, spec.join, kOffsetMiterLimit, spec.arc_tolerance);
    }
    if (name == "union" || name == "group" || name == "render" || name == "color" || name == "material") {
      if (name == "color") read_color(call);
      else if (name == "material") read_material(call, Material{});
      else read_pass_through(call);
      return union_of_children(call);
    }
    if (name == "difference" || name == "intersection") {
      read_pass_through(call);
      return combine(call, name == "difference" ? ClipperLib::ctDifference : ClipperLib::ctIntersection);
    }
    throw SceneError(call.loc, fmt::format("{}() is not a 2-D shape: 2-D subtrees hold square, circle, polygon, "
                                           "text, import (DXF, SVG), projection, offset, hull, minkowski, their "
                                           "transforms and resize, union, difference and intersection",
                                           name));
  }

  std::vector<Polygon2d> children(const Call& call) {
    std::vector<Polygon2d> out;
    for (const Call& child : call.children)
      if (std::optional<Polygon2d> s = shape(child)) out.push_back(std::move(*s));
    return out;
  }

  // applyToChildren2D: one child passes as it is, several are clipped.
  std::optional<Polygon2d> combine(const Call& call, ClipperLib::ClipType type) {
    std::vector<Polygon2d> kids = children(call);
    if (kids.empty()) return std::nullopt;
    if (kids.size() == 1) return std::move(kids.front());
    return clip_shapes(kids, type);
  }
  std::optional<Polygon2d> union_of_children(const Call& call) { return combine(call, ClipperLib::ctUnion); }

  const RegionSources& sources_;
};

}  // namespace

bool is_2d_import(const Call& call) {
  for (const Argument& a : call.args)
    if ((a.name == "file" || a.name.empty()) && a.value.kind == Value::Kind::String) {
      const std::string e = lower_extension(std::string(a.value.string));
      return e == ".dxf" || e == ".svg";
    }
  return false;
}

bool needs_clipping(const Call& call) {
  if (call.name == "offset" || call.name == "projection" || call.name == "hull" || call.name == "minkowski")
    return true;
  if (call.name == "import") return is_2d_import(call);
  if (call.name == "polygon") return paths_meet(read_polygon_paths(call, glm::dmat3(1.0)).paths);
  return false;
}

Polygon2d evaluate_region(const Call& call, const RegionSources& sources) {
  std::optional<Polygon2d> s = Evaluator(sources).shape(call);
  return s ? std::move(*s) : Polygon2d{{}, true};
}

std::vector<std::vector<glm::dvec2>> region_paths(const Call& call, const RegionSources& sources) {
  std::vector<std::vector<glm::dvec2>> out;
  for (Outline2d& o : evaluate_region(call, sources).outlines) out.push_back(std::move(o.vertices));
  return out;
}

namespace {

// A PolyTree's contours in tree order, each with its parent's index.
void collect(const ClipperLib::PolyNode& node, int parent, NestedPaths& out) {
  for (const ClipperLib::PolyNode* child : node.Childs) {
    ClipperLib::Path cleaned;
    ClipperLib::CleanPolygon(child->Contour, cleaned);
    int here = parent;
    if (cleaned.size() >= 3 && ClipperLib::Area(cleaned) != 0) {
      std::vector<glm::dvec2> path;
      for (const ClipperLib::IntPoint& p : cleaned)
        path.emplace_back(static_cast<double>(p.X) / kClipperScale, static_cast<double>(p.Y) / kClipperScale);
      out.paths.push_back(std::move(path));
      out.parent.push_back(parent);
      here = static_cast<int>(out.paths.size()) - 1;
    }
    collect(*child, here, out);
  }
}

}  // namespace

NestedPaths nested_region_paths(const Call& call, const glm::dmat3& plane, const RegionSources& sources) {
  Polygon2d shape = evaluate_region(call, sources);
  NestedPaths out;
  try {
    transform(shape, plane);
    // One more union splits every outline where it touches itself (Clipper's
    // strictly simple output), so that each path is a simple prism base,
    // and gives the nesting. The vertices are those of OpenSCAD's own
    // re-sanitizing after a transform.
    ClipperLib::Clipper clipper;
    clipper.StrictlySimple(true);
    ClipperLib::PolyTree tree;
    clipper.AddPaths(to_clipper(shape), ClipperLib::ptSubject, true);
    clipper.Execute(ClipperLib::ctUnion, tree, ClipperLib::pftNonZero);
    collect(tree, -1, out);
  } catch (const ClipperRangeError& e) {
    throw SceneError(call.loc, fmt::format("{}(): {}", call.name, e.what()));
  } catch (const ClipperLib::clipperException& e) {
    throw SceneError(call.loc, fmt::format("{}(): clipping failed: {}", call.name, e.what()));
  }
  if (out.paths.empty())
    throw SceneError(call.loc, fmt::format("{}() draws nothing: its 2-D shape encloses no area", call.name));
  return out;
}

}  // namespace capsim::scene_file
