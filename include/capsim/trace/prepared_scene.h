#pragma once
// A scene frozen for tracing: prepared primitives, the status-tree template, the
// voxel grid, and the camera resolved. Immutable once built and shared by every
// thread and every simulated cell.

#include "capsim/system/huge_pages.h"
#include "capsim/trace/openscad_camera.h"
#include "capsim/trace/status_tree.h"
#include "capsim/trace/voxel_grid.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace capsim {

// The largest image side, in pixels, the tracer takes (as --size and as the
// scene camera's size).
inline constexpr int kMaxImageSide = 16384;

struct PrepareOptions {
  int grid = 0;        // divisions per axis; 0 = auto_grid_divisions
  int width = 0;       // 0 = the camera's (or the default 512)
  int height = 0;
  // OpenSCAD's camera options: when given, they choose the camera, over the
  // scene's camera statement (openscad_camera on openscad_preview_bounds).
  std::optional<OpenScadCameraOptions> openscad;
  int threads = 0;  // host threads for voxel generation (0 = all); the grid does not depend on it
};

struct PreparedScene {
  Scene scene;                          // as parsed (materials, colours, lights)
  Camera camera;                        // resolved: the options', the scene's, or framed; with the size applied
  std::optional<OpenScadCameraOptions> openscad;  // the options that chose the camera, if any
  std::vector<Light> lights;            // resolved: the scene's, or one at the eye
  LargeVector<PreparedPrimitive> prims;  // same order as scene.primitives
  std::vector<bool> placed;             // primitive contributes to the CSG tree
  StatusTree tree_template;
  VoxelGrid grid;
  VoxelGenCounts voxel_counts;          // the host's work for Algorithm-3
};

// The box a view frames: with OpenSCAD's options, the one OpenSCAD's preview
// frames (openscad_preview_bounds), else that of what the CSG tree leaves
// (csg_result_bounds); the voxel grid's universe when either is empty.
Aabb framed_bounds(const PreparedScene& scene);

// The camera used when a scene has none: looking at the centre of the bounds from
// direction (1, -2, 1.2) (OpenSCAD-like: from the front right, above), z up, 40
// degree vertical field, far enough that the bounding sphere fits the view.
Camera default_camera(const Aabb& bounds, int width, int height);

// The image size prepare_scene gives the camera: options' size if set, else the
// scene camera's, else 512x512.
struct ImageSize {
  int width = 0, height = 0;
  std::uint64_t pixels() const { return static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height); }
};
ImageSize image_size(const Scene& scene, const PrepareOptions& options);

// Throws SceneError for a scene with nothing to draw or a size out of range.
PreparedScene prepare_scene(Scene scene, const PrepareOptions& options);

// The frames of one sequence seen as one view: every frame whose camera is
// framed (OpenSCAD's options, or no camera statement) gets the camera that
// frames the bounds of all the frames (framed_bounds; default_camera or
// openscad_camera at its own image size) and, without light statements, the
// light at that camera's eye; so the view does not jump between frames.
void frame_sequence(std::vector<PreparedScene>& frames);

}  // namespace capsim
