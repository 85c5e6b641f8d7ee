// projection()'s children as meshes under a CSG tree.

#include "scene/regions/scene_projection.h"

#include "scene/meshes/meshed_solids.h"
#include "scene/reading/scene_args.h"
#include "scene/regions/projection_2d.h"

namespace capsim::scene_file {

std::vector<std::vector<glm::dvec2>> read_projection(const Call& call, const FileAccess& files) {
  Args args(call, {}, {"cut", "convexity"});
  const bool cut = args.boolean("cut", false);
  args.number("convexity", 1);
  MeshedSolids solids = read_meshed_solids(call.children, files, {"projection()", "projects"});
  solids.root.loc = call.loc;
  return project_solids(solids, cut);
}

}  // namespace capsim::scene_file
