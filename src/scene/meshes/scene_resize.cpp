// resize(): OpenSCAD's scale to a new bounding box.

#include "scene/meshes/scene_resize.h"

#include "scene/meshes/convex_decomposition.h"
#include "scene/meshes/meshed_solids.h"
#include "scene/reading/scene_args.h"
#include "scene/regions/region_2d.h"

#include <fmt/format.h>

#include <span>

namespace capsim::scene_file {
namespace {

// A size, or an auto flag, from a vector of up to three items.
const Value& items_of(const Args& args, std::string_view name, std::string_view expected) {
  const Value& v = args.value(name);
  if (v.kind != Value::Kind::Vector || v.items.size() > 3) args.fail_type(name, expected);
  return v;
}

glm::dvec3 box_size(const Aabb& box) { return box.empty() ? glm::dvec3(0) : box.hi - box.lo; }

}  // namespace

ResizeSpec read_resize_spec(const Call& call) {
  Args args(call, {"newsize", "auto"}, {"convexity"});
  args.number("convexity", 1);
  ResizeSpec spec;
  if (args.has("newsize")) {
    const Value& v = items_of(args, "newsize", "a vector of up to 3 sizes");
    for (std::size_t i = 0; i < v.items.size(); ++i) {
      const Value& item = v.items[i];
      if (item.kind != Value::Kind::Number || !std::isfinite(item.number))
        throw SceneError(item.loc, fmt::format("{} must be a vector of up to 3 sizes, but element {} is {}",
                                               args.what("newsize"), i + 1, describe(item)));
      if (item.number < 0)
        throw SceneError(item.loc, fmt::format("{} must not be negative, got {} for {}", args.what("newsize"),
                                               item.number, "xyz"[i]));
      spec.newsize[static_cast<int>(i)] = item.number;
    }
  }
  if (args.has("auto")) {
    const Value& a = args.value("auto");
    if (a.kind == Value::Kind::Bool) {
      spec.autosize = glm::bvec3(a.boolean);
    } else {
      const Value& v = items_of(args, "auto", "true, false or a vector of up to 3 of them");
      for (std::size_t i = 0; i < v.items.size(); ++i) {
        const Value& item = v.items[i];
        if (item.kind == Value::Kind::Bool) {
          spec.autosize[static_cast<int>(i)] = item.boolean;
        } else if (item.kind == Value::Kind::Number) {
          spec.autosize[static_cast<int>(i)] = item.number != 0;
        } else {
          throw SceneError(item.loc, fmt::format("{} must be true, false or a vector of up to 3 of them, but "
                                                 "element {} is {}",
                                                 args.what("auto"), i + 1, describe(item)));
        }
      }
    }
  }
  return spec;
}

glm::dvec3 resize_factors(const ResizeSpec& spec, const glm::dvec3& size, int dimensions) {
  glm::dvec3 scale(1.0);
  int largest = 0;
  for (int i = 0; i < dimensions; ++i) {
    if (spec.newsize[i] == 0) continue;
    if (size[i] == 0) return glm::dvec3(1.0);
    scale[i] = spec.newsize[i] / size[i];
    if (spec.newsize[i] > spec.newsize[largest]) largest = i;
  }
  const double autoscale = spec.newsize[largest] != 0 ? spec.newsize[largest] / size[largest] : 1.0;
  for (int i = 0; i < dimensions; ++i)
    if (spec.autosize[i] && spec.newsize[i] == 0) scale[i] = autoscale;
  return scale;
}

glm::dmat4 read_resize(const Call& call, const FileAccess& files) {
  const ResizeSpec spec = read_resize_spec(call);
  const MeshedSolids solids = read_meshed_solids(call.children, files, {"resize()", "meshes"});
  std::optional<Aabb> box = known_bounds(solids);
  if (!box) {
    const EvaluationWords words{"resize() of these children", "their difference or intersection",
                                "evaluates with CGAL for its bounding box"};
    box.emplace();
    for (const auto& piece : evaluated_corners(solids, false, call, words))
      for (const glm::dvec3& p : piece) box->extend(p);
  }
  const glm::dvec3 s = resize_factors(spec, box_size(*box), 3);
  glm::dmat4 m(1.0);
  m[0][0] = s.x;
  m[1][1] = s.y;
  m[2][2] = s.z;
  return m;
}

glm::dmat3 read_resize_2d(const Call& call, const FileAccess& files) {
  const ResizeSpec spec = read_resize_spec(call);
  Call shape = call;
  shape.name = "union";
  shape.args.clear();
  shape.modifiers.clear();
  return resize_matrix_2d(spec, evaluate_region(shape, {files.import_dir, files.max_bytes}).outlines);
}

glm::dmat3 resize_matrix_2d(const ResizeSpec& spec, const std::vector<Outline2d>& outlines) {
  Aabb box;
  for (const Outline2d& o : outlines)
    for (const glm::dvec2& p : o.vertices) box.extend(glm::dvec3(p, 0));
  const glm::dvec3 s = resize_factors(spec, box_size(box), 2);
  glm::dmat3 m(1.0);
  m[0][0] = s.x;
  m[1][1] = s.y;
  return m;
}

}  // namespace capsim::scene_file
