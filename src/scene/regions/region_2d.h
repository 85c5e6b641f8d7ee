#pragma once
// 2-D subtrees evaluated as OpenSCAD 2021.01 evaluates them: each shape
// tessellated (a circle into Calc::get_fragments_from_r's fragments), each
// leaf sanitized under the even-odd rule, transforms applied to the
// vertices, union, difference, intersection and offset() run by Clipper at
// OpenSCAD's scale (scene/regions/clipper_utils.h), DXF and SVG files read as
// OpenSCAD reads them. The result is a set of closed paths that do not cross
// (they may touch at vertices), read under the even-odd rule.
//
// The exact path (scene_extrusion.h: a circle extrudes to a true cylinder)
// stays the rule; a subtree is clipped only where it has to be: offset(), a
// 2-D import(), a polygon whose paths cross. Other extrusions (rotate_extrude,
// twisted linear_extrude) take their outlines from region_paths().

#include "scene/regions/clipper_utils.h"
#include "scene/reading/scene_syntax.h"

#include <cstddef>
#include <string>
#include <vector>

namespace capsim::scene_file {

// Where 2-D imports are read from: relative paths beside the scene file
// (import_dir), files of at most max_file_bytes.
struct RegionSources {
  std::string import_dir;
  std::size_t max_file_bytes = 0;
};

// At most this many vertices in any shape along the way: Clipper's time and
// memory grow with them.
inline constexpr std::size_t kMaxRegionVertices = 2000000;

// The 2-D subtree rooted at `call` as OpenSCAD's Polygon2d, sanitized. Throws
// SceneError at the call concerned: a 3-D object or setting inside, an
// unreadable import, coordinates beyond Clipper's range, too many vertices.
Polygon2d evaluate_region(const Call& call, const RegionSources& sources);

// The region's closed paths (even-odd rule), in the call's own frame: the
// outlines other extrusions build on. Empty when the region is.
std::vector<std::vector<glm::dvec2>> region_paths(const Call& call, const RegionSources& sources);

// A region placed by `plane` (the 2-D transforms above it), as paths that
// are each simple, with their nesting: parent[k] is the path directly around
// path k, or -1. Refuses a region of no area (nothing to draw) at the call.
struct NestedPaths {
  std::vector<std::vector<glm::dvec2>> paths;
  std::vector<int> parent;
};
NestedPaths nested_region_paths(const Call& call, const glm::dmat3& plane, const RegionSources& sources);

// Whether `call` must be clipped to be drawn: an offset(), a 2-D import(),
// a polygon whose paths cross or touch. (Its children are the region's
// business, not the exact path's.)
bool needs_clipping(const Call& call);

// Whether an import() names a 2-D file (.dxf, .svg).
bool is_2d_import(const Call& call);

}  // namespace capsim::scene_file
