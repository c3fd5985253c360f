#pragma once
// Sparse symmetric positive definite solves. CHOLMOD (supernodal Cholesky) is the default; a
// conjugate-gradient solver with incomplete-Cholesky preconditioning serves systems whose
// factor would not fit in memory. `automatic` picks by size. The symbolic analysis is done
// once per pattern and reused for every Newton step.
#include <memory>
#include <string>

#include <Eigen/SparseCore>

namespace magfem {

enum class LinearSolverKind { automatic, cholmod, cg };

struct LinearSolverOptions {
  LinearSolverKind kind = LinearSolverKind::automatic;
  // automatic: CHOLMOD up to this many unknowns, CG above.
  int direct_limit = 1'500'000;
  double cg_tolerance = 1e-12; // relative residual
  int cg_max_iterations = 20000;
};

class LinearSolver {
public:
  explicit LinearSolver(LinearSolverOptions options = {});
  ~LinearSolver();
  LinearSolver(const LinearSolver&) = delete;
  LinearSolver& operator=(const LinearSolver&) = delete;

  // `lower`: symmetric matrix given by its lower triangle. Throws SolveError if it is not
  // positive definite (a floating region without a gauge, a bad material).
  void factorize(const Eigen::SparseMatrix<double>& lower);
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs);
  std::string name() const;
  int last_iterations() const { return last_iterations_; }

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  LinearSolverOptions options_;
  int last_iterations_ = 1;
};

} // namespace magfem
