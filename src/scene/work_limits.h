#pragma once
// The most work one call of a scene file may ask for, past which it is
// refused where it stands (docs/scene-format.md gives each message).
//
// A fuzzing build (FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION, the macro
// libFuzzer projects define for it; tests/fuzz/CMakeLists.txt) lowers them,
// so that one input stays well inside the fuzzer's 10 s under the
// sanitizers: the refusals are the same code, reached at smaller inputs.
// (A sphere of 400,000 points took over 10 s there, inside the limits.)

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

}  // namespace capsim
