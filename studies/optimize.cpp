#include "studies/optimize.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>
#include <nlopt.hpp>

#include "casefile/cli_number.hpp"
#include "casefile/parameter_expression.hpp"
#include "core/input_error.hpp"
#include "core/output_stage.hpp"
#include "pipeline/build_info.hpp"

namespace magfem {
namespace {

const std::string cli = "<command line>";

OptimizeVariable parse_variable(const std::string& text) {
  const auto eq = text.find('='), colon = text.find(':');
  if (eq == std::string::npos || eq == 0 || colon == std::string::npos || colon < eq)
    throw InputError(cli, 0, "--vary", "expected NAME=LO:HI, got '" + text + "'");
  OptimizeVariable v{text.substr(0, eq), 0, 0};
  v.lower = parse_cli_number("--vary", text.substr(eq + 1, colon - eq - 1));
  v.upper = parse_cli_number("--vary", text.substr(colon + 1));
  if (!(v.lower < v.upper))
    throw InputError(cli, 0, "--vary", "expected LO < HI in '" + text + "'");
  return v;
}

OptimizeConstraint parse_constraint(const std::string& text) {
  const auto le = text.find("<="), ge = text.find(">=");
  if ((le == std::string::npos) == (ge == std::string::npos) ||
      text.find('<', (le == std::string::npos ? ge : le) + 2) != std::string::npos ||
      text.find('>', (le == std::string::npos ? ge : le) + 2) != std::string::npos)
    throw InputError(cli, 0, "--constraint",
                     "expected one inequality EXPR <= EXPR or EXPR >= EXPR, got '" + text + "'");
  const auto at = le == std::string::npos ? ge : le;
  return {text, text.substr(0, at), text.substr(at + 2), le != std::string::npos};
}

// The constraint as g(x) <= 0, for NLopt.
double constraint_value(const OptimizeConstraint& c, const std::vector<OptimizeVariable>& vars,
                        const double* x) {
  auto lookup = [&](const std::string& name) -> double {
    for (std::size_t i = 0; i < vars.size(); ++i)
      if (vars[i].name == name)
        return x[i];
    throw ExpressionError(ExpressionError::Kind::undefined_name,
                          "'" + name + "' is not a --vary parameter", name);
  };
  const double lhs = evaluate_expression(c.lhs, lookup), rhs = evaluate_expression(c.rhs, lookup);
  return c.at_most ? lhs - rhs : rhs - lhs;
}

// Names and syntax are checked once, at the centre of the box, before any model run.
void check_constraints(const OptimizeOptions& o) {
  std::vector<double> centre;
  for (const auto& v : o.variables)
    centre.push_back(0.5 * (v.lower + v.upper));
  for (const auto& c : o.constraints) {
    try {
      (void)constraint_value(c, o.variables, centre.data());
    } catch (const ExpressionError& e) {
      throw InputError(cli, 0, "--constraint", "'" + c.text + "': " + e.what());
    }
  }
}

} // namespace

namespace {

// The options as given: optimize's own, and study's sweep options passed on to study.
struct OptimizeArgs {
  OptimizeOptions options;
  std::vector<std::string> study_args;
  int senses = 0; // --maximize / --minimize given
};

// study's options that optimize passes on to it: the sweep whose torque the objective takes
// and the FE check's mesh. The others are refused by name, not ignored: its variables are
// --vary, its objective --maximize/--minimize, it always optimizes the analytic model, one
// evaluation at a time, without a checkpoint.
bool passed_to_study(const std::string& name) {
  for (const char* n : {"--rotate", "--axis", "--angles", "--mesh-scale", "--order", "--accuracy",
                        "--max-passes", "--max-unknowns", "--quiet", "--out"})
    if (name == n)
      return true;
  return false;
}

bool refused_study_option(const std::string& name) {
  if (passed_to_study(name))
    return false;
  for (const OptionInfo& info : study_option_infos())
    if (info.name == name)
      return true;
  return false;
}

OptionTable<OptimizeArgs> make_optimize_table() {
  using A = OptimizeArgs;
  using S = const std::string&;
  OptionTable<A> table("optimize");
  table.value("--vary", "NAME=LO:HI",
              [](A& a, S, S v) { a.options.variables.push_back(parse_variable(v)); });
  for (const char* sense : {"--maximize", "--minimize"})
    table.value(sense, "OBJECTIVE", [](A& a, S opt, S v) {
      a.options.maximize = opt == "--maximize";
      a.study_args.insert(a.study_args.end(), {"--objective", v});
      ++a.senses;
    });
  table.value("--xtol", "X", [](A& a, S opt, S v) {
    a.options.xtol = parse_cli_number(opt, v);
    if (!(a.options.xtol > 0))
      throw InputError(cli, 0, opt, "must be positive");
  });
  table.value("--constraint", "EXPR",
              [](A& a, S, S v) { a.options.constraints.push_back(parse_constraint(v)); });
  table.flag("--verify-fe", [](A& a, S, S) { a.options.verify_fe = true; });
  for (const OptionInfo& info : study_option_infos()) {
    if (passed_to_study(info.name))
      table.value(info.name, info.value, [](A& a, S opt, S v) {
        a.study_args.push_back(opt);
        if (!v.empty())
          a.study_args.push_back(v);
      });
    else
      table.value(info.name, "", [](A&, S opt, S) {
        throw InputError(cli, 0, opt,
                         "not an optimize option (optimize takes --vary, --maximize/--minimize, "
                         "and optimizes the analytic model)");
      });
  }
  return table;
}

const OptionTable<OptimizeArgs>& optimize_option_table() {
  static const OptionTable<OptimizeArgs> table = make_optimize_table();
  return table;
}

} // namespace

std::vector<OptionInfo> optimize_option_infos() {
  std::vector<OptionInfo> out;
  for (const OptionInfo& info : optimize_option_table().options())
    if (!refused_study_option(info.name))
      out.push_back(info);
  return out;
}

OptimizeOptions parse_optimize_options(const std::vector<std::string>& args) {
  OptimizeArgs parsed;
  const std::vector<std::string> positional = optimize_option_table().parse(args, parsed);
  OptimizeOptions& o = parsed.options;
  std::vector<std::string>& study_args = parsed.study_args;
  study_args.insert(study_args.end(), positional.begin(), positional.end());
  const int senses = parsed.senses;
  if (o.variables.empty())
    throw InputError(cli, 0, "--vary", "give at least one --vary NAME=LO:HI");
  if (senses != 1)
    throw InputError(cli, 0, "--maximize", "give one --maximize or --minimize OBJECTIVE");
  check_constraints(o);
  // The adaptive options refine the FE check's mesh (study takes them with --fe; the model
  // stays analytic, run_optimize).
  for (const char* adaptive : {"--accuracy", "--max-passes", "--max-unknowns"})
    if (std::find(study_args.begin(), study_args.end(), adaptive) != study_args.end()) {
      if (!o.verify_fe)
        throw InputError(cli, 0, adaptive, "refines the FE check's mesh: give --verify-fe");
      if (std::find(study_args.begin(), study_args.end(), "--fe") == study_args.end())
        study_args.push_back("--fe");
    }
  for (const auto& v : o.variables) // study wants parameters; their values are ours
    study_args.push_back("--param"), study_args.push_back(v.name + "=" + std::to_string(v.lower));
  o.study = parse_study_options(study_args);
  if (o.study.out_dir.find("_study") != std::string::npos) {
    auto& dir = o.study.out_dir;
    dir.replace(dir.rfind("_study"), 6, "_optimize");
  }
  return o;
}

OptimizeResult run_optimize(const OptimizeOptions& options,
                            const std::function<void(const OptimizeEvaluation&)>& on_evaluation) {
  OptimizeResult result;
  const auto& vars = options.variables;
  const std::size_t n = vars.size();
  StudyOptions analytic = options.study;
  analytic.sweep.analytic = true;
  analytic.objectives.resize(1);
  // Fail early on names and options (the grid run does the same check).
  {
    StudyOptions check = analytic;
    check.quiet = true;
    for (std::size_t i = 0; i < n; ++i)
      check.parameters[i].values = {0.5 * (vars[i].lower + vars[i].upper)};
    (void)run_study(check);
  }
  auto model = [&](const std::vector<double>& x) {
    if (options.study.sweep.stop.stop_requested())
      throw SolveError("optimize: stopped after " + std::to_string(result.evaluations) +
                       " evaluations");
    const StudyDesign d = evaluate_study_design(analytic, x);
    if (!d.ok)
      throw SolveError("optimize: the model failed at a point inside the bounds: " + d.error);
    ++result.evaluations;
    result.method = d.method;
    result.history.push_back({x, d.objectives[0]});
    if (on_evaluation)
      on_evaluation(result.history.back());
    return d.objectives[0];
  };
  using Model = decltype(model);
  // COBYLA: derivative-free, honours bounds, works in one dimension (BOBYQA needs two).
  nlopt::opt opt(nlopt::LN_COBYLA, static_cast<unsigned>(n));
  std::vector<double> lower(n), upper(n), x(n);
  for (std::size_t i = 0; i < n; ++i) {
    lower[i] = vars[i].lower, upper[i] = vars[i].upper;
    x[i] = 0.5 * (lower[i] + upper[i]);
  }
  opt.set_lower_bounds(lower);
  opt.set_upper_bounds(upper);
  // NLopt turns an exception in a callback into a bare "nlopt failure": keep the model's own
  // message and stop the optimizer with it.
  struct Context {
    Model* model;
    std::string error;
  } context{&model, {}};
  auto call = [](unsigned dim, const double* p, double*, void* data) -> double {
    auto* c = static_cast<Context*>(data);
    try {
      return (*c->model)(std::vector<double>(p, p + dim));
    } catch (const std::exception& e) {
      c->error = e.what();
      throw nlopt::forced_stop();
    }
  };
  if (options.maximize)
    opt.set_max_objective(call, &context);
  else
    opt.set_min_objective(call, &context);
  struct ConstraintContext {
    const OptimizeConstraint* constraint;
    const std::vector<OptimizeVariable>* variables;
  };
  std::vector<ConstraintContext> constraint_contexts;
  for (const auto& c : options.constraints)
    constraint_contexts.push_back({&c, &vars});
  auto constraint = [](unsigned, const double* p, double*, void* data) -> double {
    const auto* c = static_cast<const ConstraintContext*>(data);
    return constraint_value(*c->constraint, *c->variables, p);
  };
  for (auto& c : constraint_contexts)
    opt.add_inequality_constraint(constraint, &c, 0.0);
  opt.set_xtol_rel(options.xtol);
  opt.set_maxeval(options.max_evaluations);
  // Initial step: a quarter of each range, so that the first simplex spans the box.
  std::vector<double> step(n);
  for (std::size_t i = 0; i < n; ++i)
    step[i] = 0.25 * (upper[i] - lower[i]);
  opt.set_initial_step(step);
  double best = 0;
  nlopt::result why{};
  try {
    why = opt.optimize(x, best);
  } catch (const nlopt::forced_stop&) {
    throw SolveError(context.error);
  }
  result.optimum = x;
  result.objective = best;
  // COBYLA ends on a point it judges feasible; one that is not (an empty feasible set, or a
  // stop on the evaluation limit) must not be reported as the constrained optimum. The slack
  // is round-off of the variables' scale.
  double scale = 0;
  for (const auto& v : vars)
    scale = std::max({scale, std::abs(v.lower), std::abs(v.upper)});
  for (const auto& c : options.constraints) {
    result.violations.push_back(constraint_value(c, vars, x.data()));
    if (result.violations.back() > 1e-8 * scale)
      throw SolveError("optimize: no point inside the bounds satisfies --constraint '" + c.text +
                       "' (it is violated by " + std::to_string(result.violations.back()) +
                       " at the best point found)");
  }
  switch (why) {
  case nlopt::XTOL_REACHED:
    result.stop = "xtol reached";
    break;
  case nlopt::FTOL_REACHED:
    result.stop = "ftol reached";
    break;
  case nlopt::MAXEVAL_REACHED:
    result.stop = "maximum evaluations reached";
    break;
  default:
    result.stop = "nlopt code " + std::to_string(static_cast<int>(why));
  }
  if (options.verify_fe) {
    if (!options.study.quiet)
      std::fprintf(stderr, "optimize: %d analytic evaluations, %s; FE check at the optimum...\n",
                   result.evaluations, result.stop.c_str());
    StudyOptions fe = analytic;
    fe.sweep.analytic = false;
    const StudyDesign d = evaluate_study_design(fe, x);
    if (!d.ok)
      throw SolveError("optimize --verify-fe: the FE check failed: " + d.error);
    result.fe_objective = d.objectives[0];
    result.fe_error = d.objective_errors[0];
    result.fe_adapt = d.adapt;
    result.fe_seconds = d.seconds;
  }
  return result;
}

nlohmann::ordered_json optimize_summary(const OptimizeOptions& options, const OptimizeResult& r) {
  const auto& vars = options.variables;
  nlohmann::ordered_json j;
  j["case"] = options.study.case_file;
  j["method"] = r.method;
  j["optimizer"] = "nlopt LN_COBYLA";
  j["sense"] = options.maximize ? "maximize" : "minimize";
  j["objective"] = options.study.objectives.front().name;
  for (std::size_t i = 0; i < vars.size(); ++i)
    j["optimum"].push_back({{"name", vars[i].name},
                            {"value", r.optimum[i]},
                            {"lower", vars[i].lower},
                            {"upper", vars[i].upper}});
  for (std::size_t i = 0; i < options.constraints.size(); ++i)
    j["constraints"].push_back(
        {{"constraint", options.constraints[i].text}, {"slack", 0.0 - r.violations[i]}});
  j["analytic_value"] = r.objective;
  j["evaluations"] = r.evaluations;
  j["stop"] = r.stop;
  if (r.fe_objective) {
    j["fe_value"] = *r.fe_objective;
    j["fe_minus_analytic"] = *r.fe_objective - r.objective;
    j["fe_relative_difference"] = (*r.fe_objective - r.objective) / std::abs(r.objective);
    if (!std::isnan(r.fe_error))
      j["fe_error_estimate"] = r.fe_error;
    if (r.fe_adapt.passes)
      j["fe_adapt"] = {{"converged", r.fe_adapt.converged},
                       {"passes", r.fe_adapt.passes},
                       {"unknowns", r.fe_adapt.unknowns},
                       {"stopped_deg", r.fe_adapt.stopped_deg}};
    if (const auto w = optimize_warning(r); !w.empty())
      j["warnings"] = {w};
    j["fe_seconds"] = r.fe_seconds;
  }
  return j;
}

std::string optimize_warning(const OptimizeResult& r) {
  if (!r.fe_adapt.passes || r.fe_adapt.converged)
    return "";
  std::string at;
  char deg[32];
  for (double a : r.fe_adapt.stopped_deg)
    std::snprintf(deg, sizeof deg, " %g", a), at += deg;
  return "the FE check's adaptive refinement stopped at a limit before its accuracy at" + at +
         " deg (fe_error_estimate is the estimate reached)";
}

std::string optimize_history_csv(const OptimizeOptions& options, const OptimizeResult& r) {
  std::string out = "evaluation";
  for (const auto& v : options.variables)
    out += "," + v.name;
  out += "," + options.study.objectives.front().name + "\n";
  char buf[64];
  for (std::size_t k = 0; k < r.history.size(); ++k) {
    out += std::to_string(k + 1);
    for (double x : r.history[k].values) {
      std::snprintf(buf, sizeof buf, ",%.10g", x);
      out += buf;
    }
    std::snprintf(buf, sizeof buf, ",%.10g\n", r.history[k].objective);
    out += buf;
  }
  return out;
}

std::vector<std::string> write_optimize_outputs(const OptimizeOptions& options,
                                                const OptimizeResult& r, const std::string& dir) {
  std::filesystem::create_directories(dir);
  OutputStage stage(dir);
  nlohmann::ordered_json j;
  add_provenance(j);
  j.update(optimize_summary(options, r));
  stage.write_text("summary.json", j.dump(2) + "\n");
  stage.write_text("history.csv", optimize_history_csv(options, r));
  stage.commit();
  return {"summary.json", "history.csv"};
}

int run_optimize_command(const OptimizeOptions& options) {
  const OptimizeResult r = run_optimize(options);
  const auto& vars = options.variables;
  const std::string& objective = options.study.objectives.front().name;
  const auto written = write_optimize_outputs(options, r, options.study.out_dir);

  for (std::size_t i = 0; i < vars.size(); ++i)
    std::printf("optimum  %s = %.6g (bounds %g..%g)\n", vars[i].name.c_str(), r.optimum[i],
                vars[i].lower, vars[i].upper);
  std::printf("analytic %s = %.8g (%s, %d evaluations, %s)\n", objective.c_str(), r.objective,
              r.method.c_str(), r.evaluations, r.stop.c_str());
  for (std::size_t i = 0; i < options.constraints.size(); ++i)
    std::printf("subject  %s: slack %.4g (0: the constraint is active)\n",
                options.constraints[i].text.c_str(), 0.0 - r.violations[i]);
  if (r.fe_objective)
    std::printf("FE       %s = %.8g +- %.2g (estimated), FE - analytic = %.4g (%.3g %%), %.0f s\n",
                objective.c_str(), *r.fe_objective, r.fe_error, *r.fe_objective - r.objective,
                100 * (*r.fe_objective - r.objective) / std::abs(r.objective), r.fe_seconds);
  if (const auto w = optimize_warning(r); !w.empty())
    std::fprintf(stderr, "magfem: warning: %s\n", w.c_str());
  std::printf("wrote    %s/%s, %s\n", options.study.out_dir.c_str(), written[0].c_str(),
              written[1].c_str());
  return 0;
}

} // namespace magfem
