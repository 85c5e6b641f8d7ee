#pragma once
// rotate_extrude's solid: a 2-D profile in the (r, z) half plane turned about
// the z axis, whole or through a wedge. A point p lies in it when
// (sqrt(px^2 + py^2), pz) lies in the profile (and p in the wedge), so the
// solid is exact: each straight profile edge turns into a cone frustum,
// cylinder or annulus, each ellipse (a placed circle) into a torus-like
// quartic surface; nothing is tessellated.

#include "capsim/scene/bounds.h"

#include <glm/glm.hpp>

#include <vector>

namespace capsim {

// The ellipse {u : (u - center)^T form (u - center) <= 1}; `form` is symmetric
// positive definite (a circle of radius r: form = I / r^2).
struct ProfileEllipse {
  glm::dvec2 center{0};
  glm::dmat2 form{1.0};
};

// A profile: closed paths under the even-odd rule (paths that do not cross one
// another or themselves) and ellipses that lie apart from each other and from
// the paths. x is the radius, y the height. Only the part at x >= 0 is turned:
// the rest (a shape that crosses the axis) is the preimage of no point.
struct RevolvedProfile {
  std::vector<std::vector<glm::dvec2>> paths;
  std::vector<ProfileEllipse> ellipses;
};

// A profile edge clipped to x >= 0, with its unit outward normal in the
// profile plane (out of the even-odd region).
struct RevolvedEdge {
  glm::dvec2 a{0}, b{0};
  glm::dvec2 outward{0};
};

// The solid, object space: the profile turned from the +x axis counter-
// clockwise (seen from +z) through sweep_deg, 0 < sweep_deg <= 360. Surfaces
// are numbered edges first, then ellipses, then the two caps of a partial
// turn: the half planes at 0 and at sweep_deg.
struct Revolution {
  RevolvedProfile profile;
  double sweep_deg = 360;
  std::vector<RevolvedEdge> edges;
  Aabb bounds;  // the turned profile's box, cut to the wedge's
  bool full() const { return sweep_deg >= 360; }
  int cap_surface(int which) const { return static_cast<int>(edges.size() + profile.ellipses.size()) + which; }
};

// The solid of a profile (its edges clipped and oriented, its bounds).
// Precondition: 0 < sweep_deg <= 360 and the profile as RevolvedProfile says.
Revolution make_revolution(RevolvedProfile profile, double sweep_deg);

// The profile mirrored in the axis (x -> -x): OpenSCAD turns a shape that lies
// at x <= 0 as its mirror image, starting on the -x axis.
RevolvedProfile mirrored(const RevolvedProfile& profile);

// The smallest and largest x the profile reaches.
glm::dvec2 profile_x_range(const RevolvedProfile& profile);

}  // namespace capsim
