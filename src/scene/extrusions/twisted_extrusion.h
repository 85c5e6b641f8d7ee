#pragma once
// linear_extrude with a twist or with different scales in x and y: its sides
// are curved (ruled) surfaces with no closed form capsim traces, so the solid
// is OpenSCAD 2021.01's own tessellation of it (GeometryEvaluator's
// extrudePolygon and add_slice): the outline rotated and scaled at each slice,
// each quad between two slices split along its shorter diagonal, the caps flat.

#include "capsim/scene/triangle_mesh.h"

#include <glm/glm.hpp>

#include <vector>

namespace capsim::scene_file {

struct Sweep {
  double height = 1;
  double twist = 0;             // degrees, turned clockwise seen from above, as OpenSCAD turns it
  glm::dvec2 scale{1.0, 1.0};   // at the top, each axis >= 0
  int slices = 1;
  // Straight walls of one slice's height below the bottom and above the top
  // (where the top is not a point or a line), for extrusions of several
  // leaves whose caps a slab cuts (scene_extrusion.h).
  bool collars = false;
};

// OpenSCAD's number of slices when linear_extrude gives none: from the
// largest squared distance of the shape's points from the axis (reach_sqr),
// and, for different scales without a twist, the largest squared distance a
// point moves between the caps (move_sqr). fn, fa, fs are the extrusion's
// $fn, $fa, $fs.
int openscad_slices(double reach_sqr, double move_sqr, const Sweep& sweep, double fn, double fa, double fs);

// The closed mesh of one simple outline swept from z = 0 to the height (in
// either winding; it is taken counter-clockwise, as OpenSCAD's sanitised
// outlines are).
PolygonMesh sweep_mesh(std::vector<glm::dvec2> outline, const Sweep& sweep);

}  // namespace capsim::scene_file
