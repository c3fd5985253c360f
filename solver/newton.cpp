#include "solver/newton.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/progress.hpp"

namespace magfem {
namespace {
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Smallest line-search factor; below it the full step is taken regardless, because a
// tangent that is this poor means the problem is badly posed and the iteration cap reports it.
constexpr double min_step = 1.0 / 64;
constexpr double armijo = 1e-4;

// Krylov tolerance of the start problem's solve (NewtonOptions::linear_start) when the steps
// are inexact (forcing_max > 0). Why this tight, when a Newton step may stop at forcing_max:
// in coil-driven total-potential iron u must cancel the coil's potential Phi_s, whose field
// there is far above the iron's working H (TEAM 20's pole: ~30 kA/m against a few hundred),
// and a loose solve leaves enough of it uncancelled to throw the iron into saturation, where
// Newton restarts from the state the linear start exists to avoid. TEAM 20 at 3000 AT, order 1,
// mesh scale 2 (37k unknowns, CG + incomplete Cholesky): start solved to 0.1 (= forcing_max, as
// before), start residual 0.30, then 22 iterations, steps down to 0.085, 911 CG iterations
// (with every step to 0.01 instead of 0.1: still 22); to 1e-2: 9 iterations, 743 CG; to 1e-4:
// 0.030, then 8 iterations, all full steps, 676 CG. The coil-driven rod: 12 -> 9.
constexpr double start_cg_tolerance = 1e-4;

// Line search for the secant (Picard) direction. The residual is the gradient of a convex
// energy functional, so along u + a du the energy's slope is g(a) = r(u + a du) . du, negative
// at a = 0 (the secant matrix is positive definite). The step goes to the root of g in (0, 1]
// by regula falsi (Illinois), a few residual evaluations; without it the secant iteration
// overshoots in saturation and oscillates (measured: no convergence in 400 steps on the
// saturated C-core). Returns the step; u_try and r_try hold the point taken.
double energy_line_search(const NonlinearSystem& system, const Eigen::VectorXd& u,
                          const Eigen::VectorXd& du, const Eigen::VectorXd& r, TangentKind kind,
                          Eigen::VectorXd& u_try, Eigen::VectorXd& r_try) {
  auto slope_at = [&](double a) {
    u_try = u + a * du;
    system.evaluate(u_try, r_try, nullptr, kind);
    return r_try.dot(du);
  };
  double a_lo = 0, g_lo = r.dot(du);
  double a_hi = 1, g_hi = slope_at(1.0);
  if (!(g_lo < 0) || g_hi <= 0)
    return 1.0; // full step already at or before the minimum
  constexpr int max_evaluations = 8;
  constexpr double slope_reduction = 0.1; // |g(a)| below this fraction of |g(0)| is enough
  const double g0 = -g_lo;
  int side = 0;
  double a = 1;
  for (int i = 0; i < max_evaluations; ++i) {
    a = (a_lo * g_hi - a_hi * g_lo) / (g_hi - g_lo);
    const double g = slope_at(a);
    if (std::abs(g) <= slope_reduction * g0)
      return a;
    if (g < 0) {
      a_lo = a, g_lo = g;
      if (side == -1)
        g_hi *= 0.5;
      side = -1;
    } else {
      a_hi = a, g_hi = g;
      if (side == 1)
        g_lo *= 0.5;
      side = 1;
    }
  }
  return a; // u_try, r_try belong to the last evaluation
}

// Newton's iteration with `linear` for the tangent systems, the tangent assembled into k.
NewtonReport newton_iterations(const NonlinearSystem& system, Eigen::VectorXd& u,
                               const NewtonOptions& options, TangentSolver& linear,
                               Eigen::SparseMatrix<double>& k) {
  NewtonReport report;
  report.linear = system.is_linear();
  if (u.size() != system.n_unknowns())
    u = Eigen::VectorXd::Zero(system.n_unknowns());
  Eigen::VectorXd r;
  auto t0 = Clock::now();
  system.evaluate(u, r, &k, options.method);
  report.assemble_s += seconds_since(t0);
  // After the first evaluation: at u = 0 (the usual start) it is the load's residual, which
  // an assembler may keep as its load norm instead of evaluating it again (Assembler3D).
  const double scale = system.load_norm() > 0 ? system.load_norm() : 1.0;
  double r_norm = r.norm();
  report.residual_history.push_back(r_norm / scale);
  if (system.load_norm() == 0) { // no sources: the zero field is the answer
    report.converged = true;
    report.message = "no sources: zero field";
    report.linear_solver = "none";
    report.preconditioner = "none";
    return report;
  }

  const TangentKind kind = system.is_linear() ? TangentKind::newton : options.method;
  // Iteration 1 may be the start problem's solve instead of a Newton step.
  int first = 1;
  if (options.linear_start && !system.is_linear() && u.isZero(0)) {
    Eigen::VectorXd r0;
    Eigen::SparseMatrix<double> k0;
    if (system.start_problem(r0, k0)) {
      t0 = Clock::now();
      // Only a starting point, but not a loose one (start_cg_tolerance); the loop resets the
      // tolerance.
      if (options.forcing_max > 0)
        linear.set_cg_tolerance(std::max(options.linear.cg_tolerance, start_cg_tolerance));
      linear.factorize(k0);
      u = linear.solve(-r0);
      if (options.forcing_max > 0)
        linear.set_cg_tolerance(options.linear.cg_tolerance);
      report.solve_s += seconds_since(t0);
      report.linear_iterations += linear.last_iterations();
      t0 = Clock::now();
      system.evaluate(u, r, &k, kind);
      report.assemble_s += seconds_since(t0);
      r_norm = r.norm();
      report.residual_history.push_back(r_norm / scale);
      report.step_lengths.push_back(1.0);
      report.iterations = first++;
      if (Progress* p = options.linear.progress) {
        char line[120];
        std::snprintf(line, sizeof line, "Newton start (linear solve): relative residual %.3e",
                      r_norm / scale);
        p->note(line);
      }
    }
  }
  const double tight = options.linear.cg_tolerance;
  double forcing = options.forcing_max, previous_r_norm = r_norm;
  for (int it = first; it <= options.max_iterations; ++it) {
    t0 = Clock::now();
    if (!system.is_linear() && options.forcing_max > 0) {
      if (it > 1) { // Eisenstat-Walker choice 2 (gamma 0.9, alpha 2) with its safeguard
        const double ratio = r_norm / previous_r_norm;
        const double safeguard = 0.9 * forcing * forcing;
        forcing = std::max(0.9 * ratio * ratio, safeguard > 0.1 ? safeguard : 0.0);
      }
      // Never tighter than needed to meet Newton's own residual tolerance next step.
      forcing = std::min(forcing, options.forcing_max);
      const double needed = 0.5 * options.residual_tol * scale / std::max(r_norm, 1e-300);
      // The loosest of the two that still meets the target: a tolerance below `needed`
      // would solve more accurately than the next residual test can tell.
      linear.set_cg_tolerance(
          std::max(tight, std::min(options.forcing_max, std::max(forcing, needed))));
    }
    previous_r_norm = r_norm;
    linear.factorize(k);
    const Eigen::VectorXd du = linear.solve(-r);
    report.solve_s += seconds_since(t0);
    report.linear_iterations += linear.last_iterations();
    report.iterations = it;

    if (system.is_linear()) {
      // One exact step; the final residual follows from the same matrix.
      u += du;
      const Eigen::VectorXd r_new = r + k.selfadjointView<Eigen::Lower>() * du;
      report.residual_history.push_back(r_new.norm() / scale);
      report.step_lengths.push_back(1.0);
      report.converged = true;
      break;
    }

    double alpha = 1.0;
    Eigen::VectorXd u_try, r_try;
    t0 = Clock::now();
    if (kind == TangentKind::picard && options.line_search) {
      alpha = energy_line_search(system, u, du, r, kind, u_try, r_try);
    } else {
      u_try = u + du;
      system.evaluate(u_try, r_try, nullptr, kind);
      const bool lowers_residual = r_try.norm() <= (1 - armijo) * r_norm;
      if (options.line_search && !lowers_residual && r.dot(du) < 0)
        // A Newton step that raises the residual goes to the energy's minimum along it (it
        // descends the energy where the tangent is positive definite: a monotone B-H curve).
        // Halving until the residual norm decreased stalled Newton on the foot of the curve,
        // where a step that lowers the energy raises the residual in a few elements (TEAM 20
        // at 1000 AT, order 2, 305k unknowns: steps 0.5, 0.125, ..., still 9.2e-5 after 40
        // iterations; with this search 27 iterations to 9e-14, quadratic over the last four).
        alpha = energy_line_search(system, u, du, r, kind, u_try, r_try);
      else if (options.line_search && !lowers_residual)
        for (alpha = 0.5;; alpha *= 0.5) { // no descent direction: backtrack on the residual
          u_try = u + alpha * du;
          system.evaluate(u_try, r_try, nullptr, kind);
          if (r_try.norm() <= (1 - armijo * alpha) * r_norm || alpha <= min_step)
            break;
        }
    }
    report.assemble_s += seconds_since(t0);
    u = u_try;
    r_norm = r_try.norm();
    report.residual_history.push_back(r_norm / scale);
    report.step_lengths.push_back(alpha);

    const double update =
        alpha * du.norm() / std::max(u.norm(), std::numeric_limits<double>::min());
    if (Progress* p = options.linear.progress) {
      char line[120];
      std::snprintf(line, sizeof line, "Newton iteration %d: relative residual %.3e, step %.3g", it,
                    r_norm / scale, alpha);
      p->note(line);
    }
    if (!std::isfinite(r_norm)) {
      report.message = "the residual became non-finite";
      break;
    }
    if (r_norm / scale <= options.residual_tol && update <= options.update_tol) {
      report.converged = true;
      break;
    }
    t0 = Clock::now();
    system.evaluate(u, r, &k, kind);
    report.assemble_s += seconds_since(t0);
  }
  report.linear_solver = linear.name();
  report.preconditioner = linear.preconditioner();
  report.linear_setup_s = linear.setup_seconds();
  report.linear_solve_s = linear.solve_seconds();
  report.notes = linear.notes();
  if (!report.converged && report.message.empty())
    report.message = "no convergence in " + std::to_string(options.max_iterations) +
                     " iterations (relative residual " +
                     std::to_string(report.residual_history.back()) + ")";
  return report;
}

} // namespace

NewtonReport solve_nonlinear(const NonlinearSystem& system, Eigen::VectorXd& u,
                             const NewtonOptions& options) {
  // The matrix and its solver live together so that a linear system's can be handed back.
  const auto factorized = std::make_shared<FactorizedMatrix>(options.linear);
  NewtonReport report =
      newton_iterations(system, u, options, factorized->solver, factorized->lower);
  if (options.keep_linear_factorization && system.is_linear() && report.converged)
    report.factorized = factorized;
  return report;
}

NewtonReport solve_nonlinear(const NonlinearSystem& system, Eigen::VectorXd& u,
                             const NewtonOptions& options, TangentSolver& linear) {
  Eigen::SparseMatrix<double> k;
  return newton_iterations(system, u, options, linear, k);
}

} // namespace magfem
