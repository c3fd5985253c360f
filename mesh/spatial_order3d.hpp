#pragma once
// Renumbers a tetrahedral mesh along a space-filling curve: its nodes in Hilbert order of
// their positions, then its tets in Hilbert order of their centroids (CGAL's hilbert_sort,
// median policy: deterministic). Why: TetGen numbers nodes in insertion order (surface
// points first, refinement points as they come), so the neighbours of a node, and with them
// the columns of a matrix row (DOFs are numbered vertices first, then edges by vertex pair),
// lie far apart in memory, and every pass over the matrix waits on gathers that miss the
// cache. On benchmark32's default mesh (2.1 M unknowns) the order took the CPU of the
// Gauss-Seidel sweeps, CG's products, the sparsity pattern and the Galerkin product from
// 15.9 to 6.2 s, and the whole run's from 60 to 48 s (perf samples; the sort itself 0.7 s),
// with the same 20 CG iterations. The mesh is the same: node positions, the tets' vertex order
// (orientation), their parts and the boundary faces are carried over.
#include "mesh/mesh3d.hpp"

namespace magfem {

// Renumbers m.nodes and m.tets (with m.tet_part) and remaps every node index the mesh holds
// (tets, outer_faces, symmetry_faces). Per-tet data beside tet_part must be computed after.
void order_spatially(Mesh3D& m);

} // namespace magfem
