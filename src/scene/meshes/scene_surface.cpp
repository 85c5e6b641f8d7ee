// surface(): a height map's closed mesh.

#include "scene/meshes/scene_surface.h"

#include "scene/meshes/height_maps.h"
#include "scene/reading/scene_args.h"
#include "scene/meshes/scene_meshes.h"

#include <fmt/format.h>

#include <memory>

namespace capsim::scene_file {

Primitive read_surface(const Call& call, const std::string& import_dir, std::size_t max_bytes) {
  // OpenSCAD's export writes the file's timestamp, which means nothing here.
  Args args(call, {"file", "center", "convexity"}, {"invert", "timestamp"});
  if (!args.has("file")) throw SceneError(call.loc, "surface needs the file to read: surface(\"heights.dat\")");
  const Value& f = args.value("file");
  if (f.kind != Value::Kind::String) args.fail_type("file", "a string");
  args.number("convexity", 1);  // a preview hint
  args.number("timestamp", 0);
  const bool center = args.boolean("center", false);
  const bool invert = args.boolean("invert", false);
  const std::string path = resolve_import(args, std::string(f.string), import_dir);
  HeightMap map;
  try {
    map = read_height_map(path, max_bytes, invert);
  } catch (const HeightMapError& e) {
    args.fail_value("file", fmt::format("cannot read the height map: {}", e.what()));
  }
  MeshBuild built = build_closed_mesh(height_map_mesh(map, center));
  if (!built.mesh)  // not expected: the mesh is closed by construction
    args.fail_value("file", fmt::format("the height map in {} gives no solid: {}", path, built.defect.reason));
  Primitive p;
  p.kind = PrimitiveKind::Mesh;
  p.mesh = std::make_shared<const TriangleMesh>(std::move(*built.mesh));
  p.loc = call.loc;
  return p;
}

}  // namespace capsim::scene_file
