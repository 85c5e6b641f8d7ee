// Fuzz target: parse -> prepare -> trace of a tiny image, the whole tracer on
// arbitrary bytes.
//
// Every scene the parser accepts must either be refused by prepare_scene with a
// SceneError or trace to finite colours: an 8x8 image with the automatic grid,
// shadows, reflection and refraction. Scenes of more than kMaxPrimitives
// primitives are skipped, so that one input cannot run for seconds (their cost
// is the subject of the scale tests, not of this target).

#include "capsim/scene/parser.h"
#include "capsim/trace/prepared_scene.h"
#include "capsim/trace/tracer.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace {

constexpr std::size_t kMaxPrimitives = 200;  // scenes/balls.csg has 125
constexpr int kImageSide = 8;

// A sample the tracer must never produce for an accepted scene.
[[noreturn]] void bad_sample(int x, int y, const capsim::PixelSample& s) {
  std::fprintf(stderr, "pixel (%d, %d): colour (%g, %g, %g), alpha %g, depth %g\n", x, y,
               s.color.x, s.color.y, s.color.z, static_cast<double>(s.alpha), s.depth);
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    capsim::Scene scene = capsim::parse_scene(text, "fuzz.csg");
    if (scene.primitives.size() > kMaxPrimitives) return 0;
    capsim::PrepareOptions options;
    options.width = kImageSide;
    options.height = kImageSide;
    const capsim::PreparedScene prepared = capsim::prepare_scene(std::move(scene), options);
    const capsim::Tracer tracer(prepared, capsim::TraceOptions{});
    capsim::Tracer::Scratch scratch(prepared);
    for (int y = 0; y < kImageSide; ++y)
      for (int x = 0; x < kImageSide; ++x) {
        capsim::OpCounts ops;
        const capsim::PixelSample s = tracer.trace_pixel(x, y, scratch, ops);
        const bool finite_colour =
            std::isfinite(s.color.x) && std::isfinite(s.color.y) && std::isfinite(s.color.z);
        if (!finite_colour || !(s.alpha >= 0 && s.alpha <= 1) || std::isnan(s.depth)) bad_sample(x, y, s);
      }
  } catch (const capsim::SceneError&) {
    // Refused by the parser or by prepare_scene, with FILE:LINE:COL.
  }
  return 0;
}
