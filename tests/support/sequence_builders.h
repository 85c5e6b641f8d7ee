#pragma once
// Short animated sequences built in code for the tests of sequences: a row of
// objects that moves a step to the right on every frame, and the tracers a
// sequence run takes.

#include "capsim/trace/prepared_scene.h"
#include "capsim/trace/tracer.h"
#include "support/scene_builders.h"

#include <memory>
#include <utility>
#include <vector>

namespace capsim::testing {

// Frame k: `spheres` spheres, and `boxes` boxes behind them, moved k steps of
// 0.4 to the right, seen from the front and above.
inline PreparedScene moving_frame(int k, int width, int height, int spheres = 5, int boxes = 0) {
  std::vector<Primitive> prims;
  for (int i = 0; i < spheres; ++i) prims.push_back(sphere({i * 1.5 + 0.4 * k, 0, 0}, 0.6));
  for (int i = 0; i < boxes; ++i) prims.push_back(box({i * 2.0 + 0.4 * k, -1, -1.8}, {1, 1, 0.6}));
  Scene s = make_scene(prims);
  Camera cam;
  // The row's middle, from far enough away to see it move.
  const bool wide = boxes > 0;
  cam.eye = wide ? glm::dvec3{4, -14, 6} : glm::dvec3{3, -12, 5};
  cam.center = wide ? glm::dvec3{4, 0, 0} : glm::dvec3{3, 0, 0};
  cam.up = {0, 0, 1};
  cam.fov_deg = 45;
  s.camera = cam;
  PrepareOptions o;
  o.width = width;
  o.height = height;
  return prepare_scene(s, o);
}

// The frames of a sequence and their tracers; `list` is what simulate_frames takes.
struct FrameTracers {
  std::vector<PreparedScene> scenes;
  std::vector<std::unique_ptr<Tracer>> tracers;
  std::vector<const Tracer*> list;

  explicit FrameTracers(std::vector<PreparedScene> frames) : scenes(std::move(frames)) {
    for (const PreparedScene& s : scenes) tracers.push_back(std::make_unique<Tracer>(s, TraceOptions{}));
    for (const auto& t : tracers) list.push_back(t.get());
  }
  // The tracers refer to the scenes: a move keeps the vectors' elements where
  // they are, a copy would not.
  FrameTracers(FrameTracers&&) = default;
  FrameTracers(const FrameTracers&) = delete;
  FrameTracers& operator=(const FrameTracers&) = delete;
};

// count frames of moving_frame.
inline FrameTracers moving_frames(int count, int width, int height, int spheres = 5, int boxes = 0) {
  std::vector<PreparedScene> scenes;
  for (int k = 0; k < count; ++k) scenes.push_back(moving_frame(k, width, height, spheres, boxes));
  return FrameTracers(std::move(scenes));
}

}  // namespace capsim::testing
