#pragma once
// Sphere lattices, the test models of the paper's Table 4-2 (16, 512 = 8^3,
// 1000 = 10^3, 4096 = 16^3 and 6859 = 19^3 spheres), as scene files and scenes.
//
// One geometry for every lattice (docs/calibration.md gives the reasons):
// equal spheres of radius kLatticeRadius, centres kLatticeSpacing apart along
// x, y and z; the lattice stands on the view axis with its near face (the
// layer z = 0, the others at -spacing, -2 spacing, ...) in one plane for every
// size; one fixed camera looks straight down -z at it, its 40 degree field of
// view framing the near face of a kLatticeViewSide x kLatticeViewSide lattice.
// So the largest lattice of the table fills the screen and a smaller one covers
// the middle of it, as much as its near face spans.

#include "capsim/scene.h"

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

// The lattice as a scene file (capsim's format: a camera statement and a
// union of translated spheres), width x height pixels. Preconditions: the
// shape's sides >= 1, width and height in 1 to 16384.
std::string lattice_scene_text(const LatticeShape& shape, int width, int height);

// The same scene, parsed from that text: a run on it equals a run on the file.
Scene make_sphere_lattice(const LatticeShape& shape, int width, int height);

}  // namespace capsim::sim
