#pragma once
// Sensitivity of the 3D solution to each coil's current at a converged operating point:
// K du_j = -dr/dI_j with K the Newton tangent there. For linear problems du_j is the
// potential of coil j alone at 1 A; for nonlinear iron it is the small-signal response, from
// which the incremental (differential) inductance follows.
#include <functional>
#include <vector>

#include <Eigen/Core>

#include "solver/assembler3d.hpp"
#include "solver/linear_solver.hpp"

namespace magfem {

// du/dI_j for every coil j, as free-DOF vectors. One factorization (or preconditioner) of the
// tangent serves all coils, solved together (LinearSolver::solve_many).
std::vector<Eigen::VectorXd> current_sensitivities_3d(const Assembler3D& assembler,
                                                      const Eigen::VectorXd& u, int n_coils,
                                                      const LinearSolverOptions& options);
// The same for any system and tangent solver: `load_derivative(j)` is dr/dI_j at u (a
// distributed solve: DistributedSystem3D's, with DistributedLinearSolver).
std::vector<Eigen::VectorXd>
current_sensitivities_3d(const NonlinearSystem& system,
                         const std::function<Eigen::VectorXd(int coil)>& load_derivative,
                         const Eigen::VectorXd& u, int n_coils, TangentSolver& solver);

} // namespace magfem
