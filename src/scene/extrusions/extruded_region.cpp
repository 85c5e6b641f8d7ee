// linear_extrude() as closed meshes.

#include "scene/extrusions/extruded_region.h"

#include "scene/extrusions/scene_extrusion.h"
#include "scene/extrusions/twisted_extrusion.h"

#include <fmt/format.h>

namespace capsim::scene_file {

ExtrudedRegion extruded_region(const Call& call, const RegionSources& sources, std::string_view under) {
  const Extrusion e = read_linear_extrude(call);
  Call shape = call;  // the children as one 2-D union
  shape.name = "union";
  shape.args.clear();
  shape.modifiers.clear();
  NestedPaths region = nested_region_paths(shape, glm::dmat3(1.0), sources);
  Sweep sweep;
  sweep.height = e.height;
  sweep.twist = e.twist;
  sweep.scale = e.curved() ? e.scale_xy : glm::dvec2(e.scale);
  sweep.slices = e.slices;
  if (sweep.slices == 0) {
    std::vector<glm::dvec2> points;
    for (const auto& path : region.paths) points.insert(points.end(), path.begin(), path.end());
    sweep.slices = e.curved() ? extrusion_slices(points, e) : 1;
  }
  ExtrudedRegion out;
  for (const auto& path : region.paths) {
    check_swept_points(path.size(), sweep.slices, call.loc, fmt::format("linear_extrude() under {}", under));
    MeshBuild built = build_closed_mesh(sweep_mesh(path, sweep));
    if (!built.mesh) throw SceneError(call.loc, fmt::format("linear_extrude() under {}: {}", under, built.defect.reason));
    out.meshes.push_back(std::move(*built.mesh));
  }
  out.parent = std::move(region.parent);
  if (e.center) out.to_call = glm::dmat4(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -e.height / 2, 1);
  return out;
}

}  // namespace capsim::scene_file
