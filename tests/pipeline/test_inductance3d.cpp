// The 3D inductance matrix as the pipeline computes it (issue 35: the main solve's matrix and
// preconditioner reused for a linear case, all coils' loads from one element loop, the block
// CG stopped at 1e-5 with the variational correction) against a reference computed apart: the
// tangent assembled afresh at the run's solution, factorized by CHOLMOD (exact solves), each
// coil's sensitivity, no correction.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "casefile/case_spec.hpp"
#include "pipeline/run3d.hpp"
#include "postproc/coil_linkage3d.hpp"
#include "solver/assembler3d.hpp"
#include "solver/linear_solver.hpp"
#include "tests/case_helpers.hpp"

using namespace magfem;

namespace {

// L from exact sensitivity solves on the Newton tangent at the run's converged solution, one
// coil at a time (Assembler3D::current_derivative, one CHOLMOD solve each): none of the
// pipeline's block path (current_derivatives, solve_many, the kept operator, the correction).
Eigen::MatrixXd reference_inductance(const Run3D& run) {
  const Assembler3D assembler(run.problem, *run.dofs);
  const Eigen::VectorXd u = assembler.restrict_to_free(run.field->phi());
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> k;
  assembler.evaluate(u, r, &k, TangentKind::newton);
  LinearSolverOptions direct;
  direct.kind = LinearSolverKind::cholmod;
  LinearSolver solver(direct);
  solver.factorize(k);
  std::vector<Eigen::VectorXd> full;
  for (int j = 0; j < run.coils->n_coils(); ++j)
    full.push_back(assembler.expand(solver.solve(-assembler.current_derivative(u, j))));
  return inductance_matrix_3d(*run.field, full);
}

double largest_difference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

} // namespace

// Linear: three unlike coils (turns, sizes, places: every column and every entry differ)
// beside a linear iron block (its total potential: the loads' K Phi_s term) and a weak magnet
// (mu_r 1.05), solved by CG + pmg so that the block CG runs on the main solve's kept
// preconditioner. The case's linear_tolerance 1e-4 (the sensitivity solves take the looser of
// it and their own 1e-5) makes the solves' error visible: uncorrected the matrix is off by
// 3.7e-6 of its largest entry, with the variational correction by 2.1e-7 (its square plus
// the total region's small linear term). Tolerance 1e-6. A stale or wrong operator, a dropped
// or swapped column is off by O(1); the correction left out or of the wrong sign (7.5e-6)
// fails.
TEST(Inductance3D, ReusedOperatorAndLooseBlockSolveGiveTheExactSolvesMatrix) {
  const auto path = test::write_temp_case("inductance3d_linear.yaml", R"(dimension: 3
unit: mm
materials:
  iron: {kind: linear, mu_r: 1000}
  weak: {kind: magnet, B_r: 0.5, mu_r: 1.05}
regions:
  - {name: block, shape: box, size: [30, 30, 8], material: iron,
     placement: {translate: [0, 0, -12]}}
  - {name: magnet, shape: cylinder, r_outer: 5, height: 4, material: weak,
     magnetization: {type: axial}, placement: {translate: [18, 0, -2]}}
coils:
  - {name: a, shape: solenoid, r_inner: 4, r_outer: 7, length: 5, center: [0, 0, 0],
     axis: [0, 0, 1], turns: 200, current: 1}
  - {name: b, shape: solenoid, r_inner: 3, r_outer: 5, length: 4, center: [-16, 4, 2],
     axis: [1, 0, 0], turns: 50, current: 2}
  - {name: c, shape: solenoid, r_inner: 2, r_outer: 4, length: 6, center: [4, -16, 6],
     axis: [0, 1, 1], turns: 120, current: -1}
boundary: {type: open, radius: 45}
mesh: {size: 12, chord_tolerance: 1}
solver: {order: 2, linear_solver: cg, preconditioner: pmg, linear_tolerance: 1e-4}
output: {vtu: false}
)");
  const auto run = run_case_3d(read_case(path));
  ASSERT_EQ(run->report.preconditioner, "pmg");
  EXPECT_FALSE(run->report.factorized) << "the kept matrix is released after the coils";
  const Eigen::MatrixXd& l = run->coil_results.inductance_H;
  const Eigen::MatrixXd ref = reference_inductance(*run);
  ASSERT_EQ(l.rows(), 3);
  ASSERT_EQ(l.cols(), 3);
  const double error = largest_difference(l, ref);
  std::printf("%ld unknowns; L_11 %.8g H; largest difference from exact solves %.2e\n",
              static_cast<long>(run->dofs->n_dofs()), l(0, 0), error);
  EXPECT_LT(error, 1e-6);
  // Reciprocity: the matrix's asymmetry is the functional's own (discretization), not the
  // solves': the same as the exact solves' to 1e-6.
  EXPECT_NEAR(largest_difference(l, l.transpose()) * l.cwiseAbs().maxCoeff(),
              largest_difference(ref, ref.transpose()) * ref.cwiseAbs().maxCoeff(),
              1e-6 * ref.cwiseAbs().maxCoeff());
}

// Nonlinear, solved by Picard: the main solve's last matrix is the secant operator (mu I, no
// 2 mu' H H^T term) at the previous iterate, not the tangent at the solution, so it must not
// serve the sensitivity solves. The rod of steel_1010 saturates at 3 A (the differential
// inductance is ~16 % below the secant, test_coil_blind_spots3d.cpp), so a sensitivity on the
// secant operator is tens of percent off (measured: L_11 5 times too large). Tolerance 1e-6:
// both by CHOLMOD here, they agree to round-off.
TEST(Inductance3D, NonlinearPicardSolveDoesNotLendItsSecantOperator) {
  const auto path = test::write_temp_case(
      "inductance3d_picard.yaml",
      test::rod_in_solenoid_case3d(
          3, "{order: 1, method: picard, max_iterations: 300, tolerance: 1e-8}"));
  const auto run = run_case_3d(read_case(path));
  ASSERT_TRUE(run->report.converged) << run->report.message;
  const Eigen::MatrixXd& l = run->coil_results.inductance_H;
  const Eigen::MatrixXd ref = reference_inductance(*run);
  const double error = largest_difference(l, ref);
  std::printf("Picard: %d iterations; L_11 %.8g H, exact solves %.8g H; largest difference "
              "%.2e\n",
              run->report.iterations, l(0, 0), ref(0, 0), error);
  EXPECT_LT(error, 1e-6);
}
