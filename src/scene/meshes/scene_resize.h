#pragma once
// resize(newsize, auto): a scale about the origin that brings the bounding
// box of OpenSCAD's geometry of the children to `newsize`, as OpenSCAD
// 2021.01 resizes (its computeResizeTransform). The box is that of the
// polyhedra OpenSCAD renders, not of the exact solids: a sphere's is its
// tessellation's. The children are then traced exactly under that scale.

#include "scene/meshes/scene_hulls.h"
#include "scene/reading/scene_syntax.h"
#include "scene/regions/clipper_utils.h"

#include <glm/glm.hpp>

#include <vector>

namespace capsim::scene_file {

struct ResizeSpec {
  glm::dvec3 newsize{0};            // 0: that axis keeps its size, or takes `autosize`'s scale
  glm::bvec3 autosize{false};       // an axis of size 0 takes the scale of the largest new size
};

// newsize: a vector of up to 3 sizes, none negative (missing ones 0);
// auto: true/false or a vector of up to 3 of them (numbers read as OpenSCAD
// reads them: non-zero is true; OpenSCAD's export writes [1, 0, 0]).
ResizeSpec read_resize_spec(const Call& call);

// The factors for a box of `size`, over the first `dimensions` axes (3 for
// solids, 2 for 2-D shapes): newsize / size where newsize is given; where
// it is 0 and auto, the factor of the largest given newsize; else 1. All 1
// when a given axis has size 0 (OpenSCAD warns and leaves a flat object).
glm::dvec3 resize_factors(const ResizeSpec& spec, const glm::dvec3& size, int dimensions);

// resize() of solids: the box of the union of the children as OpenSCAD
// meshes them (scene/meshes/meshed_solids.h); a difference or intersection
// in them is evaluated by CGAL when its box is not its first operand's.
// Refused at the call concerned: what reading the meshes refuses, and a
// solid CGAL cannot evaluate or of more than kMaxDecomposedTriangles
// triangles.
glm::dmat4 read_resize(const Call& call, const FileAccess& files);

// resize() of 2-D shapes: the box of OpenSCAD's region of the children
// (scene/regions/region_2d.h), x and y only.
glm::dmat3 read_resize_2d(const Call& call, const FileAccess& files);

// The 2-D scale about the origin, as a homogeneous matrix, that brings the
// box of `outlines` to `spec`'s sizes, x and y only (OpenSCAD's
// Polygon2d::resize); no outlines give the factors of an empty box.
glm::dmat3 resize_matrix_2d(const ResizeSpec& spec, const std::vector<Outline2d>& outlines);

}  // namespace capsim::scene_file
