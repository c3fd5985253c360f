#pragma once
// The 3D system solved by all processes of an mpirun (MPI_COMM_WORLD) together: each
// assembles its own share of the tetrahedra (Assembler3D with AssemblyOptions3D::share) into
// one distributed PETSc matrix (DistributedLinearSolver), CG with BoomerAMG or GAMG runs on
// all, and the solution comes back whole on every process; rank 0 alone post-processes.
// Nonlinear systems run Newton (newton.hpp) on every process with the residuals summed over
// the processes (DistributedSystem3D): every residual evaluation, the line search's too, is
// distributed, and every process takes the same steps and reports the same convergence.
//
// Replicated on every process: the mesh, the DOF map, the equation numbering, the vectors
// (solution, residual) and, but for own-row assembly (distributed_rows.hpp), whose pattern
// covers the process's tetrahedra only, the sparsity pattern (Assembler3D's set-up);
// distributed: the element loops, the matrix, the AMG hierarchy and the Krylov iteration.
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "solver/assembler3d.hpp"
#include "solver/current_sensitivity3d.hpp"
#include "solver/element_range.hpp"
#include "solver/newton.hpp"

namespace magfem {

// Collective. The system of `share` (this process's share of the tetrahedra) solved over
// MPI_COMM_WORLD of `size` processes with options.linear's CG options (tolerance, iteration
// limit, preconditioner, petsc_options, progress) and, when nonlinear, Newton's. `u` gets the
// free-DOF solution on every process. The report is the same on every process; a linear
// system's is the one solve_nonlinear gives. Throws SolveError, on every process alike, when
// CG stops short of the tolerance or the true residual does not confirm it.
// `share` is let go as soon as the solve no longer needs it: a linear system's after its one
// assembly, and the assembled part once PETSc holds it, both before the preconditioner's
// set-up, where a process's memory peaks (issue 33: the share's pattern and scatter table
// were a sixth of it); a nonlinear system's after Newton. A caller that needs the share
// afterwards (the coils' sensitivity solves) keeps its own copy of the pointer.
NewtonReport solve_distributed(std::shared_ptr<const Assembler3D> share, int size,
                               const NewtonOptions& options, Eigen::VectorXd& u);

// Collective: du/dI_j for every coil j at the converged u with the variational correction
// (current_sensitivity3d.hpp), the tangent assembled by shares, one preconditioner set-up for
// all coils, the products K du_j summed over the processes; every process gets them whole.
CurrentSensitivities3D current_sensitivities_distributed(const Assembler3D& share, int size,
                                                         const Eigen::VectorXd& u, int n_coils,
                                                         const LinearSolverOptions& options);

} // namespace magfem
