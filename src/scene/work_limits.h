#pragma once
// The most work one call of a scene file may ask for, past which it is
// refused where it stands (docs/scene-format.md gives each message).
//
// A fuzzing build (FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION, the macro
// libFuzzer projects define for it; tests/fuzz/CMakeLists.txt) lowers them,
// so that one input stays well inside the fuzzer's 10 s under the
// sanitizers: the refusals are the same code, reached at smaller inputs.
// (There, inside the full limits, a sphere of 400,000 points took over 10 s,
// and a minkowski of a cube less a 48-fragment sphere 25 s.)

#include <cstddef>

namespace capsim {

#ifdef FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION
inline constexpr bool kFuzzingBuild = true;
#else
inline constexpr bool kFuzzingBuild = false;
#endif

// Points on one circle ($fn, or $fa and $fs): beyond this it is not a
// number of fragments anyone means ($fa or $fs 0, or a huge $fn).
inline constexpr int kMaxFragments = kFuzzingBuild ? 1000 : 1000000;

// Points of one mesh capsim tessellates (a sphere or cylinder under hull,
// minkowski or an evaluated operation, a twisted extrusion, a revolution),
// and of the point set it takes the hull of.
inline constexpr std::size_t kMaxTessellatedPoints = kFuzzingBuild ? 10000 : 4000000;

// Triangles of the meshes CGAL evaluates or splits as one exact Nef
// polyhedron (scene/meshes/convex_decomposition.h): its arithmetic is slow,
// about 25 s on one core for a surface() of 35 x 35 random heights (some
// 4,900 triangles), 3 s for one of 15 x 15.
inline constexpr std::size_t kMaxDecomposedTriangles = kFuzzingBuild ? 500 : 5000;

// Parts of one minkowski. Each is a mesh leaf of its own to hold and trace;
// the cap keeps one minkowski of two finely split children (their part
// counts multiply) from taking the scene's primitives and memory.
inline constexpr std::size_t kMaxMinkowskiParts = kFuzzingBuild ? 100 : 10000;

}  // namespace capsim
