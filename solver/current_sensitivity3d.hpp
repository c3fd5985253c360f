#pragma once
// Sensitivity of the 3D solution to each coil's current at a converged operating point:
// K du_j = -dr/dI_j with K the Newton tangent there. For linear problems du_j is the
// potential of coil j alone at 1 A; for nonlinear iron it is the small-signal response, from
// which the incremental (differential) inductance follows.
#include <vector>

#include <Eigen/Core>

#include "solver/assembler3d.hpp"
#include "solver/factorized_matrix.hpp"
#include "solver/linear_solver.hpp"

namespace magfem {

// du/dI_j for every coil j, as free-DOF vectors. One factorization (or preconditioner) of the
// tangent serves all coils, solved together (LinearSolver::solve_many).
std::vector<Eigen::VectorXd> current_sensitivities_3d(const Assembler3D& assembler,
                                                      const Eigen::VectorXd& u, int n_coils,
                                                      const LinearSolverOptions& options);
struct CurrentSensitivities3D {
  std::vector<Eigen::VectorXd> du; // du/dI_j, free DOFs
  // n_coils x n_coils: du_i . (f_j - K du_j), f_j = -dr/dI_j: each solve's residual weighed
  // by the other's solution. The inductance L_ij = c_ij + g_i . du_j is affine in du_j
  // (postproc/coil_linkage3d.hpp), g_i = -f_i but for the total-potential regions' discrete
  // K Phi_s; with an inexact du_j = du*_j + e_j it is off by g_i . e_j, linear in the error.
  // L_ij - correction_ij is off by e_i K e_j + (g_i + f_i) . e_j: the product of two
  // energy-norm errors, plus the small mismatch term (measured: 1/30 of the uncorrected error,
  // pipeline/coil_run3d.cpp and tests/pipeline/test_inductance3d.cpp).
  Eigen::MatrixXd correction;
};

// The correction above from the solutions (columns du_j), the right-hand sides f_j and the
// products K du_j.
Eigen::MatrixXd variational_correction(const Eigen::MatrixXd& du, const Eigen::MatrixXd& rhs,
                                       const Eigen::MatrixXd& k_du);

// The same with the correction, and with `same_operator` (may be null): the main solve's
// factorized matrix, used instead of assembling and setting up the tangent again when the
// system is linear (then its matrix is the tangent at every u). Ignored for a nonlinear
// system, whose main solve never factorized the tangent at the converged u.
CurrentSensitivities3D current_sensitivities_with_correction_3d(const Assembler3D& assembler,
                                                                const Eigen::VectorXd& u,
                                                                int n_coils,
                                                                const LinearSolverOptions& options,
                                                                FactorizedMatrix* same_operator);

} // namespace magfem
