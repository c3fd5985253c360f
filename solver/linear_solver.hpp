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
  // automatic: and only if a quick symbolic analysis (AMD ordering) predicts at most this
  // many floating-point operations for the factorization (10^9). 3D systems fill in far
  // more than 2D ones: a 237k-unknown P2 tet system needs 870 GFlop and 2.7 GB, i.e. 11
  // minutes with Debian's reference BLAS (1.3 GFlop/s here), while CG+IC takes 20 s.
  // 0 = no limit.
  double direct_max_gflop = 20;
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
  // Factorization cost predicted by the automatic choice (0 if it did not look).
  double predicted_gflop() const { return predicted_gflop_; }
  double predicted_factor_gb() const { return predicted_factor_gb_; }

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  LinearSolverOptions options_;
  int last_iterations_ = 1;
  double predicted_gflop_ = 0, predicted_factor_gb_ = 0;
};

} // namespace magfem
