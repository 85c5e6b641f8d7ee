// polyhedron() and import(): Mesh primitives from a scene file's points and
// faces, or from a mesh file.

#include "scene/meshes/scene_meshes.h"

#include "capsim/scene/scene_limits.h"
#include "scene/meshes/mesh_files.h"
#include "scene/reading/scene_args.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <memory>

namespace capsim::scene_file {

namespace {

// The vector argument `name`, refused unless a vector that is not empty.
const Value& vector_argument(const Args& args, std::string_view name, std::string_view expected) {
  const Value& v = args.value(name);
  if (v.kind != Value::Kind::Vector || v.items.empty()) args.fail_type(name, expected);
  return v;
}

std::vector<glm::dvec3> read_points(const Args& args) {
  constexpr std::string_view kShape = "a vector of [x, y, z] points";
  const Value& list = vector_argument(args, "points", kShape);
  std::vector<glm::dvec3> points;
  points.reserve(list.items.size());
  for (std::size_t i = 0; i < list.items.size(); ++i) {
    const Value& p = list.items[i];
    bool ok = p.kind == Value::Kind::Vector && p.items.size() == 3;
    for (std::size_t k = 0; ok && k < 3; ++k) ok = p.items[k].kind == Value::Kind::Number;
    if (!ok)
      throw SceneError(p.loc, fmt::format("{} must be {}, but point {} is {}", args.what("points"), kShape, i,
                                          describe(p)));
    const glm::dvec3 q(p.items[0].number, p.items[1].number, p.items[2].number);
    static_assert(kMaxLength == 1e30, "the message names the range");
    if (!(std::abs(q.x) <= kMaxLength && std::abs(q.y) <= kMaxLength && std::abs(q.z) <= kMaxLength))
      throw SceneError(p.loc, fmt::format("point {} lies beyond 1e30 from the origin, the farthest capsim traces", i));
    points.push_back(q);
  }
  return points;
}

std::vector<std::vector<std::uint32_t>> read_faces(const Args& args, std::string_view name,
                                                    std::size_t point_count) {
  constexpr std::string_view kShape = "a vector of faces, each a vector of point indices";
  const Value& list = vector_argument(args, name, kShape);
  std::vector<std::vector<std::uint32_t>> faces;
  faces.reserve(list.items.size());
  for (std::size_t f = 0; f < list.items.size(); ++f) {
    const Value& face = list.items[f];
    if (face.kind != Value::Kind::Vector)
      throw SceneError(face.loc, fmt::format("{} must be {}, but face {} is {}", args.what(name), kShape, f,
                                             describe(face)));
    std::vector<std::uint32_t> indices;
    for (const Value& i : face.items) {
      if (i.kind != Value::Kind::Number || i.number != std::floor(i.number) || i.number < 0 ||
          i.number >= static_cast<double>(point_count))
        throw SceneError(i.loc, fmt::format("face {} names point {}, but the points are numbered 0 to {}", f,
                                            i.kind == Value::Kind::Number ? fmt::format("{}", i.number) : describe(i),
                                            point_count - 1));
      indices.push_back(static_cast<std::uint32_t>(i.number));
    }
    faces.push_back(std::move(indices));
  }
  return faces;
}

Primitive mesh_primitive(TriangleMesh mesh) {
  Primitive p;
  p.kind = PrimitiveKind::Mesh;
  p.mesh = std::make_shared<const TriangleMesh>(std::move(mesh));
  return p;
}

}  // namespace

std::string resolve_import(const Args& args, const std::string& file, const std::string& import_dir) {
  namespace fs = std::filesystem;
  const fs::path given(file);
  if (given.is_absolute()) return file;
  const fs::path beside = fs::path(import_dir) / given;
  std::error_code ec;
  if (fs::exists(beside, ec)) return beside.string();
  if (fs::exists(given, ec)) return file;
  args.fail_value("file", fmt::format("cannot import '{}': there is no such file beside the scene file ({}) nor in "
                                      "the current directory",
                                      file, beside.string()));
}

Primitive read_polyhedron(const Call& call) {
  Args args(call, {"points", "faces", "convexity"}, {"triangles"});
  if (args.has("faces") && args.has("triangles"))
    throw SceneError(args.name_loc("triangles"), "polyhedron takes faces or triangles (its older name), not both");
  args.number("convexity", 1);  // a preview hint: the tracer's crossings are exact at any convexity
  if (!args.has("points")) throw SceneError(call.loc, "polyhedron needs its points");
  PolygonMesh m;
  m.points = read_points(args);
  const std::string_view faces = args.has("triangles") ? "triangles" : "faces";
  if (!args.has(faces)) throw SceneError(call.loc, "polyhedron needs its faces");
  m.faces = read_faces(args, faces, m.points.size());
  MeshBuild built = build_closed_mesh(m);
  if (!built.mesh) {
    const Loc at = built.defect.face >= 0 ? args.value(faces).items[static_cast<std::size_t>(built.defect.face)].loc
                                          : call.loc;
    throw SceneError(at, fmt::format("polyhedron is not a closed solid: {}", built.defect.reason));
  }
  Primitive p = mesh_primitive(std::move(*built.mesh));
  p.loc = call.loc;
  return p;
}

std::vector<Primitive> read_import(const Call& call, const std::string& import_dir, std::size_t max_bytes) {
  // OpenSCAD's export writes every parameter; those of 2-D files (layer,
  // origin, scale, dpi) and its file's timestamp mean nothing for a mesh.
  Args args(call, {"file", "layer", "convexity", "origin", "scale"}, {"timestamp", "dpi", "center", "id"});
  if (!args.has("file")) throw SceneError(call.loc, "import needs the file to read: import(\"model.stl\")");
  const Value& f = args.value("file");
  if (f.kind != Value::Kind::String) args.fail_type("file", "a string");
  const std::string file(f.string);
  if (!is_mesh_file_name(file))
    args.fail_value("file", fmt::format("cannot import '{}': capsim imports STL (.stl), OFF (.off), AMF (.amf) and "
                                        "3MF (.3mf) meshes, and DXF (.dxf) and SVG (.svg) as 2-D shapes",
                                        file));
  const std::string path = resolve_import(args, file, import_dir);
  std::vector<MeshObject> objects;
  try {
    objects = read_mesh_file(path, max_bytes);
  } catch (const MeshFileError& e) {
    args.fail_value("file", fmt::format("cannot import '{}': {}", file, e.what()));
  }
  // Each object of an AMF or 3MF file a closed solid of its own: OpenSCAD
  // unites them, which the parser does by a union of their leaves.
  std::vector<Primitive> solids;
  for (const MeshObject& o : objects) {
    MeshBuild built = build_closed_mesh(o.mesh);
    if (!built.mesh)
      args.fail_value("file", fmt::format("cannot import '{}': {} is not a closed solid: {}", file, o.name,
                                          built.defect.reason));
    solids.push_back(mesh_primitive(std::move(*built.mesh)));
    solids.back().loc = call.loc;
  }
  return solids;
}

}  // namespace capsim::scene_file
