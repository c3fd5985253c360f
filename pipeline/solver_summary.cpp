#include "pipeline/solver_summary.hpp"

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

} // namespace magfem
