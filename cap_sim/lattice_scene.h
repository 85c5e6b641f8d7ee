#pragma once
// Sphere lattices, the test models of the paper's Table 4-2 (512 = 8^3,
// 1000 = 10^3, 4096 = 16^3, 6859 = 19^3 spheres), built in code.
// Unit spheres with centres kLatticeSpacing apart; the camera looks straight down
// the -z axis at the lattice from above, with the 40 degree field of view framing
// the near face exactly: the face's nx x ny spheres fill the screen.

#include "capsim/scene.h"

namespace capsim::sim {

inline constexpr double kLatticeSpacing = 3.0;  // centre to centre: one radius of gap

// nx x ny spheres in the near face, nz layers deep. Precondition: all >= 1,
// width, height >= 1.
Scene make_sphere_lattice(int nx, int ny, int nz, int width, int height);

}  // namespace capsim::sim
