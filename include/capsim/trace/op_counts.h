#pragma once
// Operation counts a trace returns alongside its colour. The machine simulation
// charges cycles for each of them from a cost profile; the tracer knows nothing
// of time.

#include <cstdint>

namespace capsim {

struct OpCounts {
  std::uint64_t sphere_tests = 0;   // ray-sphere intersection tests
  std::uint64_t cone_tests = 0;     // ray-cone/cylinder intersection tests
  std::uint64_t box_tests = 0;      // ray-box intersection tests
  std::uint64_t mesh_tests = 0;     // ray-mesh intersections: the ray carried into the mesh's space
  std::uint64_t mesh_node_tests = 0;  // boxes of a mesh's hierarchy tested against the ray
  std::uint64_t triangle_tests = 0;   // mesh triangles tested against the ray
  std::uint64_t revolution_tests = 0;  // ray-revolution intersections: the ray carried into its space
  std::uint64_t revolution_edge_tests = 0;  // profile edges (cone, cylinder, annulus) tested
  std::uint64_t quartic_tests = 0;     // profile ellipses (tori) tested: a quartic's real roots
  std::uint64_t dda_setups = 0;     // Algorithm-2 set-ups (one per ray that meets the universe)
  std::uint64_t dda_steps = 0;      // Algorithm-2 voxel steps
  std::uint64_t voxel_passes = 0;   // partial evaluation: voxels visited that hold primitives,
                                    // in each of which Algorithm-4 runs over the voxel's crossings
  std::uint64_t tree_visits = 0;    // Algorithm-4 node visits (leaf toggles and operator nodes)
  std::uint64_t hits_sorted = 0;    // crossings put in order along the ray
  std::uint64_t shading_evals = 0;  // local illumination evaluations (one per light per hit)
  std::uint64_t matvec = 0;         // 4x4 matrix x vector products outside the intersection
                                    // tests (whose cost includes carrying the ray into
                                    // object space): two per surface normal
  std::uint64_t rays = 0;           // rays traced, all kinds
  std::uint64_t primary_rays = 0;
  std::uint64_t shadow_rays = 0;
  std::uint64_t secondary_rays = 0;  // reflection and refraction
  std::uint64_t aa_squares = 0;      // antialiasing: squares whose corners were compared
                                     // with the threshold and averaged

  std::uint64_t intersection_tests() const {
    return sphere_tests + cone_tests + box_tests + mesh_tests + revolution_tests;
  }
  // Inline, field by field: the machine adds a pixel's counts into its cell
  // for every pixel of every run, and the compiler pairs the fields into
  // vector additions.
  OpCounts& operator+=(const OpCounts& o) {
    sphere_tests += o.sphere_tests;
    cone_tests += o.cone_tests;
    box_tests += o.box_tests;
    mesh_tests += o.mesh_tests;
    mesh_node_tests += o.mesh_node_tests;
    triangle_tests += o.triangle_tests;
    revolution_tests += o.revolution_tests;
    revolution_edge_tests += o.revolution_edge_tests;
    quartic_tests += o.quartic_tests;
    dda_setups += o.dda_setups;
    dda_steps += o.dda_steps;
    voxel_passes += o.voxel_passes;
    tree_visits += o.tree_visits;
    hits_sorted += o.hits_sorted;
    shading_evals += o.shading_evals;
    matvec += o.matvec;
    rays += o.rays;
    primary_rays += o.primary_rays;
    shadow_rays += o.shadow_rays;
    secondary_rays += o.secondary_rays;
    aa_squares += o.aa_squares;
    return *this;
  }
  friend OpCounts operator+(OpCounts a, const OpCounts& b) { return a += b; }
  bool operator==(const OpCounts&) const = default;
};

// Work done by the host's voxel generation (Algorithm-3), charged to the host.
struct VoxelGenCounts {
  std::uint64_t primitives = 0;     // primitives placed
  std::uint64_t matmat = 0;         // 4x4 matrix x matrix products
  std::uint64_t matvec = 0;         // 4x4 matrix x vector products (box corners)
  std::uint64_t columns = 0;        // X-Y voxel columns examined
  std::uint64_t voxel_entries = 0;  // (voxel, primitive) entries written
  std::uint64_t grid_voxels = 0;    // voxels of the grid (N^3), each set up and given its list

  VoxelGenCounts& operator+=(const VoxelGenCounts& o);
  bool operator==(const VoxelGenCounts&) const = default;
};

}  // namespace capsim
