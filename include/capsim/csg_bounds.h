#pragma once
// The box OpenSCAD frames a CSG tree by, for its --viewall.

#include "capsim/primitive_geometry.h"

#include <vector>

namespace capsim {

// The box OpenSCAD 2021.01's preview frames (export_png's --viewall): its CSG
// tree pruned as it builds it (an intersection whose children's boxes do not
// meet is empty; a subtrahend whose box misses the minuend's is dropped), then
// the union of the boxes of the solids drawn positively, those under an even
// number of subtractions. An intersection frames all its children, not their
// common part (OpenSCAD's CSGProduct::getBoundingBox extends where it "should
// intersect").
Aabb openscad_preview_bounds(const CsgNode& node, const std::vector<PreparedPrimitive>& prims);

}  // namespace capsim
