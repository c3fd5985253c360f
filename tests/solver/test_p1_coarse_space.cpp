// The P1 coarse space of the p-multigrid preconditioner (solver/p1_coarse_space) and the
// preconditioner itself, on structured box meshes (no TetGen). The Galerkin identity
// P^T K_P2 P = K_P1 holds exactly on straight tetrahedra because P1 is a subspace of P2 and
// P interpolates it exactly: it checks the edge numbering, the 1/2 weights and the removal of
// constrained DOFs all at once.
#include <gtest/gtest.h>

#include <algorithm>
#include <tuple>

#include <Eigen/Dense>

#include "box_problem3d.hpp"
#include "core/input_error.hpp"
#include "solver/assembler3d.hpp"
#include "solver/galerkin_product.hpp"
#include "solver/linear_solver.hpp"
#include "solver/p1_coarse_space.hpp"

namespace magfem {
namespace {

constexpr double mm = 1e-3;

using Box = test::BoxProblem3D;

// The residual at u = 0 (minus the load) and the tangent's lower triangle.
std::pair<Eigen::VectorXd, Eigen::SparseMatrix<double>>
residual_and_tangent_at_zero(const Assembler3D& assembler) {
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> lower;
  assembler.evaluate(Eigen::VectorXd::Zero(assembler.n_unknowns()), r, &lower, TangentKind::newton);
  return {r, lower};
}

Eigen::SparseMatrix<double> full_tangent(const Assembler3D& assembler) {
  return residual_and_tangent_at_zero(assembler).second.selfadjointView<Eigen::Lower>();
}

// CG options with the P1 coarse space of these DOFs (pmg unless another preconditioner is set).
LinearSolverOptions cg_with_coarse_space(const DofMap3D& dofs, const Assembler3D& a) {
  LinearSolverOptions o;
  o.kind = LinearSolverKind::cg;
  o.coarse_prolongation = std::make_shared<const Eigen::SparseMatrix<double, Eigen::RowMajor>>(
      p1_prolongation(dofs, a.dof_to_equation()));
  return o;
}

// The reference: CHOLMOD's solution of lower x = rhs.
Eigen::VectorXd direct_solution(const Eigen::SparseMatrix<double>& lower,
                                const Eigen::VectorXd& rhs) {
  LinearSolverOptions direct_options;
  direct_options.kind = LinearSolverKind::cholmod;
  LinearSolver direct(direct_options);
  direct.factorize(lower);
  return direct.solve(rhs);
}

// Dirichlet (phi = 0 on the box's faces: every boundary vertex and midpoint constrained) and
// Neumann (one gauge vertex constrained): P^T K2 P equals the P1 matrix assembled directly, to
// round-off (1e-12 of the largest entry).
TEST(P1CoarseSpace, GalerkinOperatorIsTheP1Matrix) {
  for (const auto boundary : {OuterKind3D::dirichlet, OuterKind3D::neumann}) {
    const Box p2(3, 2, boundary), p1(3, 1, boundary);
    const DofMap3D dofs2(p2.mesh, 2), dofs1(p1.mesh, 1);
    const Assembler3D a2(p2.problem, dofs2), a1(p1.problem, dofs1);
    const auto p = p1_prolongation(dofs2, a2.dof_to_equation());
    ASSERT_EQ(p.rows(), a2.n_unknowns());
    ASSERT_EQ(p.cols(), a1.n_unknowns());
    const Eigen::MatrixXd galerkin = Eigen::MatrixXd(p.transpose() * full_tangent(a2) * p);
    const Eigen::MatrixXd direct = Eigen::MatrixXd(full_tangent(a1));
    EXPECT_LT((galerkin - direct).cwiseAbs().maxCoeff(), 1e-12 * direct.cwiseAbs().maxCoeff());
  }
}

// galerkin_product (pmg's coarse operator) equals Eigen's P^T A P entry by entry (to 1e-13 of
// the largest: only the summation order differs), on a box with a shell-free Neumann gauge and
// with Dirichlet faces, and gives the same bits with 1 and 3 threads. A wrong weight, a lost
// symmetric half or a row written into another's place fails it.
TEST(P1CoarseSpace, RowWiseGalerkinProductIsEigensAndIndependentOfThreads) {
  for (const auto boundary : {OuterKind3D::dirichlet, OuterKind3D::neumann}) {
    const Box box(4, 2, boundary);
    const DofMap3D dofs(box.mesh, 2);
    const Assembler3D a(box.problem, dofs);
    const auto p = p1_prolongation(dofs, a.dof_to_equation());
    Eigen::SparseMatrix<double, Eigen::RowMajor> full = full_tangent(a);
    full.makeCompressed();
    const CsrMatrix one =
        galerkin_product(full.outerIndexPtr(), full.innerIndexPtr(), full.valuePtr(), p, 1);
    const CsrMatrix three =
        galerkin_product(full.outerIndexPtr(), full.innerIndexPtr(), full.valuePtr(), p, 3);
    EXPECT_EQ(one.row_start, three.row_start);
    EXPECT_EQ(one.column, three.column);
    EXPECT_EQ(one.value, three.value);
    const Eigen::MatrixXd eigen = Eigen::MatrixXd(p.transpose() * full * p);
    ASSERT_EQ(one.rows, eigen.rows());
    Eigen::MatrixXd ours = Eigen::MatrixXd::Zero(one.rows, one.cols);
    for (int i = 0; i < one.rows; ++i)
      for (int k = one.row_start[i]; k < one.row_start[i + 1]; ++k) {
        if (k > one.row_start[i]) {
          EXPECT_LT(one.column[k - 1], one.column[k]); // sorted, as PETSc requires
        }
        ours(i, one.column[k]) = one.value[k];
      }
    EXPECT_LT((ours - eigen).cwiseAbs().maxCoeff(), 1e-13 * eigen.cwiseAbs().maxCoeff());
  }
}

// The row-wise product as an Eigen matrix, after checking its CSR shape: m + 1 row starts from
// 0 to the number of entries, columns in range and strictly increasing within each row.
Eigen::SparseMatrix<double> checked_csr(const CsrMatrix& c) {
  EXPECT_EQ(c.row_start.size(), static_cast<std::size_t>(c.rows) + 1);
  EXPECT_EQ(c.row_start.front(), 0);
  EXPECT_EQ(static_cast<std::size_t>(c.row_start.back()), c.column.size());
  EXPECT_EQ(c.column.size(), c.value.size());
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < c.rows && i + 1 < static_cast<int>(c.row_start.size()); ++i)
    for (int k = c.row_start[i]; k < c.row_start[i + 1]; ++k) {
      EXPECT_TRUE(c.column[k] >= 0 && c.column[k] < c.cols) << "row " << i;
      if (k > c.row_start[i]) {
        EXPECT_LT(c.column[k - 1], c.column[k]) << "row " << i;
      }
      t.emplace_back(i, c.column[k], c.value[k]);
    }
  Eigen::SparseMatrix<double> m(c.rows, c.cols);
  m.setFromTriplets(t.begin(), t.end());
  return m;
}

// The product is cut into blocks of galerkin_block_rows (2048) coarse rows, and the test above
// has 124 coarse rows: one block. Here a Neumann box of 13^3 cells has 14^3 - 1 = 2743 coarse
// rows, so the default runs two blocks, the second one partial (695 rows), and smaller blocks
// cut it into many (1, 100, 999 rows; 4096 is one block again). Every variant must equal
// Eigen's P^T A P to 1e-13 of the largest entry (only the summation order differs) and give
// the same bits as the default: each row is summed alone, so the blocks change nothing. A
// block whose last rows are dropped, or rows written at a wrong offset, fails both.
TEST(P1CoarseSpace, RowWiseGalerkinProductOverManyBlocksIsEigens) {
  const Box box(13, 2, OuterKind3D::neumann);
  const DofMap3D dofs(box.mesh, 2);
  const Assembler3D a(box.problem, dofs);
  const auto p = p1_prolongation(dofs, a.dof_to_equation());
  ASSERT_GT(static_cast<std::size_t>(p.cols()), galerkin_block_rows);
  ASSERT_NE(p.cols() % static_cast<int>(galerkin_block_rows), 0); // a partial last block
  Eigen::SparseMatrix<double, Eigen::RowMajor> full = full_tangent(a);
  full.makeCompressed();
  const Eigen::SparseMatrix<double> eigen = p.transpose() * full * p;
  const double scale = eigen.coeffs().cwiseAbs().maxCoeff();
  const CsrMatrix ours =
      galerkin_product(full.outerIndexPtr(), full.innerIndexPtr(), full.valuePtr(), p, 2);
  ASSERT_EQ(ours.rows, eigen.rows());
  ASSERT_EQ(ours.cols, eigen.cols());
  const Eigen::SparseMatrix<double> difference = checked_csr(ours) - eigen;
  EXPECT_LT(difference.coeffs().cwiseAbs().maxCoeff(), 1e-13 * scale);
  for (const std::size_t block :
       {std::size_t{1}, std::size_t{100}, std::size_t{999}, std::size_t{4096}}) {
    const CsrMatrix other =
        galerkin_product(full.outerIndexPtr(), full.innerIndexPtr(), full.valuePtr(), p, 2, block);
    EXPECT_EQ(other.row_start, ours.row_start) << "block " << block;
    EXPECT_EQ(other.column, ours.column) << "block " << block;
    EXPECT_EQ(other.value, ours.value) << "block " << block;
  }
}

// A distributed coarse operator is the sum of the processes' shares (partial_galerkin_product):
// the rows split over three "processes" in an order that interleaves them (row r to process
// 7 r mod 3), each process's rows renumbered 0.. and kept as PETSc does, a diagonal block (the
// columns it owns, local numbering) and an off-diagonal one (the rest, compressed). The shares,
// each summed into the coarse rows it names, must give Eigen's P^T A P to 1e-13 of the largest
// entry. A column read through the wrong block's map, a dropped block or a row taken for
// another's fails it, and so do unsorted rows or columns.
TEST(P1CoarseSpace, PartialGalerkinProductsOverRowBlocksSumToEigens) {
  const Box box(6, 2, OuterKind3D::neumann);
  const DofMap3D dofs(box.mesh, 2);
  const Assembler3D a(box.problem, dofs);
  const auto p = p1_prolongation(dofs, a.dof_to_equation());
  Eigen::SparseMatrix<double, Eigen::RowMajor> full = full_tangent(a);
  full.makeCompressed();
  const Eigen::SparseMatrix<double> eigen = p.transpose() * full * p;
  const int n = static_cast<int>(full.rows());
  const auto process_of = [](int r) { return (7 * r) % 3; };
  Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(p.cols(), p.cols());
  for (int process = 0; process < 3; ++process) {
    std::vector<int> equations, local(n, -1);
    for (int r = 0; r < n; ++r)
      if (process_of(r) == process) {
        local[r] = static_cast<int>(equations.size());
        equations.push_back(r);
      }
    std::vector<int> off_columns; // the off-diagonal block's columns (equations), compressed
    std::vector<int> d_start{0}, d_column, o_start{0}, o_column, o_index(n, -1);
    std::vector<double> d_value, o_value;
    for (int r : equations) {
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(full, r); it; ++it) {
        const int c = static_cast<int>(it.col());
        if (local[c] >= 0) {
          d_column.push_back(local[c]);
          d_value.push_back(it.value());
          continue;
        }
        if (o_index[c] < 0) {
          o_index[c] = static_cast<int>(off_columns.size());
          off_columns.push_back(c);
        }
        o_column.push_back(o_index[c]);
        o_value.push_back(it.value());
      }
      d_start.push_back(static_cast<int>(d_column.size()));
      o_start.push_back(static_cast<int>(o_column.size()));
    }
    const std::vector<CsrRowBlock> blocks = {
        {d_start.data(), d_column.data(), d_value.data(), equations.data()},
        {o_start.data(), o_column.data(), o_value.data(), off_columns.data()}};
    std::vector<int> coarse_rows;
    CsrMatrix share = partial_galerkin_product(static_cast<int>(equations.size()), blocks,
                                               equations.data(), p, coarse_rows);
    ASSERT_EQ(static_cast<int>(coarse_rows.size()), share.rows);
    EXPECT_TRUE(std::is_sorted(coarse_rows.begin(), coarse_rows.end()));
    EXPECT_EQ(std::adjacent_find(coarse_rows.begin(), coarse_rows.end()), coarse_rows.end());
    const Eigen::MatrixXd rows = Eigen::MatrixXd(checked_csr(share));
    for (int i = 0; i < share.rows; ++i)
      sum.row(coarse_rows[i]) += rows.row(i);
  }
  const double scale = eigen.coeffs().cwiseAbs().maxCoeff();
  EXPECT_LT((sum - Eigen::MatrixXd(eigen)).cwiseAbs().maxCoeff(), 1e-13 * scale);
}

// A linear potential is in P1: its coarse vector, prolonged, is the P2 interpolant (vertex and
// midpoint values of the same linear function), exactly.
TEST(P1CoarseSpace, ProlongationInterpolatesLinearPotentials) {
  const Box box(2, 2, OuterKind3D::neumann);
  const DofMap3D dofs(box.mesh, 2);
  const Assembler3D a(box.problem, dofs);
  const auto p = p1_prolongation(dofs, a.dof_to_equation());
  auto phi = [](const Eigen::Vector3d& x) {
    return 2 + 3 * x.x() / mm - x.y() / mm + 5 * x.z() / mm;
  };
  // The gauge vertex (DOF 0, at the origin) is constrained, i.e. phi = 0 there: shift phi.
  const double offset = phi(dofs.dof_points()[0]);
  Eigen::VectorXd coarse(p.cols()), fine_exact(p.rows());
  const auto& eq = a.dof_to_equation();
  int c = 0;
  for (int d = 0; d < dofs.n_dofs(); ++d) {
    if (eq[d] < 0)
      continue;
    const double v = phi(dofs.dof_points()[d]) - offset;
    fine_exact[eq[d]] = v;
    if (d < dofs.n_vertices())
      coarse[c++] = v;
  }
  ASSERT_EQ(c, p.cols());
  EXPECT_LT((p * coarse - fine_exact).cwiseAbs().maxCoeff(),
            1e-12 * fine_exact.cwiseAbs().maxCoeff());
}

// A box problem assembled at u = 0: the residual (minus the load) and the tangent's lower
// triangle, with the DOF map and assembler they came from.
struct BoxSystem {
  Box box;
  DofMap3D dofs;
  Assembler3D a;
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> lower;
  BoxSystem(int n, int order, OuterKind3D outer)
      : box(n, order, outer), dofs(box.mesh, order), a(box.problem, dofs) {
    std::tie(r, lower) = residual_and_tangent_at_zero(a);
  }
};

// CG with pmg (options o) reaches CHOLMOD's solution (1e-9) in fewer than 30 iterations.
void expect_pmg_solves_to_the_direct_solution(const LinearSolverOptions& o, const BoxSystem& s) {
  LinearSolver pmg(o);
  pmg.factorize(s.lower);
  const Eigen::VectorXd x = pmg.solve(-s.r);
  EXPECT_EQ(pmg.preconditioner(), "pmg");
  const Eigen::VectorXd exact = direct_solution(s.lower, -s.r);
  EXPECT_LT((x - exact).norm(), 1e-9 * exact.norm());
  EXPECT_LT(pmg.last_iterations(), 30) << "of " << s.a.n_unknowns() << " unknowns";
  std::printf("pmg: %d CG iterations for %d unknowns\n", pmg.last_iterations(), s.a.n_unknowns());
}

// CG + p-multigrid solves the P2 box problem to the direct solution (relative difference
// 1e-9 for a 1e-12 residual and a condition number below 1e3), in far fewer iterations than
// unknowns: a preconditioner that were not symmetric positive definite, or a coarse space
// numbered wrongly, would stall CG or need hundreds of iterations (measured: 10).
TEST(P1CoarseSpace, PmgSolvesToTheDirectSolution) {
  const BoxSystem s(6, 2, OuterKind3D::dirichlet);
  LinearSolverOptions o = cg_with_coarse_space(s.dofs, s.a);
  o.preconditioner = PreconditionerKind::pmg;
  expect_pmg_solves_to_the_direct_solution(o, s);
}

// The block smoother (some equations solved together by CHOLMOD, Gauss-Seidel on the others,
// forward before the coarse correction and backward after it): the V-cycle must stay one
// symmetric positive definite operator, else CG stalls or breaks down. Here the block is the
// equations of the iron half of the box; same solution as CHOLMOD's, in few iterations.
TEST(P1CoarseSpace, PmgWithASmootherBlockSolvesToTheDirectSolution) {
  const BoxSystem s(6, 2, OuterKind3D::dirichlet);
  LinearSolverOptions o = cg_with_coarse_space(s.dofs, s.a);
  o.preconditioner = PreconditionerKind::pmg;
  o.smoother_block = std::make_shared<const std::vector<int>>(
      element_equations(s.dofs, s.a.dof_to_equation(), s.box.mesh.n_tets(),
                        [&](std::size_t t) { return s.box.mesh.tet_part[t] == 1; }));
  ASSERT_GT(o.smoother_block->size(), 0u);
  ASSERT_LT(o.smoother_block->size(), static_cast<std::size_t>(s.a.n_unknowns()));
  expect_pmg_solves_to_the_direct_solution(o, s);
}

// Newton sets the preconditioner up at every step, while the smoother block (the open-boundary
// shell: air) does not change: its Cholesky factor is reused as long as the block's entries are
// the ones it was computed from, and computed again when one changes. Each solve must still
// reach CHOLMOD's solution of its own matrix. Here the block is the air half of the box; the
// iron half's diagonal grows (as saturation changes the tangent in iron), then one block
// entry does. Would fail on: a block change not seen (a stale factor kept: count 1 at the
// end), or no reuse at all (count 3).
TEST(P1CoarseSpace, PmgReusesTheSmootherBlockFactorWhileTheBlockIsUnchanged) {
  const BoxSystem s(6, 2, OuterKind3D::dirichlet);
  LinearSolverOptions o = cg_with_coarse_space(s.dofs, s.a);
  o.preconditioner = PreconditionerKind::pmg;
  const auto block = element_equations(s.dofs, s.a.dof_to_equation(), s.box.mesh.n_tets(),
                                       [&](std::size_t t) { return s.box.mesh.tet_part[t] != 1; });
  o.smoother_block = std::make_shared<const std::vector<int>>(block);
  std::vector<bool> in_block(s.a.n_unknowns(), false);
  for (int e : block)
    in_block[e] = true;
  const auto first_outside = std::find(in_block.begin(), in_block.end(), false) - in_block.begin();
  ASSERT_LT(first_outside, s.a.n_unknowns());
  LinearSolver pmg(o);
  auto solve_and_check = [&](const Eigen::SparseMatrix<double>& lower) {
    pmg.factorize(lower);
    const Eigen::VectorXd x = pmg.solve(-s.r);
    const Eigen::VectorXd exact = direct_solution(lower, -s.r);
    EXPECT_LT((x - exact).norm(), 1e-9 * exact.norm());
  };
  solve_and_check(s.lower);
  EXPECT_EQ(pmg.smoother_block_factorizations(), 1);

  Eigen::SparseMatrix<double> stiffer_iron = s.lower;
  for (int e = 0; e < s.a.n_unknowns(); ++e)
    if (!in_block[e])
      stiffer_iron.coeffRef(e, e) *= 1.5;
  solve_and_check(stiffer_iron);
  EXPECT_EQ(pmg.smoother_block_factorizations(), 1);

  Eigen::SparseMatrix<double> changed_block = stiffer_iron;
  changed_block.coeffRef(block.front(), block.front()) *= 1.5;
  solve_and_check(changed_block);
  EXPECT_EQ(pmg.smoother_block_factorizations(), 2);
}

// CG's automatic preconditioner is pmg when a coarse space is given; a pmg that fails (here
// its set-up: a smoother block naming an equation that does not exist) falls back to
// incomplete Cholesky, which solves, with the reason in a note.
TEST(P1CoarseSpace, AutomaticIsPmgAndFallsBackToIncompleteCholeskyWithANote) {
  const BoxSystem sys(4, 2, OuterKind3D::dirichlet);
  const auto& [r, lower] = std::tie(sys.r, sys.lower);
  LinearSolverOptions o = cg_with_coarse_space(sys.dofs, sys.a);
  {
    LinearSolver s(o);
    s.factorize(lower);
    const Eigen::VectorXd x = s.solve(-r);
    EXPECT_EQ(s.preconditioner(), "pmg");
    EXPECT_TRUE(s.notes().empty());
    EXPECT_LT((-r - lower.selfadjointView<Eigen::Lower>() * x).norm(), 1e-10 * r.norm());
  }
  o.smoother_block = std::make_shared<const std::vector<int>>(std::vector<int>{sys.a.n_unknowns()});
  LinearSolver s(o);
  s.factorize(lower);
  const Eigen::VectorXd x = s.solve(-r);
  EXPECT_LT((-r - lower.selfadjointView<Eigen::Lower>() * x).norm(), 1e-10 * r.norm());
  EXPECT_EQ(s.preconditioner(), "ichol");
  ASSERT_EQ(s.notes().size(), 1u);
  EXPECT_NE(s.notes()[0].find("falling back to incomplete Cholesky"), std::string::npos)
      << s.notes()[0];
  EXPECT_NE(s.notes()[0].find("out of range"), std::string::npos) << s.notes()[0];
}

// Without a coarse space (P1 elements, 2D) pmg is BoomerAMG on the system, with a note.
TEST(P1CoarseSpace, PmgWithoutACoarseSpaceIsBoomerAmgWithANote) {
  const Box box(4, 1, OuterKind3D::dirichlet);
  const DofMap3D dofs(box.mesh, 1);
  const Assembler3D a(box.problem, dofs);
  EXPECT_EQ(p1_prolongation(dofs, a.dof_to_equation()).size(), 0);
  const auto [r, lower] = residual_and_tangent_at_zero(a);
  LinearSolverOptions o;
  o.kind = LinearSolverKind::cg;
  o.preconditioner = PreconditionerKind::pmg;
  LinearSolver s(o);
  s.factorize(lower);
  const Eigen::VectorXd x = s.solve(-r);
  EXPECT_LT((-r - lower.selfadjointView<Eigen::Lower>() * x).norm(), 1e-10 * r.norm());
  EXPECT_EQ(s.preconditioner(), "boomeramg");
  ASSERT_EQ(s.notes().size(), 1u);
  EXPECT_NE(s.notes()[0].find("p-multigrid needs P2"), std::string::npos) << s.notes()[0];
}

// petsc_options that PETSc would ignore or refuse are named before any solve (the case reader
// turns the answer into exit 2): a word that is no option, an unknown type, a bad number.
TEST(P1CoarseSpace, PetscOptionsProblemsAreFoundBeforeTheSolve) {
  LinearSolverOptions o;
  o.preconditioner = PreconditionerKind::pmg;
  for (const char* good : {"", "-mg_levels_ksp_max_it 2", "-mg_coarse_pc_type lu",
                           "-pc_type gamg -pc_gamg_threshold 0.05"}) {
    o.petsc_options = good;
    EXPECT_EQ(petsc_options_problem(o), "") << good;
  }
  const std::pair<const char*, const char*> bad[] = {
      {"pc_type gamg", "'pc_type' is neither a PETSc option"},
      {"-pc_type gamg extra", "'extra'"},
      {"-pc_type nonsense", "nonsense"},
      {"-ksp_rtol abc", "abc"},
      {"-mg_levels_pc_type nonsense", "nonsense"}};
  for (const auto& [options, says] : bad) {
    o.petsc_options = options;
    const std::string why = petsc_options_problem(o);
    EXPECT_NE(why.find(says), std::string::npos) << options << ": " << why;
  }
}

} // namespace
} // namespace magfem
