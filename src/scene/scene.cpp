// The small pieces of scene.h that are not plain data: source locations, the
// error type every bad input becomes, and names for enums.

#include "capsim/scene/scene.h"

#include <fmt/format.h>

namespace capsim {

std::string SourceLoc::str() const {
  const std::string& name = file ? *file : std::string("<scene>");
  // Line 0 stands for the file as a whole (e.g. it cannot be read).
  if (line <= 0) return name;
  return fmt::format("{}:{}:{}", name, line, col);
}

SceneError::SceneError(const SourceLoc& loc, const std::string& message)
    : std::runtime_error(fmt::format("{}: {}", loc.str(), message)), loc_(loc), message_(message) {}

const char* to_string(PrimitiveKind kind) {
  switch (kind) {
    case PrimitiveKind::Sphere: return "sphere";
    case PrimitiveKind::Box: return "box";
    case PrimitiveKind::Cone: return "cone";
    case PrimitiveKind::Mesh: return "mesh";
    case PrimitiveKind::Revolution: return "revolution";
  }
  return "?";
}

Aabb object_bounds(PrimitiveKind kind) {
  switch (kind) {
    case PrimitiveKind::Sphere:
      return {glm::dvec3(-1), glm::dvec3(1)};
    case PrimitiveKind::Box:
      return {glm::dvec3(0), glm::dvec3(1)};
    case PrimitiveKind::Cone:
      return {glm::dvec3(-1, -1, 0), glm::dvec3(1, 1, 1)};
    case PrimitiveKind::Mesh:
    case PrimitiveKind::Revolution:
      break;
  }
  return {};
}

Aabb object_bounds(const Primitive& p) {
  if (p.kind == PrimitiveKind::Revolution) return p.revolution->bounds;
  return p.kind == PrimitiveKind::Mesh ? p.mesh->bounds : object_bounds(p.kind);
}

const char* to_string(Projection projection) {
  return projection == Projection::Orthographic ? "ortho" : "perspective";
}

const char* to_string(CsgOp op) {
  switch (op) {
    case CsgOp::Union: return "union";
    case CsgOp::Intersection: return "intersection";
    case CsgOp::Difference: return "difference";
  }
  return "?";
}

}  // namespace capsim
