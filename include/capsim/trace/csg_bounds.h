#pragma once
// Boxes a view frames a CSG tree by: what the tree leaves (capsim's default
// view) and what OpenSCAD's preview draws (its --viewall).

#include "capsim/trace/primitive_geometry.h"

#include <span>
#include <vector>

namespace capsim {

// The box OpenSCAD 2021.01's preview frames (export_png's --viewall): its CSG
// tree pruned as it builds it (an intersection whose children's boxes do not
// meet is empty; a subtrahend whose box misses the minuend's is dropped), then
// the union of the boxes of the solids drawn positively, those under an even
// number of subtractions. An intersection frames all its children, not their
// common part (OpenSCAD's CSGProduct::getBoundingBox extends where it "should
// intersect").
Aabb openscad_preview_bounds(const CsgNode& node, std::span<const PreparedPrimitive> prims);

// A box holding what the CSG tree leaves: a union's is the union of its
// children's, an intersection's their common part, a difference's its first
// child's (what is subtracted only removes). Empty when the boxes show that
// nothing is left (an intersection of boxes that do not meet).
Aabb csg_result_bounds(const CsgNode& node, std::span<const PreparedPrimitive> prims);

}  // namespace capsim
