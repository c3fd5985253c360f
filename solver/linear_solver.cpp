#include "solver/linear_solver.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/IterativeLinearSolvers>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/input_error.hpp"
#include "core/progress.hpp"
#include "solver/petsc_solver.hpp"

namespace magfem {
namespace {
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

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
  c.print = 0;  // "problem too large" is an answer here, not an error to print
  cholmod_factor* l = cholmod_analyze(&a, &c);
  const double too_large = std::numeric_limits<double>::infinity();
  const std::pair<double, double> cost =
      (l && c.status == CHOLMOD_OK) ? std::pair{c.fl, c.lnz} : std::pair{too_large, too_large};
  cholmod_free_factor(&l, &c);
  cholmod_finish(&c);
  return cost;
}

using IncompleteCholesky = Eigen::IncompleteCholesky<double, Eigen::Lower>;

// Preconditioned conjugate gradients (the iteration of Eigen's ConjugateGradient, with its
// stopping test |r| < tol |b| on the recursively updated residual), reporting each iteration
// to `progress` and stopping on a breakdown (p.Ap <= 0: the matrix or the preconditioner is
// not positive definite) instead of iterating on garbage.
KrylovOutcome pcg(const Eigen::SparseMatrix<double>& lower, const IncompleteCholesky& m,
                  const Eigen::VectorXd& b, Eigen::VectorXd& x, double tol, int max_iterations,
                  Progress* progress) {
  KrylovOutcome out;
  const auto a = lower.selfadjointView<Eigen::Lower>();
  x = Eigen::VectorXd::Zero(b.size());
  const double b_norm2 = b.squaredNorm();
  if (b_norm2 == 0) {
    out.converged = true;
    out.reason = "zero right-hand side";
    return out;
  }
  const double threshold = std::max(tol * tol * b_norm2, (std::numeric_limits<double>::min)());
  Eigen::VectorXd r = b;
  Eigen::VectorXd p = m.solve(r);
  Eigen::VectorXd z(b.size()), ap(b.size());
  double r_norm2 = r.squaredNorm();
  double rz = r.dot(p);
  out.reason = "DIVERGED_ITS";
  int i = 0;
  while (r_norm2 >= threshold) {
    if (i == max_iterations)
      break;
    ap.noalias() = a * p;
    const double pap = p.dot(ap);
    if (!(pap > 0) || !(rz > 0)) {
      out.reason =
          std::isfinite(pap) && std::isfinite(rz) ? "DIVERGED_INDEFINITE" : "DIVERGED_NANORINF";
      break;
    }
    const double alpha = rz / pap;
    x += alpha * p;
    r -= alpha * ap;
    r_norm2 = r.squaredNorm();
    ++i;
    if (progress)
      progress->iteration("CG+ichol", i, std::sqrt(r_norm2 / b_norm2));
    if (r_norm2 < threshold)
      break;
    z = m.solve(r);
    const double rz_old = rz;
    rz = r.dot(z);
    p = z + (rz / rz_old) * p;
  }
  out.iterations = i;
  out.relative_residual = std::sqrt(r_norm2 / b_norm2);
  out.converged = r_norm2 < threshold;
  if (out.converged)
    out.reason = "CONVERGED_RTOL";
  return out;
}

} // namespace

double true_residual_limit(double tol) {
  return std::max(1e4 * tol, 1e-6);
}

std::string describe_krylov_stop(const KrylovOutcome& o, const std::string& method, double tol) {
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "%s did not converge: stopped after %d iterations (%s) at relative residual "
                "%.3e; the tolerance is %.1e",
                method.c_str(), o.iterations, o.reason.c_str(), o.relative_residual, tol);
  return buf;
}

std::string petsc_options_problem(const LinearSolverOptions& options) {
  PetscSolverOptions petsc;
  petsc.petsc_options = options.petsc_options;
  if (options.preconditioner == PreconditionerKind::gamg)
    petsc.preconditioner = "gamg";
  else if (options.preconditioner == PreconditionerKind::pmg)
    petsc.preconditioner = "pmg";
  return petsc_options_problem(petsc);
}

struct LinearSolver::Impl {
  bool use_direct = true;
  bool analyzed = false;
  bool use_amg = false;
  bool amg_may_fall_back = false;
  std::string amg_name = "boomeramg";
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> direct;
  IncompleteCholesky ichol;
  bool ichol_analyzed = false;
  std::unique_ptr<PetscSolver> amg;
  const Eigen::SparseMatrix<double>* matrix = nullptr;
};

LinearSolver::LinearSolver(LinearSolverOptions options)
    : impl_(std::make_unique<Impl>()), options_(options) {}

LinearSolver::~LinearSolver() = default;

void LinearSolver::choose(const Eigen::SparseMatrix<double>& lower) {
  const auto pre = options_.preconditioner;
  // Naming a preconditioner or PETSc options asks for CG.
  const bool wants_cg = pre != PreconditionerKind::automatic || !options_.petsc_options.empty();
  const bool automatic = options_.kind == LinearSolverKind::automatic && !wants_cg;
  impl_->use_direct = options_.kind == LinearSolverKind::cholmod ||
                      (automatic && lower.rows() <= options_.direct_limit);
  if (impl_->use_direct && automatic && options_.direct_max_gflop > 0) {
    const auto [flops, lnz] = predicted_cholesky_cost(lower);
    predicted_gflop_ = flops * 1e-9;
    predicted_factor_gb_ = lnz * 12e-9; // value + row index
    impl_->use_direct = predicted_gflop_ <= options_.direct_max_gflop;
  }
  if (impl_->use_direct)
    return;
  switch (pre) {
  case PreconditionerKind::automatic:
    // P2 tetrahedra (a coarse space given): p-multigrid, flat in iterations and faster than
    // incomplete Cholesky at every size measured (linear_solver.hpp). PETSc options keep
    // meaning BoomerAMG, as before.
    if (options_.coarse_prolongation && options_.petsc_options.empty()) {
      impl_->use_amg = true;
      impl_->amg_name = "pmg";
    } else {
      impl_->use_amg = !options_.petsc_options.empty() || lower.rows() >= options_.amg_min_unknowns;
    }
    impl_->amg_may_fall_back = true;
    break;
  case PreconditionerKind::ichol:
    impl_->use_amg = false;
    break;
  case PreconditionerKind::boomeramg:
  case PreconditionerKind::gamg:
    impl_->use_amg = true;
    impl_->amg_name = pre == PreconditionerKind::gamg ? "gamg" : "boomeramg";
    break;
  case PreconditionerKind::pmg:
    impl_->use_amg = true;
    impl_->amg_name = options_.coarse_prolongation ? "pmg" : "boomeramg";
    if (!options_.coarse_prolongation) {
      notes_.push_back("p-multigrid needs P2 tetrahedra (no coarser order here): BoomerAMG "
                       "on the system instead");
      if (options_.progress)
        options_.progress->note(notes_.back());
    }
    break;
  }
}

void LinearSolver::fall_back(const std::string& why) {
  notes_.push_back("AMG (" + impl_->amg_name + ") failed: " + why +
                   "; falling back to incomplete Cholesky");
  if (options_.progress)
    options_.progress->note(notes_.back());
  impl_->use_amg = false;
  impl_->amg.reset();
}

void LinearSolver::set_up_krylov(const Eigen::SparseMatrix<double>& lower) {
  if (impl_->use_amg) {
    if (options_.progress)
      options_.progress->stage("preconditioner set-up: " + impl_->amg_name + ", " +
                               std::to_string(lower.rows()) + " unknowns");
    try {
      if (!impl_->amg)
        impl_->amg = std::make_unique<PetscSolver>(
            PetscSolverOptions{impl_->amg_name, options_.petsc_options, options_.cg_tolerance,
                               options_.cg_max_iterations, options_.progress,
                               options_.coarse_prolongation.get(), options_.smoother_block.get()});
      impl_->amg->setup(lower);
      return;
    } catch (const SolveError& e) {
      if (!impl_->amg_may_fall_back)
        throw;
      fall_back(e.what());
    }
  }
  if (options_.progress)
    options_.progress->stage("preconditioner set-up: incomplete Cholesky, " +
                             std::to_string(lower.rows()) + " unknowns");
  if (!impl_->ichol_analyzed) {
    impl_->ichol.analyzePattern(lower);
    impl_->ichol_analyzed = true;
  }
  impl_->ichol.factorize(lower);
  if (impl_->ichol.info() != Eigen::Success)
    throw SolveError("incomplete Cholesky preconditioner failed");
}

void LinearSolver::set_cg_tolerance(double tol) {
  options_.cg_tolerance = tol;
  if (impl_->amg)
    impl_->amg->set_relative_tolerance(tol);
}

int LinearSolver::smoother_block_factorizations() const {
  return impl_->amg ? impl_->amg->block_factorizations() : 0;
}

void LinearSolver::factorize(const Eigen::SparseMatrix<double>& lower) {
  const auto t0 = Clock::now();
  if (!impl_->analyzed) {
    choose(lower);
    if (impl_->use_direct)
      impl_->direct.analyzePattern(lower);
  }
  impl_->analyzed = true;
  impl_->matrix = &lower;
  if (impl_->use_direct) {
    if (options_.progress)
      options_.progress->stage("factorization: CHOLMOD, " + std::to_string(lower.rows()) +
                               " unknowns");
    impl_->direct.factorize(lower);
    if (impl_->direct.info() != Eigen::Success)
      throw SolveError("the system matrix is not positive definite (CHOLMOD); check that every "
                       "material has mu_r > 0 and the potential has a reference");
  } else {
    set_up_krylov(lower);
  }
  setup_s_ += seconds_since(t0);
}

// Why the Krylov solve of a x = rhs that ended in `o` is not a solution ("" if it is).
std::string LinearSolver::krylov_failure(const KrylovOutcome& o, const Eigen::VectorXd& rhs,
                                         const Eigen::VectorXd& x,
                                         const std::string& method) const {
  const double tol = options_.cg_tolerance;
  if (!o.converged)
    return describe_krylov_stop(o, method, tol);
  const double b_norm = rhs.norm();
  if (b_norm == 0)
    return std::string();
  const double true_residual =
      (rhs - impl_->matrix->selfadjointView<Eigen::Lower>() * x).norm() / b_norm;
  if (true_residual <= true_residual_limit(tol))
    return std::string();
  char buf[200];
  std::snprintf(buf, sizeof buf, "; the true residual |b - A x| / |b| is %.3e", true_residual);
  return describe_krylov_stop(o, method, tol) + buf;
}

Eigen::VectorXd LinearSolver::solve_krylov(const Eigen::VectorXd& rhs) {
  const Eigen::SparseMatrix<double>& a = *impl_->matrix;
  const double tol = options_.cg_tolerance;
  auto failure = [&](const KrylovOutcome& o, const Eigen::VectorXd& x, const std::string& method) {
    return krylov_failure(o, rhs, x, method);
  };
  Eigen::VectorXd x;
  int iterations = 0;
  if (impl_->use_amg) {
    if (options_.progress)
      options_.progress->stage("solve: CG + " + impl_->amg->preconditioner_name());
    const KrylovOutcome o = impl_->amg->solve(rhs, x);
    iterations += o.iterations;
    const std::string why = failure(o, x, "CG + " + impl_->amg->preconditioner_name());
    last_iterations_ = iterations;
    if (why.empty())
      return x;
    if (!impl_->amg_may_fall_back)
      throw SolveError(why);
    fall_back(why);
    set_up_krylov(a);
  }
  if (options_.progress)
    options_.progress->stage("solve: CG + incomplete Cholesky");
  const KrylovOutcome o =
      pcg(a, impl_->ichol, rhs, x, tol, options_.cg_max_iterations, options_.progress);
  last_iterations_ = iterations + o.iterations;
  const std::string why = failure(o, x, "CG + incomplete Cholesky");
  if (!why.empty())
    throw SolveError(why);
  return x;
}

Eigen::VectorXd LinearSolver::solve(const Eigen::VectorXd& rhs) {
  const auto t0 = Clock::now();
  Eigen::VectorXd x;
  if (impl_->use_direct) {
    x = impl_->direct.solve(rhs);
    last_iterations_ = 1;
  } else {
    x = solve_krylov(rhs);
  }
  solve_s_ += seconds_since(t0);
  return x;
}

Eigen::MatrixXd LinearSolver::solve_many(const Eigen::MatrixXd& rhs) {
  const auto t0 = Clock::now();
  Eigen::MatrixXd x(rhs.rows(), rhs.cols());
  if (impl_->use_direct) {
    x = impl_->direct.solve(rhs);
    last_iterations_ = 1;
  } else if (impl_->use_amg) {
    if (options_.progress)
      options_.progress->stage("solve: CG + " + impl_->amg->preconditioner_name() + ", " +
                               std::to_string(rhs.cols()) + " right-hand sides together");
    const auto outcomes = impl_->amg->solve_many(rhs, x);
    last_iterations_ = 0;
    std::string why;
    for (Eigen::Index j = 0; j < rhs.cols() && why.empty(); ++j) {
      last_iterations_ = std::max(last_iterations_, outcomes[j].iterations);
      why = krylov_failure(outcomes[j], rhs.col(j), x.col(j),
                           "CG + " + impl_->amg->preconditioner_name());
    }
    if (!why.empty()) {
      if (!impl_->amg_may_fall_back)
        throw SolveError(why);
      fall_back(why);
      set_up_krylov(*impl_->matrix);
      for (Eigen::Index j = 0; j < rhs.cols(); ++j)
        x.col(j) = solve_krylov(rhs.col(j));
    }
  } else {
    for (Eigen::Index j = 0; j < rhs.cols(); ++j)
      x.col(j) = solve_krylov(rhs.col(j));
  }
  solve_s_ += seconds_since(t0);
  return x;
}

std::string LinearSolver::name() const {
  return impl_->use_direct ? "cholmod" : "cg";
}

std::string LinearSolver::preconditioner() const {
  if (impl_->use_direct)
    return "none";
  if (impl_->use_amg && impl_->amg)
    return impl_->amg->preconditioner_name();
  return impl_->use_amg ? impl_->amg_name : "ichol";
}

} // namespace magfem
