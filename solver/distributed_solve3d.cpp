#include "solver/distributed_solve3d.hpp"

#include <chrono>
#include <utility>

#include "core/progress.hpp"
#include "solver/current_sensitivity3d.hpp"
#include "solver/distributed_linear_solver.hpp"
#include "solver/distributed_system3d.hpp"
#include "solver/mpi_context.hpp"

namespace magfem {
namespace {
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Assembles the one system, lets the share go (the caller's pointer was the last one unless
// it kept a copy), hands the part to PETSc and frees it, then sets the preconditioner up.
NewtonReport solve_linear(std::shared_ptr<const Assembler3D> share, const DistributedRows* rows,
                          DistributedLinearSolver& solver, const LinearSolverOptions& options,
                          Eigen::VectorXd& u) {
  NewtonReport report;
  report.linear = true;
  report.linear_solver = "cg";
  // A linear system: K phi = -r(0), r(0) the whole residual at phi = 0 (remanence, coils), K
  // this process's part of the tangent.
  auto t0 = Clock::now();
  Eigen::VectorXd r;
  double load_norm = 0;
  {
    Eigen::SparseMatrix<double> k;
    {
      const DistributedSystem3D system(*share, rows);
      system.evaluate(Eigen::VectorXd::Zero(system.n_unknowns()), r, &k, TangentKind::newton);
      load_norm = system.load_norm();
    }
    share.reset();
    report.assemble_s = seconds_since(t0);
    if (options.progress)
      options.progress->stage("preconditioner set-up: " + solver.preconditioner());
    solver.load(k);
  }
  solver.set_up();
  report.preconditioner = solver.preconditioner();
  if (options.progress)
    options.progress->stage("solve: CG + " + report.preconditioner);
  u = solver.solve(-r);
  report.linear_setup_s = solver.setup_seconds();
  report.linear_solve_s = solver.solve_seconds();
  report.solve_s = report.linear_setup_s + report.linear_solve_s;
  report.iterations = 1;
  report.linear_iterations = solver.last_iterations();
  // As for a serial linear solve: the initial relative residual (1, or 0 without sources)
  // and the final one, here the true residual PETSc computed.
  const bool sourceless = load_norm == 0;
  report.residual_history = {sourceless ? 0.0 : 1.0, solver.last_true_residual()};
  report.step_lengths = {1.0};
  report.converged = true;
  if (sourceless)
    report.message = "no sources: zero field";
  return report;
}

} // namespace

NewtonReport solve_distributed(std::shared_ptr<const Assembler3D> share, int size,
                               const NewtonOptions& options, Eigen::VectorXd& u) {
  if (Progress* progress = options.linear.progress)
    progress->stage("distributed over " + std::to_string(size) +
                    " processes: " + std::to_string(share->n_unknowns()) + " unknowns");
  const DistributedRows* rows = options.linear.distributed_rows.get();
  DistributedLinearSolver solver(options.linear, size);
  NewtonReport report;
  if (share->is_linear()) {
    report = solve_linear(std::move(share), rows, solver, options.linear, u);
  } else {
    const DistributedSystem3D system(*share, rows);
    report = solve_nonlinear(system, u, options, solver);
  }
  report.notes = solver.notes();
  return report;
}

CurrentSensitivities3D current_sensitivities_distributed(const Assembler3D& share, int size,
                                                         const Eigen::VectorXd& u, int n_coils,
                                                         const LinearSolverOptions& options) {
  CurrentSensitivities3D out;
  if (n_coils == 0)
    return out;
  const DistributedSystem3D system(share, options.distributed_rows.get());
  DistributedLinearSolver solver(options, size);
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> part; // this process's part of the tangent
  system.evaluate(u, r, &part, TangentKind::newton);
  solver.factorize(part);
  // All coils in one block solve (current_sensitivity3d.cpp).
  Eigen::MatrixXd rhs(part.rows(), n_coils);
  for (int j = 0; j < n_coils; ++j)
    rhs.col(j) = -system.current_derivative(u, j);
  const Eigen::MatrixXd du = solver.solve_many(rhs);
  // The whole K du: each process's part's product, summed as the residuals are.
  const Eigen::MatrixXd k_du = system.multiply_summed(part, du);
  out.correction = variational_correction(du, rhs, k_du);
  for (int j = 0; j < n_coils; ++j)
    out.du.push_back(du.col(j));
  return out;
}

} // namespace magfem
