#pragma once
// The linear 3D system solved by all processes of an mpirun (MPI_COMM_WORLD) together: each
// assembles its own share of the tetrahedra into one distributed PETSc matrix and right-hand
// side (petsc_solver.hpp, distributed mode), CG with BoomerAMG or GAMG runs on all, and the
// solution comes back whole on rank 0, which alone post-processes.
//
// Replicated on every process: the mesh, the DOF map, the equation numbering and sparsity
// pattern (Assembler3D's set-up); distributed: the element loop, the matrix, the AMG
// hierarchy and the Krylov iteration.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "solver/assembler3d.hpp"
#include "solver/newton.hpp"

namespace magfem {

// The tetrahedra [first, last) process `rank` of `size` assembles: contiguous ranges of the
// mesh's element order with sizes that differ by at most one. The element loop is the work
// being shared and its cost per element is nearly uniform (one order, one quadrature rule
// apart from shell and curved elements), so equal counts balance it, and a range needs no
// partitioner. The price is locality: rows are owned in contiguous equation blocks, which
// need not match an element range, and the entries of rows another process owns travel to
// it once, at assembly (a graph partition of the elements would cut that traffic).
struct ElementRange {
  std::size_t first = 0, last = 0;
};
ElementRange element_share(std::size_t n_elements, int rank, int size);

// Collective. The linear system of `assembler` (is_linear() must hold) solved with the CG
// options in `options` (tolerance, iteration limit, preconditioner, petsc_options, progress)
// over MPI_COMM_WORLD. `u` gets the free-DOF solution on rank 0 and is empty elsewhere. The
// report is the one solve_nonlinear gives for a linear system, the same on every process;
// preconditioners that cannot run distributed (ichol, pmg) and the direct solver become
// BoomerAMG with a note. Throws SolveError, on every process alike, when CG stops short of
// the tolerance or the true residual does not confirm it.
NewtonReport solve_linear_distributed(const Assembler3D& assembler, const DofMap3D& dofs,
                                      std::size_t n_elements, int rank, int size,
                                      const LinearSolverOptions& options, Eigen::VectorXd& u);

} // namespace magfem
