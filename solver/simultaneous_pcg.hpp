#pragma once
// Preconditioned conjugate gradients on several right-hand sides at once: each column runs its
// own CG (its own step lengths, its own stop), but the operator and the preconditioner are
// applied to all columns together, so that one pass over the matrix (and over a multigrid
// hierarchy's matrices and factors) serves every column: the inductance matrix's sensitivity
// solves (current_sensitivity3d.cpp). Measured there (12 columns, P2, 172k unknowns) a pass
// over the block costs about 7.5 passes over one vector, not 12.
//
// Columns are kept row-major (n x m: a row's m values side by side), the layout in which a
// sparse row meets all columns in one sweep.
#include <functional>
#include <vector>

#include <Eigen/Core>

#include "solver/petsc_solver.hpp" // KrylovOutcome (the header is PETSc-free)

namespace magfem {

class Progress;

using ColumnBlock = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// y = op(x) for a block of columns (y is sized by the caller to x's shape).
using BlockOperator = std::function<void(const ColumnBlock& x, ColumnBlock& y)>;

// Solves A X = B from X = 0 for every column of B, each column stopping when its recursively
// updated residual |r| < tol |b| (the stop of the single-vector CGs in linear_solver.cpp).
// `a` and `m` (the preconditioner, symmetric positive definite) are applied to the still
// active columns only. One outcome per column; a column whose p.Ap or r.z is not positive
// stops with DIVERGED_INDEFINITE (or DIVERGED_NANORINF) and the others go on.
std::vector<KrylovOutcome> simultaneous_pcg(const BlockOperator& a, const BlockOperator& m,
                                            const ColumnBlock& b, ColumnBlock& x, double tol,
                                            int max_iterations, Progress* progress,
                                            const char* progress_name);

} // namespace magfem
