#include "app/optimize.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>
#include <nlopt.hpp>

#include "app/build_info.hpp"
#include "app/cli_number.hpp"
#include "core/input_error.hpp"
#include "core/output_stage.hpp"

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

} // namespace

OptimizeOptions parse_optimize_options(const std::vector<std::string>& args) {
  OptimizeOptions o;
  // The sweep and objective options are study's: collect them and let study parse them.
  std::vector<std::string> study_args;
  int senses = 0;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= args.size())
        throw InputError(cli, 0, arg, "missing value");
      return args[++i];
    };
    if (arg == "--vary")
      o.variables.push_back(parse_variable(value()));
    else if (arg == "--maximize" || arg == "--minimize") {
      o.maximize = arg == "--maximize";
      study_args.push_back("--objective");
      study_args.push_back(value());
      ++senses;
    } else if (arg == "--xtol") {
      o.xtol = parse_cli_number(arg, value());
      if (!(o.xtol > 0))
        throw InputError(cli, 0, arg, "must be positive");
    } else if (arg == "--verify-fe")
      o.verify_fe = true;
    else if (arg == "--param" || arg == "--objective" || arg == "--fe")
      throw InputError(cli, 0, arg, "not an optimize option (use --vary, --maximize/--minimize)");
    else
      study_args.push_back(arg);
  }
  if (o.variables.empty())
    throw InputError(cli, 0, "--vary", "give at least one --vary NAME=LO:HI");
  if (senses != 1)
    throw InputError(cli, 0, "--maximize", "give one --maximize or --minimize OBJECTIVE");
  for (const auto& v : o.variables) // study wants parameters; their values are ours
    study_args.push_back("--param"), study_args.push_back(v.name + "=" + std::to_string(v.lower));
  o.study = parse_study_options(study_args);
  if (o.study.out_dir.find("_study") != std::string::npos) {
    auto& dir = o.study.out_dir;
    dir.replace(dir.rfind("_study"), 6, "_optimize");
  }
  return o;
}

OptimizeResult run_optimize(const OptimizeOptions& options) {
  OptimizeResult result;
  const auto& vars = options.variables;
  const std::size_t n = vars.size();
  StudyOptions analytic = options.study;
  analytic.sweep.analytic = true;
  analytic.objectives.resize(1);
  // Fail early on names and options (the grid run does the same check).
  {
    StudyOptions check = analytic;
    for (std::size_t i = 0; i < n; ++i)
      check.parameters[i].values = {0.5 * (vars[i].lower + vars[i].upper)};
    (void)run_study(check);
  }
  auto model = [&](const std::vector<double>& x) {
    const StudyDesign d = evaluate_study_design(analytic, x);
    if (!d.ok)
      throw SolveError("optimize: the model failed at a point inside the bounds: " + d.error);
    ++result.evaluations;
    result.method = d.method;
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
  struct Context {
    Model* model;
  } context{&model};
  auto call = [](unsigned dim, const double* p, double*, void* data) -> double {
    auto* c = static_cast<Context*>(data);
    return (*c->model)(std::vector<double>(p, p + dim));
  };
  if (options.maximize)
    opt.set_max_objective(call, &context);
  else
    opt.set_min_objective(call, &context);
  opt.set_xtol_rel(options.xtol);
  opt.set_maxeval(options.max_evaluations);
  // Initial step: a quarter of each range, so that the first simplex spans the box.
  std::vector<double> step(n);
  for (std::size_t i = 0; i < n; ++i)
    step[i] = 0.25 * (upper[i] - lower[i]);
  opt.set_initial_step(step);
  double best = 0;
  const nlopt::result why = opt.optimize(x, best);
  result.optimum = x;
  result.objective = best;
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
    StudyOptions fe = analytic;
    fe.sweep.analytic = false;
    const StudyDesign d = evaluate_study_design(fe, x);
    if (!d.ok)
      throw SolveError("optimize --verify-fe: the FE check failed: " + d.error);
    result.fe_objective = d.objectives[0];
    result.fe_seconds = d.seconds;
  }
  return result;
}

int run_optimize_command(const OptimizeOptions& options) {
  const OptimizeResult r = run_optimize(options);
  const auto& vars = options.variables;
  const std::string& objective = options.study.objectives.front().name;
  std::filesystem::create_directories(options.study.out_dir);
  OutputStage stage(options.study.out_dir);
  nlohmann::ordered_json j;
  add_provenance(j);
  j["case"] = options.study.case_file;
  j["method"] = r.method;
  j["optimizer"] = "nlopt LN_COBYLA";
  j["sense"] = options.maximize ? "maximize" : "minimize";
  j["objective"] = objective;
  for (std::size_t i = 0; i < vars.size(); ++i)
    j["optimum"].push_back({{"name", vars[i].name},
                            {"value", r.optimum[i]},
                            {"lower", vars[i].lower},
                            {"upper", vars[i].upper}});
  j["analytic_value"] = r.objective;
  j["evaluations"] = r.evaluations;
  j["stop"] = r.stop;
  if (r.fe_objective) {
    j["fe_value"] = *r.fe_objective;
    j["fe_minus_analytic"] = *r.fe_objective - r.objective;
    j["fe_relative_difference"] = (*r.fe_objective - r.objective) / std::abs(r.objective);
    j["fe_seconds"] = r.fe_seconds;
  }
  stage.write_text("summary.json", j.dump(2) + "\n");
  stage.commit();

  for (std::size_t i = 0; i < vars.size(); ++i)
    std::printf("optimum  %s = %.6g (bounds %g..%g)\n", vars[i].name.c_str(), r.optimum[i],
                vars[i].lower, vars[i].upper);
  std::printf("analytic %s = %.8g (%s, %d evaluations, %s)\n", objective.c_str(), r.objective,
              r.method.c_str(), r.evaluations, r.stop.c_str());
  if (r.fe_objective)
    std::printf("FE       %s = %.8g, FE - analytic = %.4g (%.3g %%), %.0f s\n", objective.c_str(),
                *r.fe_objective, *r.fe_objective - r.objective,
                100 * (*r.fe_objective - r.objective) / std::abs(r.objective), r.fe_seconds);
  std::printf("wrote    %s/summary.json\n", options.study.out_dir.c_str());
  return 0;
}

} // namespace magfem
