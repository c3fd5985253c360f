#include "solver/linear_solver.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/IterativeLinearSolvers>

#include <limits>

#include "core/input_error.hpp"

namespace magfem {
namespace {

// Factorization flops and nnz(L) that CHOLMOD predicts with an AMD ordering: a quick
// symbolic analysis (no METIS) to decide whether a direct solve is affordable. AMD fills
// somewhat more than the METIS ordering used for the real factorization, so this errs on
// the side of CG.
std::pair<double, double> predicted_cholesky_cost(const Eigen::SparseMatrix<double>& lower) {
  cholmod_common c;
  cholmod_start(&c);
  c.nmethods = 1;
  c.method[0].ordering = CHOLMOD_AMD;
  c.supernodal = CHOLMOD_SUPERNODAL;
  Eigen::SparseMatrix<double> copy = lower; // viewAsCholmod needs a mutable view
  cholmod_sparse a = Eigen::viewAsCholmod(copy);
  a.stype = -1; // symmetric, lower triangle stored
  c.print = 0; // "problem too large" is an answer here, not an error to print
  cholmod_factor* l = cholmod_analyze(&a, &c);
  const double too_large = std::numeric_limits<double>::infinity();
  const std::pair<double, double> cost =
      (l && c.status == CHOLMOD_OK) ? std::pair{c.fl, c.lnz} : std::pair{too_large, too_large};
  cholmod_free_factor(&l, &c);
  cholmod_finish(&c);
  return cost;
}

} // namespace

struct LinearSolver::Impl {
  bool use_direct = true;
  bool analyzed = false;
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> direct;
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower,
                           Eigen::IncompleteCholesky<double, Eigen::Lower>>
      cg;
};

LinearSolver::LinearSolver(LinearSolverOptions options)
    : impl_(std::make_unique<Impl>()), options_(options) {}

LinearSolver::~LinearSolver() = default;

void LinearSolver::factorize(const Eigen::SparseMatrix<double>& lower) {
  if (!impl_->analyzed) {
    const bool automatic = options_.kind == LinearSolverKind::automatic;
    impl_->use_direct = options_.kind == LinearSolverKind::cholmod ||
                        (automatic && lower.rows() <= options_.direct_limit);
    if (impl_->use_direct && automatic && options_.direct_max_gflop > 0) {
      const auto [flops, lnz] = predicted_cholesky_cost(lower);
      predicted_gflop_ = flops * 1e-9;
      predicted_factor_gb_ = lnz * 12e-9; // value + row index
      impl_->use_direct = predicted_gflop_ <= options_.direct_max_gflop;
    }
    if (impl_->use_direct) impl_->direct.analyzePattern(lower);
  }
  if (impl_->use_direct) {
    impl_->direct.factorize(lower);
    if (impl_->direct.info() != Eigen::Success)
      throw SolveError("the system matrix is not positive definite (CHOLMOD); check that every "
                       "material has mu_r > 0 and the potential has a reference");
  } else {
    if (!impl_->analyzed) impl_->cg.analyzePattern(lower);
    impl_->cg.setTolerance(options_.cg_tolerance);
    impl_->cg.setMaxIterations(options_.cg_max_iterations);
    impl_->cg.factorize(lower);
    if (impl_->cg.info() != Eigen::Success)
      throw SolveError("incomplete Cholesky preconditioner failed");
  }
  impl_->analyzed = true;
}

Eigen::VectorXd LinearSolver::solve(const Eigen::VectorXd& rhs) {
  if (impl_->use_direct) {
    Eigen::VectorXd x = impl_->direct.solve(rhs);
    last_iterations_ = 1;
    return x;
  }
  Eigen::VectorXd x = impl_->cg.solve(rhs);
  last_iterations_ = static_cast<int>(impl_->cg.iterations());
  if (impl_->cg.info() != Eigen::Success)
    throw SolveError("conjugate gradients did not converge in " +
                     std::to_string(options_.cg_max_iterations) + " iterations (residual " +
                     std::to_string(impl_->cg.error()) + ")");
  return x;
}

std::string LinearSolver::name() const {
  return impl_->use_direct ? "cholmod" : "cg+ichol";
}

} // namespace magfem
