#include "capsim/trace/prepared_scene.h"

#include "capsim/trace/csg_bounds.h"
#include "capsim/trace/scene_range.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

namespace capsim {

namespace {

SourceLoc scene_start(const Scene& scene) {
  SourceLoc loc = scene.root.loc;
  if (loc.line == 0) {
    loc.line = 1;
    loc.col = 1;
  }
  return loc;
}

// The camera a framed view gets (OpenSCAD's options', or the default) at the
// scene's image size, checked to stay within the range capsim traces.
Camera framing_camera(const PreparedScene& ps, const Aabb& bounds) {
  const int width = ps.camera.width, height = ps.camera.height;
  if (!ps.openscad) return default_camera(bounds, width, height);
  const Camera cam = openscad_camera(*ps.openscad, bounds, width, height);
  const glm::dvec3 extent = ps.grid.universe.extent();
  const double size = std::max({extent.x, extent.y, extent.z});
  const double reach = std::max({std::abs(cam.eye.x), std::abs(cam.eye.y), std::abs(cam.eye.z)});
  static_assert(kMaxSceneRatio == 1e6, "the message names the ratio");
  if (!(reach <= size * kMaxSceneRatio))
    throw std::invalid_argument(fmt::format("--camera puts the eye {:g} from the origin, more than 1e6 times the "
                                            "scene's size {:g}, the farthest capsim traces from",
                                            reach, size));
  return cam;
}

}  // namespace

Aabb framed_bounds(const PreparedScene& ps) {
  const Aabb b = ps.openscad ? openscad_preview_bounds(ps.scene.root, ps.prims)
                             : csg_result_bounds(ps.scene.root, ps.prims);
  // Nothing drawn or left (boxes that do not meet): framed by every solid.
  return b.empty() ? universe_of(ps.prims, ps.placed) : b;
}

Camera default_camera(const Aabb& bounds, int width, int height) {
  Camera cam;
  cam.width = width;
  cam.height = height;
  cam.fov_deg = 40;
  cam.up = {0, 0, 1};
  cam.center = bounds.center();
  // OpenSCAD's default view (rotation [55, 0, 25]): from the front right, 35
  // degrees above the X-Y plane.
  const double pi = std::acos(-1.0);
  const double azimuth = 25 * pi / 180, elevation = 35 * pi / 180;
  const glm::dvec3 dir{std::sin(azimuth) * std::cos(elevation),
                       -std::cos(azimuth) * std::cos(elevation), std::sin(elevation)};
  const double radius = 0.5 * glm::length(bounds.extent());
  const double half_v = 0.5 * cam.fov_deg * pi / 180;
  const double half_h = std::atan(std::tan(half_v) * width / height);
  const double distance = 1.05 * radius / std::sin(std::min(half_v, half_h));
  cam.eye = cam.center + distance * dir;
  return cam;
}

ImageSize image_size(const Scene& scene, const PrepareOptions& options) {
  if (options.width > 0) return {options.width, options.height};
  if (scene.camera) return {scene.camera->width, scene.camera->height};
  return {512, 512};
}

PreparedScene prepare_scene(Scene scene, const PrepareOptions& options) {
  PreparedScene ps;
  const SourceLoc start = scene_start(scene);
  if ((options.width != 0) != (options.height != 0) || options.width < 0 || options.height < 0 ||
      options.width > kMaxImageSide || options.height > kMaxImageSide)
    throw std::invalid_argument(
        fmt::format("image size {}x{} is out of range (1 to {} per side)", options.width,
                    options.height, kMaxImageSide));
  if (options.grid < 0 || options.grid > kMaxGridDivisions)
    throw std::invalid_argument(fmt::format("--grid {} is out of range (1 to {}, or auto)",
                                            options.grid, kMaxGridDivisions));

  ps.prims.reserve(scene.primitives.size());
  for (const Primitive& p : scene.primitives) ps.prims.push_back(prepare_primitive(p));
  ps.tree_template = StatusTree(scene.root, scene.primitives.size());
  if (ps.tree_template.empty())
    throw SceneError(start, "the scene has no objects to draw: every object in it is dropped by '%' or '*', or is "
                            "an empty group or operation (OpenSCAD renders such a scene empty, with a warning; "
                            "capsim refuses it rather than write an image of the background alone)");
  ps.placed.resize(ps.prims.size());
  for (std::size_t i = 0; i < ps.prims.size(); ++i)
    ps.placed[i] = ps.tree_template.present(static_cast<std::uint32_t>(i));

  const Aabb universe = universe_of(ps.prims, ps.placed);
  check_scene_range(scene, ps.prims, ps.placed, universe);
  const int n = options.grid > 0 ? options.grid : fitted_grid_divisions(ps.prims, ps.placed, universe);
  try {
    ps.grid = generate_voxels(ps.prims, ps.placed, universe, n, &ps.voxel_counts, options.threads);
  } catch (const VoxelGridTooLarge& e) {
    // The automatic divisions keep within the limit by their bounding-box
    // count, which is never below generate_voxels' own.
    throw std::invalid_argument(
        fmt::format("--grid {}: {}; use fewer divisions, or --grid auto, which keeps within it",
                    n, e.what()));
  }

  const ImageSize size = image_size(scene, options);
  const bool framed = options.openscad || !scene.camera;
  if (!framed) ps.camera = *scene.camera;
  ps.camera.width = size.width;
  ps.camera.height = size.height;
  ps.openscad = options.openscad;
  ps.scene = std::move(scene);
  if (framed) ps.camera = framing_camera(ps, framed_bounds(ps));
  ps.lights = ps.scene.lights;
  if (ps.lights.empty()) ps.lights.push_back({ps.camera.eye, glm::dvec3(1)});
  return ps;
}

void frame_sequence(std::vector<PreparedScene>& frames) {
  if (frames.size() < 2) return;
  Aabb bounds;
  for (const PreparedScene& f : frames) bounds.extend(framed_bounds(f));
  for (PreparedScene& f : frames) {
    if (f.scene.camera && !f.openscad) continue;
    f.camera = framing_camera(f, bounds);
    if (f.scene.lights.empty()) f.lights = {{f.camera.eye, glm::dvec3(1)}};
  }
}

}  // namespace capsim
