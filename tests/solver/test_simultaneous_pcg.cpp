// Several right-hand sides solved together (solver/simultaneous_pcg, LinearSolver::solve_many):
// the inductance matrix's block solve. Checked against independent solves of each column:
// CHOLMOD's exact solution, and the one-column CG that solve() runs with the same
// preconditioner. A column dropped, swapped or scaled, or a V-cycle applied to the wrong
// columns, moves a column's solution by O(1), far outside the 1e-9 these allow.
#include <gtest/gtest.h>

#include <tuple>

#include <Eigen/Dense>

#include "box_problem3d.hpp"
#include "solver/assembler3d.hpp"
#include "solver/linear_solver.hpp"
#include "solver/p1_coarse_space.hpp"
#include "solver/simultaneous_pcg.hpp"

namespace magfem {
namespace {

// The P2 box (magnet and iron halves, Dirichlet faces), its tangent and n_rhs right-hand
// sides: the magnet's load and loads that differ in shape and scale (a point load, a smooth
// one scaled by 1e6, and zero, which must give zero).
struct BoxSystem : test::BoxTangent3D {
  Eigen::MatrixXd rhs;
  BoxSystem() {
    const int n = a.n_unknowns();
    rhs = Eigen::MatrixXd::Zero(n, 5);
    rhs.col(0) = load;
    rhs(n / 3, 1) = 1.0;
    for (int i = 0; i < n; ++i)
      rhs(i, 2) = 1e6 * std::sin(0.01 * i);
    rhs.col(4) = Eigen::VectorXd::Random(n);
  }
  LinearSolverOptions pmg_options(bool with_block) const {
    LinearSolverOptions o;
    o.kind = LinearSolverKind::cg;
    o.preconditioner = PreconditionerKind::pmg;
    o.cg_tolerance = 1e-12;
    o.coarse_prolongation = std::make_shared<const Eigen::SparseMatrix<double, Eigen::RowMajor>>(
        p1_prolongation(dofs, a.dof_to_equation()));
    if (with_block) // the iron half, standing in for the open boundary's shell
      o.smoother_block = std::make_shared<const std::vector<int>>(
          element_equations(dofs, a.dof_to_equation(), box.mesh.n_tets(),
                            [&](std::size_t t) { return box.mesh.tet_part[t] == 1; }));
    return o;
  }
};

Eigen::MatrixXd direct_solutions(const BoxSystem& s) {
  LinearSolverOptions o;
  o.kind = LinearSolverKind::cholmod;
  LinearSolver direct(o);
  direct.factorize(s.lower);
  Eigen::MatrixXd x(s.rhs.rows(), s.rhs.cols());
  for (Eigen::Index j = 0; j < s.rhs.cols(); ++j)
    x.col(j) = direct.solve(s.rhs.col(j));
  return x;
}

// Column j of x against column j of the reference, relative to the reference's norm (the zero
// column: absolutely zero).
void expect_columns_match(const Eigen::MatrixXd& x, const Eigen::MatrixXd& reference, double tol) {
  ASSERT_EQ(x.cols(), reference.cols());
  for (Eigen::Index j = 0; j < x.cols(); ++j) {
    const double scale = reference.col(j).norm();
    if (scale == 0)
      EXPECT_EQ(x.col(j).norm(), 0.0) << "column " << j;
    else
      EXPECT_LT((x.col(j) - reference.col(j)).norm(), tol * scale) << "column " << j;
  }
}

} // namespace

// CHOLMOD: all columns in one solve equal the column-by-column solves to round-off.
TEST(SimultaneousPcg, DirectSolveManyIsEachColumnsSolve) {
  const BoxSystem s;
  LinearSolverOptions o;
  o.kind = LinearSolverKind::cholmod;
  LinearSolver direct(o);
  direct.factorize(s.lower);
  expect_columns_match(direct.solve_many(s.rhs), direct_solutions(s), 1e-13);
}

// CG + pmg with the block smoother (our 3D systems' preconditioner): the columns run side by
// side through one V-cycle per iteration. Each reaches CHOLMOD's solution to 1e-9 (a residual
// of 1e-12 and a condition number below 1e3) and the one-column solve() to the same, in no
// more iterations than the slowest column needs alone: the V-cycle applied to a block is the
// one PETSc applies to a vector, so each column's iteration is the single CG's.
TEST(SimultaneousPcg, PmgBlockSolveIsEachColumnsSolve) {
  const BoxSystem s;
  LinearSolver pmg(s.pmg_options(true));
  pmg.factorize(s.lower);
  Eigen::MatrixXd single(s.rhs.rows(), s.rhs.cols());
  int most = 0;
  for (Eigen::Index j = 0; j < s.rhs.cols(); ++j) {
    single.col(j) = pmg.solve(s.rhs.col(j));
    most = std::max(most, pmg.last_iterations());
  }
  const Eigen::MatrixXd together = pmg.solve_many(s.rhs);
  EXPECT_EQ(pmg.preconditioner(), "pmg");
  std::printf("pmg: %d iterations for %ld columns together, at most %d for one alone\n",
              pmg.last_iterations(), static_cast<long>(s.rhs.cols()), most);
  const Eigen::MatrixXd exact = direct_solutions(s);
  expect_columns_match(together, exact, 1e-9);
  expect_columns_match(together, single, 1e-9);
  EXPECT_LE(pmg.last_iterations(), most + 1);
}

// Without a smoother block (or with another preconditioner) solve_many is one CG per column:
// the same solutions.
TEST(SimultaneousPcg, OtherPreconditionersSolveColumnByColumn) {
  const BoxSystem s;
  for (const auto pre : {PreconditionerKind::pmg, PreconditionerKind::ichol}) {
    LinearSolverOptions o = s.pmg_options(false);
    o.preconditioner = pre;
    LinearSolver cg(o);
    cg.factorize(s.lower);
    expect_columns_match(cg.solve_many(s.rhs), direct_solutions(s), 1e-9);
  }
}

// The iteration itself on a small dense system with a Jacobi preconditioner: a column that
// is zero stays zero and does not take part, the others converge each on its own count (a
// column of an eigenvector in one CG step), and a non-SPD operator is reported per column.
TEST(SimultaneousPcg, ColumnsStopOnTheirOwn) {
  const int n = 40;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    a(i, i) = 2 + 0.1 * i;
    if (i + 1 < n)
      a(i, i + 1) = a(i + 1, i) = -1;
  }
  const Eigen::VectorXd d = a.diagonal();
  ColumnBlock b = ColumnBlock::Zero(n, 3);
  b.col(0) = Eigen::VectorXd::LinSpaced(n, 1, 2);
  b(0, 2) = 1; // column 1 stays zero
  int calls_with_zero_column = 0;
  const BlockOperator op = [&](const ColumnBlock& x, ColumnBlock& y) {
    y = a * x;
    calls_with_zero_column += x.cols() == 3;
  };
  const BlockOperator jacobi = [&](const ColumnBlock& x, ColumnBlock& y) {
    y = d.cwiseInverse().asDiagonal() * x;
  };
  ColumnBlock x;
  const auto out = simultaneous_pcg(op, jacobi, b, x, 1e-12, 200, nullptr, "test");
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(calls_with_zero_column, 0);
  EXPECT_TRUE(out[1].converged);
  EXPECT_EQ(out[1].iterations, 0);
  EXPECT_EQ(x.col(1).norm(), 0.0);
  for (int j : {0, 2}) {
    EXPECT_TRUE(out[j].converged) << out[j].reason;
    const Eigen::VectorXd exact = a.ldlt().solve(Eigen::VectorXd(b.col(j)));
    EXPECT_LT((Eigen::VectorXd(x.col(j)) - exact).norm(), 1e-10 * exact.norm()) << "column " << j;
  }
  const BlockOperator indefinite = [&](const ColumnBlock& x, ColumnBlock& y) { y = -a * x; };
  const auto bad = simultaneous_pcg(indefinite, jacobi, b, x, 1e-12, 200, nullptr, "test");
  EXPECT_FALSE(bad[0].converged);
  EXPECT_EQ(bad[0].reason, "DIVERGED_INDEFINITE");
}

} // namespace magfem
