// Every way the solvers can fail is reported, never passed off as a result: CHOLMOD on a
// matrix that is not positive definite, CG (incomplete Cholesky or AMG) stopped by its
// iteration limit or by an indefinite system, a PETSc "solve" that stopped without reaching
// the tolerance (caught by the true residual), Newton at its iteration limit and on a
// non-finite residual. (The CLI maps these to exit 3 with no outputs: tests/cli/test_cli.cpp.)
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "core/input_error.hpp"
#include "solver/linear_solver.hpp"
#include "solver/newton.hpp"

using namespace magfem;

namespace {

// Lower triangle of the 1D Dirichlet Laplacian tridiag(-1, 2, -1), with the given diagonal
// (negative: indefinite).
Eigen::SparseMatrix<double> laplacian(int n, double diagonal = 2.0) {
  Eigen::SparseMatrix<double> a(n, n);
  for (int i = 0; i < n; ++i) {
    a.insert(i, i) = diagonal;
    if (i > 0)
      a.insert(i, i - 1) = -1.0;
  }
  a.makeCompressed();
  return a;
}

// Lower triangle of the 2D five-point Laplacian on an n x n grid: incomplete Cholesky is not
// exact here (it is for the tridiagonal one), so CG needs tens of iterations.
Eigen::SparseMatrix<double> laplacian_2d(int n) {
  Eigen::SparseMatrix<double> a(n * n, n * n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int k = j * n + i;
      a.insert(k, k) = 4.0;
      if (i > 0)
        a.insert(k, k - 1) = -1.0;
      if (j > 0)
        a.insert(k, k - n) = -1.0;
    }
  a.makeCompressed();
  return a;
}

Eigen::SparseMatrix<double> identity_lower(int n) {
  Eigen::SparseMatrix<double> a(n, n);
  a.setIdentity();
  return a;
}

std::string solve_error(LinearSolverOptions options, const Eigen::SparseMatrix<double>& a) {
  try {
    LinearSolver s(options);
    s.factorize(a);
    const Eigen::VectorXd x = s.solve(Eigen::VectorXd::Ones(a.rows()));
    return "no error; |x| = " + std::to_string(x.norm());
  } catch (const SolveError& e) {
    return e.what();
  }
}

// r(u) = u^3 + u - load: convex, so Newton converges from 0 but needs several steps; the
// residual is made NaN when `poisoned` and u exceeds 0.5.
class Cubic : public NonlinearSystem {
public:
  explicit Cubic(bool poisoned) : poisoned_(poisoned) {}
  int n_unknowns() const override { return 1; }
  bool is_linear() const override { return false; }
  void evaluate(const Eigen::VectorXd& u, Eigen::VectorXd& r, Eigen::SparseMatrix<double>* k,
                TangentKind) const override {
    r.resize(1);
    r[0] = u[0] * u[0] * u[0] + u[0] - 10.0;
    if (poisoned_ && u[0] > 0.5)
      r[0] = std::numeric_limits<double>::quiet_NaN();
    if (k) {
      k->resize(1, 1);
      k->setZero();
      k->insert(0, 0) = 3 * u[0] * u[0] + 1;
    }
  }
  double load_norm() const override { return 10.0; }

private:
  bool poisoned_;
};

} // namespace

TEST(SolverFailures, CholmodRefusesAnIndefiniteMatrix) {
  LinearSolverOptions o;
  o.kind = LinearSolverKind::cholmod;
  EXPECT_EQ(solve_error(o, laplacian(50)).rfind("no error", 0), 0u); // control: SPD solves
  const std::string e = solve_error(o, laplacian(50, -2.0));
  EXPECT_NE(e.find("not positive definite"), std::string::npos) << e;
}

TEST(SolverFailures, CgStoppedByItsIterationLimitIsAnError) {
  LinearSolverOptions o;
  o.kind = LinearSolverKind::cg;
  o.cg_max_iterations = 3; // the 2500-unknown 2D Laplacian needs tens
  const std::string e = solve_error(o, laplacian_2d(50));
  EXPECT_NE(e.find("did not converge"), std::string::npos) << e;
  o.cg_max_iterations = 20000;
  EXPECT_EQ(solve_error(o, laplacian_2d(50)).rfind("no error", 0), 0u);
}

// BoomerAMG solves the 2D Laplacian to 1e-12 in about ten iterations; one is not enough,
// and a named preconditioner has no fallback: the limit is an error.
TEST(SolverFailures, AmgStoppedByItsIterationLimitIsAnError) {
  LinearSolverOptions o;
  o.preconditioner = PreconditionerKind::boomeramg;
  o.cg_max_iterations = 1;
  const std::string e = solve_error(o, laplacian_2d(50));
  EXPECT_NE(e.find("did not converge"), std::string::npos) << e;
  EXPECT_NE(e.find("DIVERGED_ITS"), std::string::npos) << e;
  o.cg_max_iterations = 20000;
  EXPECT_EQ(solve_error(o, laplacian_2d(50)).rfind("no error", 0), 0u);
}

// An indefinite matrix must stop CG + AMG with an error (PETSc's CG sees p.Ap < 0), never
// come back as a field: a peer's AMG once stopped early on an indefinite preconditioner and
// the wrong solution was post-processed.
TEST(SolverFailures, AmgOnAnIndefiniteMatrixIsAnError) {
  for (auto pre : {PreconditionerKind::boomeramg, PreconditionerKind::gamg}) {
    LinearSolverOptions o;
    o.preconditioner = pre;
    const std::string e = solve_error(o, laplacian_2d(20) - 6.0 * identity_lower(400));
    EXPECT_EQ(e.rfind("no error", 0), std::string::npos) << e;
  }
}

// `-ksp_type preonly` stops after one application of the preconditioner, and PETSc calls
// that converged; one Jacobi sweep is far from the solution, which the true residual
// |b - A x| / |b| exposes.
TEST(SolverFailures, AStopThatPetscCallsConvergedIsCheckedByTheTrueResidual) {
  LinearSolverOptions o;
  o.preconditioner = PreconditionerKind::boomeramg;
  o.petsc_options = "-ksp_type preonly -pc_type jacobi";
  const std::string e = solve_error(o, laplacian_2d(30));
  EXPECT_NE(e.find("true residual"), std::string::npos) << e;
}

// Automatic choice: AMG that fails (here: PETSc told to stop after 2 iterations) falls back
// to incomplete Cholesky, which solves, and the fallback is noted with its reason.
TEST(SolverFailures, AutomaticAmgFailureFallsBackToIncompleteCholeskyWithANote) {
  LinearSolverOptions o;
  o.kind = LinearSolverKind::cg;
  o.amg_min_unknowns = 1;
  o.petsc_options = "-ksp_max_it 2";
  const auto a = laplacian_2d(40);
  LinearSolver s(o);
  s.factorize(a);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(a.rows());
  const Eigen::VectorXd x = s.solve(b);
  EXPECT_LT((b - a.selfadjointView<Eigen::Lower>() * x).norm() / b.norm(), 1e-10);
  EXPECT_EQ(s.preconditioner(), "ichol");
  ASSERT_EQ(s.notes().size(), 1u);
  EXPECT_NE(s.notes()[0].find("falling back to incomplete Cholesky"), std::string::npos)
      << s.notes()[0];
  EXPECT_NE(s.notes()[0].find("DIVERGED_ITS"), std::string::npos) << s.notes()[0];
}

TEST(SolverFailures, NewtonAtItsIterationLimitReportsNoConvergence) {
  const Cubic cubic(false);
  NewtonOptions o;
  o.max_iterations = 2;
  Eigen::VectorXd u;
  const auto cut = solve_nonlinear(cubic, u, o);
  EXPECT_FALSE(cut.converged);
  EXPECT_NE(cut.message.find("no convergence in 2 iterations"), std::string::npos) << cut.message;
  o.max_iterations = 40;
  u.resize(0);
  const auto full = solve_nonlinear(cubic, u, o);
  ASSERT_TRUE(full.converged) << full.message;
  EXPECT_NEAR(u[0], 2.0, 1e-9); // 2^3 + 2 = 10
}

TEST(SolverFailures, NewtonStopsOnANonFiniteResidual) {
  const Cubic poisoned(true);
  NewtonOptions o;
  o.line_search = false; // the full step lands in the poisoned range at once
  Eigen::VectorXd u;
  const auto report = solve_nonlinear(poisoned, u, o);
  EXPECT_FALSE(report.converged);
  EXPECT_NE(report.message.find("non-finite"), std::string::npos) << report.message;
}
