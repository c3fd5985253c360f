#include "studies/study.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <optional>

#include <nlohmann/json.hpp>

#include "casefile/cli_number.hpp"
#include "core/input_error.hpp"
#include "core/output_stage.hpp"
#include "pipeline/adapt_loop.hpp"
#include "pipeline/build_info.hpp"
#include "pipeline/run_checkpoint.hpp"
#include "studies/position_runner.hpp"
#include "studies/study_plot.hpp"

namespace magfem {
namespace {

const std::string cli = "<command line>";

// NAME=START:STEP:END (END included within round-off) or NAME=A,B,C.
StudyParameter parse_parameter(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError(cli, 0, "--param",
                     "expected NAME=START:STEP:END or NAME=A,B,C, got '" + text + "'");
  StudyParameter p{text.substr(0, eq), {}};
  const std::string list = text.substr(eq + 1);
  std::vector<double> v;
  const char sep = list.find(':') != std::string::npos ? ':' : ',';
  for (std::size_t start = 0;;) {
    const auto end = list.find(sep, start);
    v.push_back(parse_cli_number("--param", list.substr(start, end - start)));
    if (end == std::string::npos)
      break;
    start = end + 1;
  }
  if (sep == ',') {
    p.values = v;
    return p;
  }
  if (v.size() != 3 || !(v[1] > 0) || v[2] < v[0])
    throw InputError(cli, 0, "--param",
                     "expected " + p.name + "=START:STEP:END with STEP > 0 and END >= START");
  const int n = static_cast<int>(std::floor((v[2] - v[0]) / v[1] + 1e-9));
  for (int i = 0; i <= n; ++i)
    p.values.push_back(v[0] + i * v[1]);
  return p;
}

} // namespace

StudyObjective parse_study_objective(const std::string& text) {
  StudyObjective o;
  if (text == "peak_torque") {
    o.name = "peak_torque_Nm";
    return o;
  }
  if (text.rfind("torque_at:", 0) == 0) {
    o.kind = StudyObjective::Kind::torque_at;
    o.angle_deg = parse_cli_number("--objective", text.substr(10));
    char name[64];
    std::snprintf(name, sizeof name, "torque_at_%gdeg_Nm", o.angle_deg);
    o.name = name;
    return o;
  }
  throw InputError(cli, 0, "--objective",
                   "unknown objective '" + text + "' (peak_torque, torque_at:DEG)");
}

namespace {

// The angles one design needs: --angles for peak_torque, plus every torque_at angle.
std::vector<double> design_angles(const StudyOptions& o) {
  std::vector<double> angles;
  for (const auto& obj : o.objectives)
    if (obj.kind == StudyObjective::Kind::peak_torque)
      angles = o.sweep.angles_deg;
  for (const auto& obj : o.objectives)
    if (obj.kind == StudyObjective::Kind::torque_at)
      angles.push_back(obj.angle_deg);
  return angles;
}

// A position's estimated torque error, N m: the adaptive loop's estimate for the torque it
// refined (a relative error of |T|, which bounds the error of any component), else the last
// mesh's own (the stress sphere's); NaN if it has neither.
double position_torque_error(const SweepRow& r) {
  if (const double adapted = position_adapt_error(r.adapt, r.torque.norm()); !std::isnan(adapted))
    return adapted;
  return r.torque_bound > 0 ? r.torque_bound : std::numeric_limits<double>::quiet_NaN();
}

// The largest of two errors, NaN (no estimate) when either is: a largest error over
// positions of which one has no estimate is not known.
double largest_known_error(double a, double b) {
  return std::isnan(a) || std::isnan(b) ? std::numeric_limits<double>::quiet_NaN() : std::max(a, b);
}

// The adaptive record of a design from its positions' rows.
StudyDesignAdapt design_adapt(const std::vector<SweepRow>& rows) {
  StudyDesignAdapt a;
  a.converged = true;
  for (const auto& r : rows) {
    a.unknowns = std::max(a.unknowns, r.unknowns);
    if (!r.adapt.passes)
      continue;
    a.passes = std::max(a.passes, r.adapt.passes);
    a.error_pct = largest_known_error(a.error_pct, r.adapt.error_pct);
    if (!r.adapt.converged)
      a.converged = false, a.stopped_deg.push_back(r.angle_deg);
  }
  a.converged = a.converged && a.passes > 0;
  return a;
}

} // namespace

StudyDesign evaluate_study_design(const StudyOptions& o, const std::vector<double>& values) {
  StudyDesign d;
  d.parameters = values;
  const auto t0 = std::chrono::steady_clock::now();
  try {
    ParameterOverrides overrides;
    for (std::size_t i = 0; i < values.size(); ++i)
      overrides[o.parameters[i].name] = values[i];
    CaseSpec spec = o.read ? o.read(overrides) : read_case(o.case_file, overrides);
    if (!o.sweep.analytic) // each position then refines for its torque (studies/sweep.hpp)
      apply_adapt_overrides(spec.adapt, o.adapt,
                            {cli, "--accuracy", "--max-passes", "--max-unknowns"});
    SweepOptions so = o.sweep;
    so.angles_deg = design_angles(o);
    // A design's sweep stays on its process (its positions on that process's threads), with
    // the process's share of the machine's cores and memory.
    so.world = MpiWorld{0, 1, o.world.size_on_node, false};
    const auto rows = run_sweep(spec, so);
    const Eigen::Vector3d axis = so.axis.normalized();
    const std::size_t n_peak = rows.size() - [&] {
      std::size_t n = 0;
      for (const auto& obj : o.objectives)
        n += obj.kind == StudyObjective::Kind::torque_at;
      return n;
    }();
    for (const auto& r : rows)
      if (!r.ok)
        throw std::runtime_error("at " + std::to_string(r.angle_deg) + " deg: " + r.error);
    std::size_t next_at = n_peak;
    for (const auto& obj : o.objectives) {
      if (obj.kind == StudyObjective::Kind::peak_torque) {
        // |max_i a_i - max_i b_i| <= max_i |a_i - b_i|: the peak's error is at most the
        // largest of its positions'.
        // A position without an estimate leaves the peak's unknown (NaN).
        double peak = 0, error = 0;
        for (std::size_t i = 0; i < n_peak; ++i) {
          peak = std::max(peak, std::abs(rows[i].torque.dot(axis)));
          error = largest_known_error(error, position_torque_error(rows[i]));
        }
        d.objectives.push_back(peak);
        d.objective_errors.push_back(error);
      } else {
        d.objective_errors.push_back(position_torque_error(rows[next_at]));
        d.objectives.push_back(rows[next_at++].torque.dot(axis));
      }
    }
    if (so.analytic) // the analytic figures are torque_accuracy's
      d.objective_errors.clear();
    else
      d.adapt = design_adapt(rows);
    d.method = sweep_method(rows, so);
    for (const auto& r : rows)
      d.torque_accuracy = std::max(d.torque_accuracy, r.torque_bound);
    d.ok = true;
  } catch (const InputError& e) {
    // Options and names are the same for every design: report them once, as bad input.
    if (e.file() == cli)
      throw;
    d.error = e.what();
  } catch (const std::exception& e) {
    d.error = e.what();
  }
  d.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return d;
}

namespace {

// What the options say before they are checked together (axis and angles need the objectives).
struct StudyArgs {
  StudyOptions options;
  std::string axis, angles;
  bool analytic = false, fe = false;
};

const OptionTable<StudyArgs>& study_option_table() {
  using A = StudyArgs;
  using S = const std::string&;
  static const auto table =
      OptionTable<A>("study")
          .value("--param", "NAME=START:STEP:END",
                 [](A& a, S, S v) { a.options.parameters.push_back(parse_parameter(v)); })
          .value("--objective", "OBJECTIVE",
                 [](A& a, S, S v) { a.options.objectives.push_back(parse_study_objective(v)); })
          .value("--rotate", "GROUP", [](A& a, S, S v) { a.options.sweep.group = v; })
          .value("--axis", "x|y|z|ax,ay,az", [](A& a, S, S v) { a.axis = v; })
          .value("--angles", "START:STEP:END|A,B,C", [](A& a, S, S v) { a.angles = v; })
          .flag("--analytic", [](A& a, S, S) { a.analytic = true; })
          .flag("--fe", [](A& a, S, S) { a.fe = true; })
          .value("--mesh-scale", "S",
                 [](A& a, S, S v) { a.options.sweep.mesh_scale = parse_cli_mesh_scale(v); })
          .value("--order", "1|2", [](A& a, S, S v) { a.options.sweep.order = parse_cli_order(v); })
          .value("--accuracy", "PCT",
                 [](A& a, S opt, S v) { parse_cli_adapt(opt, v, a.options.adapt); })
          .value("--max-passes", "N",
                 [](A& a, S opt, S v) { parse_cli_adapt(opt, v, a.options.adapt); })
          .value("--max-unknowns", "N",
                 [](A& a, S opt, S v) { parse_cli_adapt(opt, v, a.options.adapt); })
          .value("--jobs", "N",
                 [](A& a, S opt, S v) {
                   a.options.sweep.jobs = static_cast<int>(parse_cli_number(opt, v));
                   if (a.options.sweep.jobs < 1)
                     throw InputError(cli, 0, opt, "must be at least 1");
                 })
          .flag("--quiet", [](A& a, S, S) { a.options.quiet = true; })
          .flag("--resume", [](A& a, S, S) { a.options.resume = true; })
          .value("--out", "DIR", [](A& a, S, S v) { a.options.out_dir = v; });
  return table;
}

} // namespace

std::vector<OptionInfo> study_option_infos() {
  return study_option_table().options();
}

StudyOptions parse_study_options(const std::vector<std::string>& args) {
  StudyArgs parsed;
  parsed.options.sweep.analytic = true;
  const std::vector<std::string> positional = study_option_table().parse(args, parsed);
  StudyOptions& o = parsed.options;
  const std::string& axis = parsed.axis;
  const std::string& angles = parsed.angles;
  const bool analytic = parsed.analytic, fe = parsed.fe;
  if (positional.size() != 1)
    throw InputError(cli, 0, "", "study takes one case file");
  o.case_file = positional[0];
  if (analytic && fe)
    throw InputError(cli, 0, "--fe", "give --analytic or --fe, not both");
  o.sweep.analytic = !fe;
  refuse_adapt_options_unless(o.adapt, fe,
                              "refines the FE mesh: give --fe (the analytic models have no mesh)");
  if (o.parameters.empty())
    throw InputError(cli, 0, "--param", "give at least one --param NAME=START:STEP:END");
  if (o.objectives.empty())
    throw InputError(cli, 0, "--objective", "give at least one objective");
  if (o.sweep.group.empty())
    throw InputError(cli, 0, "--rotate", "name the group whose torque the objectives take");
  if (axis.empty())
    throw InputError(cli, 0, "--axis", "give the rotation axis");
  o.sweep.axis = parse_axis(axis);
  bool needs_angles = false;
  for (const auto& obj : o.objectives)
    needs_angles |= obj.kind == StudyObjective::Kind::peak_torque;
  if (needs_angles && angles.empty())
    throw InputError(cli, 0, "--angles", "peak_torque needs the angles of its sweep");
  if (!angles.empty())
    o.sweep.angles_deg = parse_angle_list(angles);
  if (o.out_dir.empty())
    o.out_dir = (std::filesystem::path("out") /
                 (std::filesystem::path(o.case_file).stem().string() + "_study"))
                    .string();
  return o;
}

namespace {

// A design's checkpoint key: its parameter values, exactly.
std::string design_key(const std::vector<double>& values) {
  std::string key;
  for (double v : values) {
    if (!key.empty())
      key += ',';
    key += RunCheckpoint::key_of(v);
  }
  return key;
}

// What study.csv and summary.json need of a finished design (doubles exact: nlohmann::json
// writes the shortest text that reads back as the same double).
nlohmann::json design_to_json(const StudyDesign& d) {
  nlohmann::json errors = nlohmann::json::array();
  for (double e : d.objective_errors)
    errors.push_back(number_or_null<nlohmann::json>(e));
  return {{"parameters", d.parameters},
          {"objectives", d.objectives},
          {"objective_errors", errors},
          {"method", d.method},
          {"torque_accuracy", d.torque_accuracy},
          {"adapt",
           {{"passes", d.adapt.passes},
            {"converged", d.adapt.converged},
            {"unknowns", d.adapt.unknowns},
            {"error_pct", number_or_null<nlohmann::json>(d.adapt.error_pct)},
            {"stopped_deg", d.adapt.stopped_deg}}},
          {"seconds", d.seconds}};
}

// A recorded design (from the checkpoint, or from another process under mpirun, failed ones
// too), if its record has the shape this build writes (else it is evaluated again, as a line
// cut short by the interrupt is). The checkpoint's identity names the objectives, so a record
// has as many as the options.
std::optional<StudyDesign> design_from_json(const nlohmann::json& j,
                                            const std::vector<double>& values) {
  try {
    StudyDesign d;
    d.parameters = values;
    d.objectives = j.at("objectives").get<std::vector<double>>();
    d.method = j.at("method").get<std::string>();
    d.torque_accuracy = j.at("torque_accuracy").get<double>();
    for (const auto& e : j.at("objective_errors"))
      d.objective_errors.push_back(e.is_number() ? e.get<double>()
                                                 : std::numeric_limits<double>::quiet_NaN());
    const auto& a = j.at("adapt");
    d.adapt = {a.at("passes").get<int>(), a.at("converged").get<bool>(),
               a.at("unknowns").get<long>(),
               a.at("error_pct").is_number() ? a.at("error_pct").get<double>()
                                             : std::numeric_limits<double>::quiet_NaN(),
               a.at("stopped_deg").get<std::vector<double>>()};
    d.seconds = j.at("seconds").get<double>();
    d.ok = true;
    return d;
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
}

} // namespace

std::string study_checkpoint_identity(const StudyOptions& o) {
  return checkpoint_identity("study", o.case_file, study_checkpoint_options(o));
}

std::string study_checkpoint_options(const StudyOptions& o) {
  const auto exact = [](double v) { return RunCheckpoint::key_of(v); };
  std::string text;
  for (const auto& p : o.parameters) {
    text += "param " + p.name + "=";
    for (double v : p.values)
      text += exact(v) + ",";
    text += " ";
  }
  for (const auto& obj : o.objectives)
    text += "objective " + obj.name + "@" + exact(obj.angle_deg) + " ";
  text += "rotate " + o.sweep.group + " axis " + exact(o.sweep.axis.x()) + "," +
          exact(o.sweep.axis.y()) + "," + exact(o.sweep.axis.z()) + " angles ";
  for (double a : o.sweep.angles_deg)
    text += exact(a) + ",";
  text += o.sweep.analytic ? " analytic tolerance " + exact(o.sweep.analytic_tolerance)
                           : " fe order " + std::to_string(o.sweep.order) + " mesh-scale " +
                                 RunCheckpoint::mesh_scale_key(o.sweep.mesh_scale);
  // The case's own adapt: is in the file's hash; the command line's goes here.
  if (o.adapt.accuracy_pct)
    text += " accuracy " + exact(*o.adapt.accuracy_pct);
  if (o.adapt.max_passes)
    text += " max-passes " + std::to_string(*o.adapt.max_passes);
  if (o.adapt.max_unknowns)
    text += " max-unknowns " + exact(*o.adapt.max_unknowns);
  return text;
}

std::vector<StudyDesign> run_study(const StudyOptions& options, RunCheckpoint* checkpoint,
                                   const std::function<void(int, int)>& on_design) {
  // Fail early for names the file does not declare (read_case names them as --param); the
  // first design's own problems (crossing radii) are that design's, reported with it. Under
  // mpirun every process checks alike, so that all end with the same exit code.
  try {
    ParameterOverrides check;
    for (const auto& p : options.parameters)
      check[p.name] = p.values.front();
    (void)(options.read ? options.read(check) : read_case(options.case_file, check));
  } catch (const InputError& e) {
    if (e.file() == cli || e.line() == 0) // an option, or a file that cannot be opened
      throw;
  }
  std::vector<std::vector<double>> grid{{}};
  for (const auto& p : options.parameters) {
    std::vector<std::vector<double>> next;
    for (const auto& g : grid)
      for (double v : p.values) {
        next.push_back(g);
        next.back().push_back(v);
      }
    grid = std::move(next);
  }
  // A line every 2 s at most (an analytic grid of hundreds of designs takes seconds; an FE
  // design takes minutes and gets its own line).
  auto last = std::chrono::steady_clock::now();
  const RowProgress<StudyDesign> progress = [&](const StudyDesign& d, int done, int total, bool) {
    const auto now = std::chrono::steady_clock::now();
    if (!options.quiet && (now - last > std::chrono::seconds(2) || done == total)) {
      std::fprintf(stderr, "study: design %d/%d done (%.1f s)%s\n", done, total, d.seconds,
                   d.ok ? "" : ", failed");
      last = now;
    }
    if (on_design)
      on_design(done, total);
  };
  const PositionCodec<StudyDesign, std::vector<double>> codec{
      design_to_json,
      [&](const nlohmann::json& j, const std::vector<double>& values) {
        return design_from_json(j, values);
      },
      design_key};
  // One design at a time on each process (a design's positions are its sweep's, on the
  // process's threads); under mpirun the designs are dealt to the processes.
  std::vector<StudyDesign> designs = run_items<StudyDesign, std::vector<double>>(
      grid, 1, checkpoint, codec,
      [&](StudyDesign& d, const std::vector<double>& values) {
        try {
          d = evaluate_study_design(options, values);
        } catch (const InputError&) { // an option bad for every design: bad input, once
          throw EndsRun{std::current_exception()};
        }
      },
      progress, options.world, options.sweep.stop);
  // A stop leaves the designs not started as default rows (no parameters): not returned.
  std::erase_if(designs, [&](const StudyDesign& d) {
    return d.parameters.size() != options.parameters.size();
  });
  return designs;
}

std::string study_csv(const StudyOptions& options, const std::vector<StudyDesign>& designs) {
  std::string out;
  for (const auto& p : options.parameters)
    out += p.name + ",";
  const bool fe = !options.sweep.analytic;
  std::vector<std::string> header;
  for (const auto& o : options.objectives)
    header.push_back(o.name);
  if (fe) // extends the analytic columns: the objectives' columns keep their places
    for (const auto& o : options.objectives)
      header.push_back(o.name + "_err");
  for (std::size_t i = 0; i < header.size(); ++i)
    out += header[i] + (i + 1 < header.size() ? "," : "\n");
  char cell[64];
  for (const auto& d : designs) {
    if (!d.ok)
      continue;
    std::vector<double> cells = d.objectives;
    if (fe)
      cells.insert(cells.end(), d.objective_errors.begin(), d.objective_errors.end());
    std::string line;
    for (double v : d.parameters)
      std::snprintf(cell, sizeof cell, "%.10g,", v), line += cell;
    for (std::size_t i = 0; i < cells.size(); ++i) {
      // an error without an estimate is an empty cell, not "nan"
      if (!std::isnan(cells[i]))
        std::snprintf(cell, sizeof cell, "%.10g", cells[i]), line += cell;
      line += i + 1 < cells.size() ? "," : "\n";
    }
    out += line;
  }
  return out;
}

nlohmann::ordered_json study_summary(const StudyOptions& options,
                                     const std::vector<StudyDesign>& designs) {
  nlohmann::ordered_json j;
  j["case"] = options.case_file;
  std::string method;
  int failed = 0;
  double seconds = 0, accuracy = 0;
  for (const auto& d : designs) {
    if (d.ok)
      method = method.empty() || method == d.method ? d.method : "mixed";
    failed += !d.ok;
    seconds += d.seconds;
    accuracy = std::max(accuracy, d.torque_accuracy);
  }
  j["method"] = method.empty() ? (options.sweep.analytic ? "analytic" : "fe") : method;
  j["group"] = options.sweep.group;
  j["axis"] = {options.sweep.axis.x(), options.sweep.axis.y(), options.sweep.axis.z()};
  j["angles_deg"] = options.sweep.angles_deg;
  for (const auto& p : options.parameters) {
    nlohmann::ordered_json pj = {{"name", p.name}, {"values", p.values}};
    j["parameters"].push_back(pj);
  }
  for (const auto& o : options.objectives)
    j["objectives"].push_back(o.name);
  j["designs"] = designs.size();
  j["failed_designs"] = failed;
  for (const auto& d : designs)
    if (!d.ok)
      j["failures"].push_back({{"parameters", d.parameters}, {"error", d.error}});
  j["seconds"] = seconds;
  // Harmonic form: rigorous truncation bound; the other analytic methods: estimated error.
  if (options.sweep.analytic)
    j["max_torque_error_Nm"] = accuracy;
  for (const auto& d : designs)
    if (d.ok && d.adapt.passes)
      j["adapt"].push_back({{"parameters", d.parameters},
                            {"converged", d.adapt.converged},
                            {"passes", d.adapt.passes},
                            {"unknowns", d.adapt.unknowns},
                            {"estimated_error_pct", number_or_null(d.adapt.error_pct)},
                            {"stopped_deg", d.adapt.stopped_deg}});
  if (const auto warnings = study_warnings(options, designs); !warnings.empty())
    j["warnings"] = warnings;
  return j;
}

std::vector<std::string> study_warnings(const StudyOptions& options,
                                        const std::vector<StudyDesign>& designs) {
  const auto number = [](double v) {
    char text[32];
    std::snprintf(text, sizeof text, " %g", v);
    return std::string(text);
  };
  std::vector<std::string> out;
  for (const auto& d : designs) {
    if (!d.ok || !d.adapt.passes || d.adapt.converged)
      continue;
    std::string line = "design (";
    for (std::size_t i = 0; i < d.parameters.size(); ++i) {
      if (i)
        line += ", ";
      line += options.parameters[i].name + " =" + number(d.parameters[i]);
    }
    line += "): adaptive refinement stopped at a limit before its accuracy at";
    for (double a : d.adapt.stopped_deg)
      line += number(a);
    line += " deg (after " + std::to_string(d.adapt.passes) +
            " passes at most; study.csv's _err columns are the estimates reached)";
    out.push_back(line);
  }
  return out;
}

int run_study_command(const StudyOptions& options) {
  // Under mpirun rank 0 alone keeps the checkpoint (the others send it their designs), and
  // alone writes and reports; every process ends with its exit code.
  std::optional<RunCheckpoint> checkpoint;
  if (options.world.is_root()) {
    checkpoint.emplace(options.out_dir, study_checkpoint_identity(options), options.resume);
    if (checkpoint->n_restored())
      std::fprintf(stderr, "magfem: --resume: %zu finished designs from the checkpoint\n",
                   checkpoint->n_restored());
  }
  const auto designs = run_study(options, checkpoint ? &*checkpoint : nullptr);
  if (!options.world.is_root())
    return code_of_root(0);
  std::filesystem::create_directories(options.out_dir);
  OutputStage stage(options.out_dir);
  stage.write_text("study.csv", study_csv(options, designs));
  std::string why;
  const bool plotted = plot_study(options, designs, stage.path_for("study.png"), why);
  if (!plotted)
    std::cerr << "magfem: note: no study.png: " << why << "\n";

  nlohmann::ordered_json j;
  add_provenance(j);
  j.update(study_summary(options, designs));
  const std::string method = j["method"];
  const double seconds = j["seconds"];
  double accuracy = 0;
  for (const auto& d : designs)
    accuracy = std::max(accuracy, d.torque_accuracy);
  const int failed = j["failed_designs"];
  stage.write_text("summary.json", j.dump(2) + "\n");
  stage.commit();
  checkpoint->remove();

  for (const auto& p : options.parameters)
    std::printf("%14s", p.name.c_str());
  for (const auto& o : options.objectives)
    std::printf(" %22s", o.name.c_str());
  std::printf("\n");
  for (const auto& d : designs) {
    for (double v : d.parameters)
      std::printf("%14.6g", v);
    if (d.ok)
      for (std::size_t i = 0; i < d.objectives.size(); ++i) {
        std::printf(" %22.8g", d.objectives[i]);
        if (i < d.objective_errors.size()) // FE: its estimate beside it
          std::printf(" +- %-8.2g", d.objective_errors[i]);
      }
    else
      std::printf(" FAILED: %s", d.error.c_str());
    std::printf("\n");
  }
  std::printf("method   %s, %zu designs in %.2f s\n", j["method"].get<std::string>().c_str(),
              designs.size(), seconds);
  if (options.sweep.analytic)
    std::printf("accuracy torque error <= %.2g N m (largest over the designs: %s)\n", accuracy,
                method == "harmonic_interaction" ? "truncation bound" : "estimate");
  else
    std::printf("accuracy +- the estimated FE error of each objective (study.csv: _err columns)\n");
  std::printf("wrote    %s/study.csv%s, summary.json\n", options.out_dir.c_str(),
              plotted ? ", study.png" : "");
  std::fflush(stdout);
  for (const auto& w : study_warnings(options, designs))
    std::cerr << "magfem: warning: " << w << "\n";
  if (failed)
    std::cerr << "magfem: " << failed << " of " << designs.size() << " designs failed\n";
  return code_of_root(failed ? 3 : 0);
}

} // namespace magfem
