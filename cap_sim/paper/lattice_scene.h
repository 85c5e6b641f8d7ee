#pragma once
// Sphere lattices, the test models of the paper's Table 4-2 (16, 512 = 8^3,
// 1000 = 10^3, 4096 = 16^3 and 6859 = 19^3 spheres), as scene files and scenes.
//
// One geometry for every lattice (docs/calibration.md gives the reasons):
// equal spheres of radius kLatticeRadius, centres kLatticeSpacing apart along
// x, y and z; the lattice stands on the view axis with its near face (the
// layer z = 0, the others at -spacing, -2 spacing, ...) facing a camera that
// looks straight down -z at it with a 40 degree field of view.
//
// The view differs by row: Table 4-2's 1-division column says which share of
// the rays met each lattice (with one voxel, a ray that meets the lattice
// tests every sphere), and each lattice is seen from the distance at which
// its universe covers that share of the screen. A count the table does not
// have is framed as the paper's counts were not: the camera frames the near
// face of a kLatticeViewSide x kLatticeViewSide lattice, so a smaller lattice
// covers the middle of the screen.

#include "capsim/scene/scene.h"

#include <optional>
#include <string>

namespace capsim::sim {

inline constexpr double kLatticeSpacing = 3.0;  // centre to centre
inline constexpr double kLatticeRadius = 0.3;   // a tenth of the spacing
inline constexpr int kLatticeViewSide = 19;     // the camera frames a 19 x 19 near face
inline constexpr int kMaxLatticeSpheres = 1'000'000;

// nx x ny spheres in the near face, nz layers deep.
struct LatticeShape {
  int nx = 1, ny = 1, nz = 1;
  int count() const { return nx * ny * nz; }
};

// The shape of a lattice of `spheres` spheres: a x a in the near face and
// spheres / a^2 deep, a the largest whole number with a^2 dividing the count
// and a at most the depth: a cube for a cube (512: 8 x 8 x 8), else the
// nearest to one with a square face (16: 2 x 2 x 4). Throws
// std::invalid_argument outside 1 to kMaxLatticeSpheres.
LatticeShape lattice_shape(int spheres);

// The share of the rays of a width x height screen that met the universe of
// a lattice of `spheres` spheres in Table 4-2, from its 1-division time: the
// time a ray that meets the lattice pays there (a 3DDDA set-up and a test of
// every sphere at Table 4-1's M380 costs) against the time per ray of the
// whole screen, at most 1. Nothing for a count the table does not have.
std::optional<double> table_4_2_screen_share(int spheres, int width, int height);

// The lattice as a scene file (capsim's format: a camera statement and a
// union of translated spheres), width x height pixels, seen as the header
// says: covering table_4_2_screen_share of the screen for the table's counts. Preconditions: the
// shape's sides >= 1, width and height in 1 to 16384.
std::string lattice_scene_text(const LatticeShape& shape, int width, int height);

// The same scene, parsed from that text: a run on it equals a run on the file.
Scene make_sphere_lattice(const LatticeShape& shape, int width, int height);

}  // namespace capsim::sim
