#pragma once
// Exact line-mesh intersection: a line meets a closed mesh in any number of
// intervals. Each triangle is tested watertight (Woop, Benthin and Wald,
// "Watertight ray/triangle intersection", JCGT 2013): a line through an edge
// or a vertex shared by several triangles is claimed by exactly one of them
// where the surface goes on across it, and by both or neither where the line
// only grazes it, so no crossing is lost or doubled. A bounding-volume
// hierarchy over the triangles, built once per mesh, picks the triangles worth
// testing.

#include "capsim/scene/triangle_mesh.h"
#include "capsim/trace/op_counts.h"
#include "capsim/trace/ray.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace capsim {

// A node of the hierarchy: a leaf holds triangles order[first, first + count),
// an inner node (count 0) its children first and first + 1.
struct MeshNode {
  Aabb box;
  std::uint32_t first = 0;
  std::uint32_t count = 0;
};

struct MeshHierarchy {
  std::shared_ptr<const TriangleMesh> mesh;
  std::vector<MeshNode> nodes;       // nodes[0] is the root
  std::vector<std::uint32_t> order;  // triangle indices, leaf by leaf
  std::vector<glm::dvec3> face_normals;  // per triangle, outward, not normalised
};

// Splits at the median of the triangles' centres along the longest axis of
// their centres' box until at most 4 triangles are left; ties are broken by
// triangle index, so the hierarchy depends on nothing but the mesh.
MeshHierarchy build_mesh_hierarchy(std::shared_ptr<const TriangleMesh> mesh);

// A boundary crossing of a leaf along a line: at t the line enters (or
// leaves) the solid through surface `surface` (a mesh's triangle index).
struct LineCrossing {
  double t;
  int surface;
  bool enter;
};

// The crossings of the whole line o + t d (object space) with the mesh,
// sorted by t, entries and exits alternating from an entry. Crossings at
// equal t that cancel (a line touching an edge or a vertex from outside)
// leave none. Counts the hierarchy's boxes and the triangles tested.
// `hits` is working space.
void mesh_line_crossings(const MeshHierarchy& h, const glm::dvec3& o, const glm::dvec3& d,
                         std::vector<LineCrossing>& out, std::vector<LineCrossing>& hits, OpCounts& ops);

}  // namespace capsim
