#pragma once
// What the nonlinear and linear solvers did, in the same words for every dimension: the
// summary.json fields (linear_solver, preconditioner, linear_iterations, threads, ranks,
// solver_notes) and the console's solve line.
#include <string>

#include <nlohmann/json.hpp>

#include "solver/newton.hpp"

namespace magfem {

// `threads`: element-loop threads of the assembly. `ranks`: MPI processes (1: no MPI run).
void add_solver_summary(nlohmann::ordered_json& j, const NewtonReport& report, int threads,
                        int ranks = 1);

// "cg + boomeramg, 41 CG iterations" (linear), "cholmod, 6 Newton iterations" (nonlinear,
// direct) and so on, then one "note" line per solver note.
std::string describe_solver(const NewtonReport& report);

// The console's solve line, "solve    order 2, 210591 unknowns (214925 DOFs, 4334 fixed),
// cg + pmg, 20 CG iterations, residual 3.92e-11". "unknowns" is the size of the system
// solved, the word the progress lines use; DOFs (summary.json's `unknowns`) include the values
// boundary conditions fix.
std::string describe_solve_line(int order, int free_unknowns, int dofs, const NewtonReport& report);

} // namespace magfem
