#pragma once
// A prepared capsim scene written as a POV-Ray 3.7 scene that does the same
// Whitted work: the same camera, point lights with shadows, background,
// primitives, CSG and materials, reflection and refraction to capsim's depth,
// no antialiasing, radiosity or photons. bench_vs_povray renders both.

#include "capsim/trace/prepared_scene.h"

#include <stdexcept>
#include <string>

namespace capsim::pov {

// A construct POV-Ray has no exact equivalent for here; what() names it and
// where the scene gives it ("FILE:LINE:COL: ...").
class Unsupported : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The scene's SDL text. max_depth is capsim's reflection/refraction limit
// (TraceOptions::max_depth): capsim traces levels 0 .. max_depth, which is
// POV-Ray's max_trace_level max_depth + 1. Throws Unsupported.
std::string pov_scene(const PreparedScene& scene, int max_depth);

}  // namespace capsim::pov
