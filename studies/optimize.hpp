#pragma once
// `magfem optimize CASE.yaml --vary NAME=LO:HI [--vary ..] --maximize|--minimize OBJECTIVE
//  --rotate GROUP --axis A [--angles LIST] [--constraint "EXPR <= EXPR" ..] [--xtol T]
//  [--verify-fe [--accuracy PCT [--max-passes N] [--max-unknowns N]]] [--out DIR]`:
// a bounded derivative-free optimizer (NLopt's COBYLA) over case-file parameters with the
// analytic sweep as the model (studies/study.hpp objectives), then, with --verify-fe, one FE
// sweep at the optimum that reports the FE objective beside the analytic one. A constraint
// is an inequality between two expressions of the varied parameters (the case file's
// expression syntax, in the parameters' own units), e.g. "R_out - R_in >= 10".
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "studies/study.hpp"

namespace magfem {

struct OptimizeVariable {
  std::string name;
  double lower = 0, upper = 0; // in the parameter's own unit
};

struct OptimizeConstraint {
  std::string text; // as given, for messages and summary.json
  std::string lhs, rhs;
  bool at_most = true; // lhs <= rhs; false: lhs >= rhs
};

struct OptimizeOptions {
  StudyOptions study; // case file, objective (the first), sweep; its parameters are the vars
  std::vector<OptimizeVariable> variables;
  std::vector<OptimizeConstraint> constraints;
  bool maximize = true;
  double xtol = 1e-4; // relative tolerance on the variables (NLopt xtol_rel)
  int max_evaluations = 500;
  bool verify_fe = false;
};

// One model evaluation the optimizer asked for, in the order asked.
struct OptimizeEvaluation {
  std::vector<double> values; // parallel to variables
  double objective = 0;       // analytic
};

struct OptimizeResult {
  std::vector<OptimizeEvaluation> history;
  std::vector<double> optimum;    // parallel to variables
  std::vector<double> violations; // per constraint at the optimum: > 0 violated, 0 active
  double objective = 0;           // analytic, at the optimum
  int evaluations = 0;
  std::string method; // of the analytic sweeps
  std::string stop;   // NLopt's reason
  std::optional<double> fe_objective;
  // The FE check's estimated error (N m; NaN: none) and its adaptive refinement (with the
  // case's adapt: or --accuracy).
  double fe_error = std::numeric_limits<double>::quiet_NaN();
  StudyDesignAdapt fe_adapt;
  double fe_seconds = 0;
};

// Parses the arguments after `optimize`; throws InputError naming the option.
OptimizeOptions parse_optimize_options(const std::vector<std::string>& args);
// Its options (for `magfem help optimize` and the completion).
std::vector<OptionInfo> optimize_option_infos();

// Runs the optimizer (and the FE check if asked). Throws InputError for bad options, and
// SolveError if the model fails at a point the optimizer asks for or no point satisfies the
// constraints. on_evaluation (may be empty) hears every evaluation as it ends; a stop asked
// through options.study.sweep.stop ends the run before the next one (SolveError).
OptimizeResult
run_optimize(const OptimizeOptions& options,
             const std::function<void(const OptimizeEvaluation&)>& on_evaluation = {});

// summary.json but the provenance: case, method, optimizer, sense, objective, optimum,
// constraints, analytic_value, evaluations, stop, and the FE check's entries (fe_value,
// fe_error_estimate, fe_adapt, warnings). Also
// magfem.optimize's `summary` in Python.
nlohmann::ordered_json optimize_summary(const OptimizeOptions& options, const OptimizeResult& r);

// The warning of an FE check that stopped at a limit before its accuracy ("" otherwise).
std::string optimize_warning(const OptimizeResult& r);

// history.csv: evaluation (1-based), the variables, the objective (its study column name), one
// row per evaluation in the order the optimizer asked.
std::string optimize_history_csv(const OptimizeOptions& options, const OptimizeResult& r);

// summary.json (with the provenance) and history.csv into dir, all or nothing; the command's
// and Python's writer. Returns the file names.
std::vector<std::string> write_optimize_outputs(const OptimizeOptions& options,
                                                const OptimizeResult& r, const std::string& dir);

// The command: prints the optimum, writes its outputs (all or nothing); exit code.
int run_optimize_command(const OptimizeOptions& options);

} // namespace magfem
