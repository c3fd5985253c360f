#pragma once
// How many tetrahedra the 3D mesher will make, estimated before it makes them (the memory
// guard: a case that would need more memory than the machine has is refused before TetGen
// allocates it, not killed an hour later).
//
// The estimate integrates the element density over the meshed ball: a mesh whose longest
// edges follow h(x) has about tets_per_h3 / h(x)^3 tetrahedra per unit volume, where h is the
// size field capped by the region size (TetGen's volume bound) of the part containing x. The
// integral runs over an octree refined until every cell is no larger than h at its centre;
// the field grows by at most its grading (0.3) across a cell, so the cell's value is within
// about 30 % of the exact integral over it. tets_per_h3 is calibrated on the 3D examples
// (docs/performance.md, "Memory guard calibration").
#include <functional>
#include <vector>

#include "mesh/geometry3d.hpp"

namespace magfem {

// Tetrahedra per h^3 of a TetGen quality mesh whose longest edges are bounded by h: a
// regular tetrahedron of edge h has volume h^3 / (6 sqrt 2) = 0.118 h^3 (8.5 per h^3), and
// the bound is a maximum, so the mean edge is shorter (calibrated: 32.6, docs/performance.md
// "Memory guard calibration").
extern const double tets_per_h3;

struct MeshEstimate3D {
  double tetrahedra = 0;
  double nodes = 0; // a Delaunay tetrahedral mesh has about 1 node per 5.5 tetrahedra
  long octree_cells = 0;
  // Per radius asked for (estimate_mesh_3d's within_radii): the share of `tetrahedra` within
  // the sphere of that radius about the origin (how a split of the domain there would divide
  // the work).
  std::vector<double> tetrahedra_within;
};

// size(x): the local size h(x) in metres (the mesher's size field, region caps included).
// ball_radius: the meshed ball (the open boundary's shell included). within_radii: spheres
// whose inner share to report in tetrahedra_within (same octree, so no extra size queries).
MeshEstimate3D estimate_mesh_3d(const std::function<double(const Vec3&)>& size, double ball_radius,
                                const std::vector<double>& within_radii = {});

} // namespace magfem
