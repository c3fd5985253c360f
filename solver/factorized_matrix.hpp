#pragma once
// A symmetric matrix kept together with its factorization or preconditioner, so that later
// solves with the same operator skip the set-up: the main solve of a linear problem hands it
// to the coils' sensitivity solves (current_sensitivity3d.hpp), whose tangent is that matrix.
#include <Eigen/SparseCore>

#include "solver/linear_solver.hpp"

namespace magfem {

struct FactorizedMatrix {
  explicit FactorizedMatrix(const LinearSolverOptions& options) : solver(options) {}
  Eigen::SparseMatrix<double> lower; // lower triangle; `solver` points at it (keep in place)
  LinearSolver solver;               // factorized (or preconditioned) for `lower`
};

} // namespace magfem
