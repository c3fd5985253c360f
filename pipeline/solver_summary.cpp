#include "pipeline/solver_summary.hpp"

#include <cstdio>

namespace magfem {

void add_solver_summary(nlohmann::ordered_json& j, const NewtonReport& report, int threads,
                        int ranks) {
  j["linear_solver"] = report.linear_solver;
  j["preconditioner"] = report.preconditioner;
  j["linear_iterations"] = report.linear_iterations;
  j["threads"] = threads;
  j["ranks"] = ranks;
  j["solver_notes"] = report.notes;
}

std::string describe_solver(const NewtonReport& report) {
  const bool linear = report.linear;
  const bool krylov = report.linear_solver == "cg";
  std::string s = report.linear_solver;
  if (krylov)
    s += " + " + report.preconditioner;
  if (!linear)
    s += ", " + std::to_string(report.iterations) + " Newton iteration(s)";
  if (krylov)
    s += ", " + std::to_string(report.linear_iterations) + " CG iterations";
  else if (linear)
    s += ", " + std::to_string(report.iterations) + " iteration(s)";
  return s;
}

std::string describe_solve_line(int order, int free_unknowns, int dofs,
                                const NewtonReport& report) {
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "solve    order %d, %d unknowns (%d DOFs, %d fixed), %s, residual %.2e\n", order,
                free_unknowns, dofs, dofs - free_unknowns, describe_solver(report).c_str(),
                report.residual_history.back());
  return buf;
}

} // namespace magfem
