#pragma once
// The P1 coarse space of a P2 tetrahedral system, for the two-level p-multigrid
// preconditioner: the piecewise linear functions on the same tetrahedra are a subspace of
// the quadratic ones, so the prolongation is exact interpolation: a vertex DOF takes the
// vertex value, an edge-midpoint DOF the mean of its two end vertices. Rows and columns are
// equations (free DOFs), not DOFs: a constrained vertex (phi = 0 on the outer boundary, the
// gauge) is no coarse unknown and contributes nothing to the midpoints next to it.
// (Curved, isoparametric elements make P1 only nearly a subspace; the coarse space is still
// a good one, and the preconditioner needs no more.)
#include <cstddef>
#include <functional>
#include <vector>

#include <Eigen/SparseCore>

#include "solver/dof_map3d.hpp"

namespace magfem {

// n_equations x n_free_vertices, row-major. `dof_to_eq`: equation of each DOF, -1 if
// constrained (Assembler3D::dof_to_equation). Empty (0 x 0) unless the map is of order 2.
Eigen::SparseMatrix<double, Eigen::RowMajor> p1_prolongation(const DofMap3D& dofs,
                                                             const std::vector<int>& dof_to_eq);

// The equations (sorted, unique) of the DOFs of the tets t < n_tets with in_block(t): the
// block that the p-multigrid smoother solves together (the open-boundary shell).
std::vector<int> element_equations(const DofMap3D& dofs, const std::vector<int>& dof_to_eq,
                                   std::size_t n_tets,
                                   const std::function<bool(std::size_t)>& in_block);

} // namespace magfem
