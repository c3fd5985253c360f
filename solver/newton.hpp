#pragma once
// Nonlinear solve of r(u) = 0 by Newton-Raphson (exact symmetric Jacobian, CHOLMOD) with a
// backtracking line search on the residual norm, or by Picard (secant) iteration. Stops when
// BOTH the relative residual and the relative update are below their tolerances. A linear
// problem takes exactly one step. The outcome is a report the caller must check; nothing
// here throws for non-convergence.
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "solver/factorized_matrix.hpp"
#include "solver/linear_solver.hpp"
#include "solver/nonlinear_system.hpp"

namespace magfem {

struct NewtonOptions {
  TangentKind method = TangentKind::newton;
  double residual_tol = 1e-9; // |r| / |load|
  double update_tol = 1e-9;   // |du| / |u|
  int max_iterations = 40;
  bool line_search = true;
  // Start from the solution of the system's start problem (NonlinearSystem::start_problem),
  // when it has one and u is zero on entry; it counts as iteration 1. Why (3D scalar
  // potential with coils): at u = 0 the iron's H is the coil's field without the iron, deep
  // in saturation, where the tangent permeability is about mu0; from there Newton's first
  // steps make the iron look like air, and the line search crawls back (TEAM 20 at 3000 AT,
  // order 1, mesh scale 4: 20 iterations, steps down to 0.1; from the linear start: 8, all
  // full steps). The 2D A formulation has no start problem: its u = 0 is B = 0, where the
  // tangent is already the initial permeability.
  bool linear_start = true;
  // Inexact Newton: far from the solution a Krylov solve to linear.cg_tolerance is wasted
  // (the next residual is dominated by the linearization, not by the solve), so each step's
  // tolerance follows the residual's progress (Eisenstat and Walker's second choice), between
  // linear.cg_tolerance and this ceiling; the last steps, where Newton is quadratic, solve to
  // linear.cg_tolerance. 0 = every step to linear.cg_tolerance. No effect on direct solves.
  // (The start problem's solve is not a Newton step and goes tighter: solver/newton.cpp.)
  double forcing_max = 0.1;
  // Linear systems: hand the factorized matrix back (NewtonReport::factorized) for further
  // solves with the same operator. Off by default: it keeps the matrix and the preconditioner
  // in memory after the solve.
  bool keep_linear_factorization = false;
  LinearSolverOptions linear;
};

struct NewtonReport {
  bool converged = false;
  bool linear = false; // the system is linear: one exact step
  int iterations = 0;
  std::vector<double> residual_history; // relative residuals, starting with the initial one
  std::vector<double> step_lengths;     // line-search factor per iteration
  std::string linear_solver;            // cholmod | cg
  std::string preconditioner;           // none | ichol | boomeramg | gamg
  int linear_iterations = 0;            // summed (CG) or number of factorizations (direct)
  double assemble_s = 0, solve_s = 0;
  // solve_s split: factorization / preconditioner set-up, and the solves themselves.
  double linear_setup_s = 0, linear_solve_s = 0;
  std::vector<std::string> notes; // the linear solver's change of course (AMG fallback)
  std::string message;
  // The linear system's matrix, factorized, when keep_linear_factorization asked for it and
  // the system is linear and converged; null otherwise. For a linear system it is the tangent
  // at the solution; for a nonlinear one no factorized matrix is (the last is at the previous
  // iterate, or a Picard secant), hence none is handed back.
  std::shared_ptr<FactorizedMatrix> factorized;
};

// With a LinearSolver on options.linear.
NewtonReport solve_nonlinear(const NonlinearSystem& system, Eigen::VectorXd& u,
                             const NewtonOptions& options);
// With the given solver for the tangent systems (options.linear only for its tolerance and
// progress): a distributed solve passes DistributedLinearSolver and a system whose residuals
// are summed over the processes, and every process takes the same steps. A linear system
// computes its final residual from the tangent, which must then be the whole matrix (a
// distributed linear system goes through solve_distributed, which solves it directly).
NewtonReport solve_nonlinear(const NonlinearSystem& system, Eigen::VectorXd& u,
                             const NewtonOptions& options, TangentSolver& linear);

} // namespace magfem
