#pragma once
// How many bytes the prepared scene occupies in a cell's memory, counted from
// the actual data structures as a cell's memory layout would hold them. Every
// number is a 4-byte word (single-precision float or 32-bit integer):
//   primitive:        kind 4 + object matrix 16 x 4 + cone radii 2 x 4
//                     + colour and alpha 4 x 4 + material 7 x 4          = 120 bytes
//   mesh, per primitive that is one: vertex 3 x 4 each; triangle 3 x 4
//                     indices + 3 x 4 normal + 4 in the hierarchy's order
//                     = 28 each; hierarchy node 6 x 4 box + 2 x 4 = 32 each
//   revolution, per primitive that is one: sweep, edge and ellipse counts
//                     3 x 4 + box 6 x 4 = 36; profile edge 2 ends, outward
//                     normal 6 x 4 = 24 each; ellipse centre 2 + form 3
//                     (symmetric) = 20 each
//   status-tree node: operator 1 + flags 1 (left child?, self, left, right)
//                     + padding 2 + parent index 4                       =   8 bytes
//   status-tree leaf: parent index 4 + flags 4 (per primitive)           =   8 bytes
//   voxel grid:       universe 6 x 4 + divisions 4 = 28 bytes,
//                     offsets (n^3 + 1) x 4, items entries x 4
//   camera:           eye, centre, up 9 x 4 + fov 4 + width, height 2 x 4 =  48 bytes
//   light:            position, colour                     6 x 4          =  24 bytes
//   background colour                                      3 x 4          =  12 bytes

#include "capsim/trace/prepared_scene.h"

#include <cstdint>

namespace capsim::sim {

inline constexpr std::uint64_t kPrimitiveRecordBytes = 120;
inline constexpr std::uint64_t kMeshVertexBytes = 12;
inline constexpr std::uint64_t kMeshTriangleBytes = 28;
inline constexpr std::uint64_t kMeshNodeBytes = 32;
inline constexpr std::uint64_t kRevolutionHeaderBytes = 36;
inline constexpr std::uint64_t kRevolvedEdgeBytes = 24;
inline constexpr std::uint64_t kRevolvedEllipseBytes = 20;
inline constexpr std::uint64_t kStatusNodeBytes = 8;
inline constexpr std::uint64_t kStatusLeafBytes = 8;
inline constexpr std::uint64_t kGridHeaderBytes = 28;
inline constexpr std::uint64_t kGridWordBytes = 4;
inline constexpr std::uint64_t kCameraBytes = 48;
inline constexpr std::uint64_t kLightBytes = 24;
inline constexpr std::uint64_t kBackgroundBytes = 12;

struct SceneFootprint {
  std::uint64_t primitives = 0;   // primitive records, and the meshes' and revolutions' data
  std::uint64_t status_tree = 0;  // operator nodes and leaves
  std::uint64_t view = 0;         // camera, lights, background
  std::uint64_t voxel_grid = 0;   // header, offsets, items

  // What the host broadcasts as "scene" and as "voxel data".
  std::uint64_t scene_bytes() const { return primitives + status_tree + view; }
  std::uint64_t voxel_bytes() const { return voxel_grid; }
};

SceneFootprint scene_footprint(const PreparedScene& scene);

}  // namespace capsim::sim
