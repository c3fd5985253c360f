#include "studies/actuator.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <utility>

#include <unistd.h>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "analytic/charge_model.hpp"
#include "analytic/torque_constants.hpp"
#include "casefile/cli_number.hpp"
#include "core/constants.hpp"
#include "core/input_error.hpp"
#include "core/output_stage.hpp"
#include "core/progress.hpp"
#include "pipeline/analytic_scene.hpp"
#include "pipeline/build_info.hpp"
#include "pipeline/run3d.hpp"
#include "pipeline/solve_case.hpp"
#include "postproc/point_locator3d.hpp"
#include "studies/actuator_coil_pitch.hpp"
#include "studies/actuator_plot.hpp"
#include "studies/position_runner.hpp"
#include "studies/sweep.hpp"

namespace magfem {
namespace {

const std::string cli = "<command line>";

// "" or ", estimated error 0.0012 N m (3 passes)" for the console's verify line.
std::string verified_error_text(const Verification& v) {
  if (!std::isfinite(v.produced_error_Nm))
    return "";
  char text[96];
  std::snprintf(text, sizeof text, ", estimated error %.2g N m (%d passes)", v.produced_error_Nm,
                v.adapt.passes);
  return text;
}

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (;;) {
    const auto end = text.find(sep, start);
    out.push_back(text.substr(start, end - start));
    if (end == std::string::npos)
      return out;
    start = end + 1;
  }
}

std::vector<Orientation> read_orientation_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    throw InputError(cli, 0, "--orientations", "cannot read " + path);
  std::string line;
  if (!std::getline(in, line) || line.rfind("rx_deg,ry_deg,rz_deg", 0) != 0)
    throw InputError(path, 1, "header", "expected the header rx_deg,ry_deg,rz_deg");
  std::vector<Orientation> out;
  for (int n = 2; std::getline(in, line); ++n) {
    if (line.empty() || line == "\r")
      continue;
    if (line.back() == '\r')
      line.pop_back();
    const auto f = split(line, ',');
    if (f.size() < 3)
      throw InputError(path, n, "row", "expected three angles rx_deg,ry_deg,rz_deg");
    try {
      out.push_back({parse_cli_number("rx_deg", f[0]), parse_cli_number("ry_deg", f[1]),
                     parse_cli_number("rz_deg", f[2])});
    } catch (const InputError& e) {
      throw InputError(path, n, "row", e.what());
    }
  }
  if (out.empty())
    throw InputError(path, 0, "rows", "no orientations in the file");
  return out;
}

bool in_rotor(const Part3D& part, const std::string& rotor) {
  return part.group == rotor;
}

// The first part that keeps the field from turning rigidly with the rotor: a magnet off it,
// or magnetic matter off it that is not a (rotation-invariant) sphere about the origin.
std::optional<std::size_t> part_against_rigid_field(const CaseSpec& spec,
                                                    const std::string& rotor) {
  for (std::size_t i = 0; i < spec.geometry3d.parts.size(); ++i) {
    const auto& part = spec.geometry3d.parts[i];
    const Material& m = *spec.regions[i].material;
    if (in_rotor(part, rotor) || is_air(m))
      continue;
    if (m.is_magnet() || !full_sphere_at_origin(part))
      return i;
  }
  return std::nullopt;
}

bool rotor_rigid_field(const CaseSpec& spec, const std::string& rotor) {
  return !part_against_rigid_field(spec, rotor);
}

// The case without its coils, probes and forces: the magnets-and-iron problem whose field
// the torque constants need (the coils are post-processing).
CaseSpec magnets_and_iron(CaseSpec spec) {
  spec.geometry3d.coils.clear();
  spec.coil_lines.clear();
  spec.probes.clear();
  spec.forces.clear();
  spec.write_vtu = false;
  return spec;
}

CaseSpec turned(const CaseSpec& spec, const std::string& rotor, const Orientation& o) {
  const Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  CaseSpec s = rotate_group(spec, rotor, Eigen::Vector3d::UnitX(), o.rx_deg * deg_to_rad, origin);
  s = rotate_group(s, rotor, Eigen::Vector3d::UnitY(), o.ry_deg * deg_to_rad, origin);
  return rotate_group(s, rotor, Eigen::Vector3d::UnitZ(), o.rz_deg * deg_to_rad, origin);
}

// B at points from an FE run; the function holds the run.
FieldAtPoints fe_field(std::shared_ptr<const Run3D> run) {
  return [run](const std::vector<Eigen::Vector3d>& points) {
    const PointLocator3D locator(run->mesh);
    std::vector<Eigen::Vector3d> b;
    b.reserve(points.size());
    for (const auto& p : points) {
      const auto loc = locator.locate(p);
      if (!loc || run->problem.is_shell(loc->tet))
        throw InputError(run->spec.file, 0, "coils",
                         "a coil leaves the meshed domain (enlarge boundary.radius)");
      b.push_back(loc->b_map * run->field->B(loc->tet, loc->bary));
    }
    return b;
  };
}

// The field at all orientations' coil points is one call, about 40 s for the design case's
// 49 orientations x 12 coils, which left the console silent that long (issue 34 item 9). In
// slices the console can say how far it is, at most every interval_s; every point still gets
// the same evaluation, so the torque constants do not change.
FieldAtPoints with_progress(FieldAtPoints field, Progress& progress, double interval_s = 2.0) {
  return [field = std::move(field), &progress, interval_s](const std::vector<Eigen::Vector3d>& x) {
    using Clock = std::chrono::steady_clock;
    constexpr std::size_t n_slices = 50;
    const std::size_t slice = std::max<std::size_t>(1, (x.size() + n_slices - 1) / n_slices);
    std::vector<Eigen::Vector3d> b;
    b.reserve(x.size());
    auto last = Clock::now();
    for (std::size_t begin = 0; begin < x.size(); begin += slice) {
      const std::size_t end = std::min(x.size(), begin + slice);
      const auto part = field({x.begin() + static_cast<std::ptrdiff_t>(begin),
                               x.begin() + static_cast<std::ptrdiff_t>(end)});
      b.insert(b.end(), part.begin(), part.end());
      if (end < x.size() &&
          std::chrono::duration<double>(Clock::now() - last).count() >= interval_s) {
        last = Clock::now();
        progress.note(std::to_string(100 * end / x.size()) + " % of the points");
      }
    }
    return b;
  };
}

std::vector<TorqueConstants> analytic_gamma(const CaseSpec& spec, const std::string& rotor,
                                            const std::vector<CoilField>& coils,
                                            const std::vector<Eigen::Matrix3d>& rotations,
                                            const CoilRule& rule, std::vector<std::string>& notes,
                                            Progress* progress) {
  FieldAtPoints field = analytic_rotor_field(spec, rotor, notes);
  if (progress) {
    std::size_t points = 0;
    for (const auto& c : coils)
      points += torque_quadrature(c, rule).size();
    progress->stage("torque constants: charge model at " + std::to_string(points) + " x " +
                    std::to_string(rotations.size()) + " coil points (" +
                    std::to_string(coils.size()) + " coils, " + std::to_string(rotations.size()) +
                    " orientations)");
    field = with_progress(std::move(field), *progress);
  }
  return torque_constants_rotating(coils, rotations, field, rule);
}

std::string number(double v) {
  if (!std::isfinite(v))
    return "inf";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

std::string angles(const Orientation& o) {
  return number(o.rx_deg) + "," + number(o.ry_deg) + "," + number(o.rz_deg);
}

std::vector<TorqueConstants> fe_gamma(const CaseSpec& spec, const ActuatorOptions& options,
                                      const std::vector<Orientation>& orientations,
                                      const std::vector<CoilField>& coils,
                                      const std::vector<Eigen::Matrix3d>& rotations, int& n_solves,
                                      std::vector<std::string>& notes) {
  RunOverrides ov;
  ov.mesh_scale = options.mesh_scale;
  ov.order = options.order;
  ov.progress = options.progress;
  const CoilRule& q = options.coil_rule;
  if (rotor_rigid_field(spec, options.rotor)) {
    notes.push_back("the field turns rigidly with the rotor: one FE solve in the rotor's frame "
                    "serves every orientation");
    n_solves = 1;
    return torque_constants_rotating(coils, rotations, fe_rotor_field(spec, options.rotor, ov), q);
  }
  notes.push_back("stator iron or magnets that are not spheres about the origin: one FE solve "
                  "per orientation");
  std::vector<TorqueConstants> out;
  for (const auto& o : orientations) {
    if (options.progress)
      options.progress->note("orientation " + std::to_string(out.size() + 1) + " of " +
                             std::to_string(orientations.size()) + " (" + angles(o) + " deg)");
    ++n_solves;
    out.push_back(torque_constants(
        coils, fe_field(run_case_3d(magnets_and_iron(turned(spec, options.rotor, o)), ov)), q));
  }
  return out;
}

struct PowerStats {
  double avg = 0, max = 0, min = 0;
  int n_ok = 0, n_ill = 0;
  int at_max = -1, at_min = -1;
};

PowerStats power_stats(const ActuatorDemand& d) {
  PowerStats s;
  s.min = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < d.commutations.size(); ++i) {
    const auto& c = d.commutations[i];
    if (!c.ok) {
      ++s.n_ill;
      continue;
    }
    ++s.n_ok;
    s.avg += c.power_W;
    if (c.power_W > s.max || s.at_max < 0)
      s.max = c.power_W, s.at_max = static_cast<int>(i);
    if (c.power_W < s.min)
      s.min = c.power_W, s.at_min = static_cast<int>(i);
  }
  if (s.n_ok > 0)
    s.avg /= s.n_ok;
  else
    s.min = 0;
  return s;
}

nlohmann::ordered_json orientation_json(const ActuatorResult& r, int i) {
  if (i < 0)
    return nullptr;
  const auto& o = r.orientations[static_cast<std::size_t>(i)];
  return {o.rx_deg, o.ry_deg, o.rz_deg};
}

} // namespace

FieldAtPoints analytic_rotor_field(const CaseSpec& spec, const std::string& rotor,
                                   std::vector<std::string>& notes) {
  for (std::size_t i = 0; i < spec.regions.size(); ++i)
    if (spec.regions[i].material->is_magnet() && !in_rotor(spec.geometry3d.parts[i], rotor))
      throw InputError(spec.file, spec.regions[i].line, "regions[" + std::to_string(i) + "]",
                       "magnet " + spec.regions[i].name + " is not on the rotor '" + rotor +
                           "'; the analytic torque constants need every magnet on it");
  const AnalyticScene scene = analytic_scene(magnets_and_iron(spec));
  for (const auto& n : scene.notes)
    notes.push_back(n);
  const auto model = std::make_shared<const ChargeModel>(scene.magnets, scene.spheres);
  return [model](const std::vector<Eigen::Vector3d>& x) { return model->B(x); };
}

FieldAtPoints fe_rotor_field(const CaseSpec& spec, const std::string& rotor,
                             const RunOverrides& overrides, std::shared_ptr<const Run3D>* run) {
  if (const auto i = part_against_rigid_field(spec, rotor))
    throw InputError(spec.file, spec.regions[*i].line, "regions[" + std::to_string(*i) + "]",
                     spec.regions[*i].name + " is off the rotor '" + rotor +
                         "' and not a sphere about the origin: the field does not turn rigidly "
                         "with the rotor, and one FE solve in its frame cannot serve every "
                         "orientation");
  std::shared_ptr<const Run3D> solved = run_case_3d(magnets_and_iron(spec), overrides);
  if (run)
    *run = solved;
  return fe_field(std::move(solved));
}

std::vector<Eigen::Vector3d> rotor_torque(const CaseSpec& spec, const FieldAtPoints& b_rotor,
                                          const std::vector<Orientation>& orientations,
                                          const CoilRule& rule) {
  // Coils without current add nothing, and each costs its quadrature points in the field at
  // every orientation (18 of seed 001's 20 EMs).
  std::vector<CoilField> coils;
  std::vector<double> current;
  for (const auto& c : spec.geometry3d.coils)
    if (c.current != 0) {
      current.push_back(c.current);
      coils.emplace_back(c);
    }
  std::vector<Eigen::Matrix3d> rotations;
  for (const auto& o : orientations)
    rotations.push_back(rotor_rotation(o));
  const Eigen::Map<const Eigen::VectorXd> i(current.data(),
                                            static_cast<Eigen::Index>(current.size()));
  std::vector<Eigen::Vector3d> out;
  for (const auto& g : torque_constants_rotating(coils, rotations, b_rotor, rule))
    out.push_back(-(g * i));
  return out;
}

std::vector<Eigen::Vector3d> analytic_rotor_torque(const CaseSpec& spec, const std::string& rotor,
                                                   const std::vector<Orientation>& orientations,
                                                   const CoilRule& rule) {
  std::vector<std::string> notes;
  return rotor_torque(spec, analytic_rotor_field(spec, rotor, notes), orientations, rule);
}

double InclinationTorque::peak_Nm() const {
  double p = 0;
  for (double t : ty_Nm)
    p = std::max(p, std::abs(t));
  return p;
}

InclinationTorque torque_about_y(const CaseSpec& spec, const FieldAtPoints& b_rotor, double max_deg,
                                 double step_deg) {
  InclinationTorque c;
  std::vector<Orientation> grid;
  const int n = static_cast<int>(std::floor(max_deg / step_deg + 1e-9));
  for (int i = -n; i <= n; ++i) {
    c.ry_deg.push_back(step_deg * i);
    grid.push_back({0, step_deg * i, 0});
  }
  for (const auto& t : rotor_torque(spec, b_rotor, grid))
    c.ty_Nm.push_back(t.y());
  return c;
}

InclinationTorque analytic_torque_about_y(const CaseSpec& spec, const std::string& rotor,
                                          double max_deg, double step_deg) {
  std::vector<std::string> notes;
  return torque_about_y(spec, analytic_rotor_field(spec, rotor, notes), max_deg, step_deg);
}

Eigen::Matrix3d rotor_rotation(const Orientation& o) {
  using A = Eigen::AngleAxisd;
  return (A(o.rz_deg * deg_to_rad, Eigen::Vector3d::UnitZ()) *
          A(o.ry_deg * deg_to_rad, Eigen::Vector3d::UnitY()) *
          A(o.rx_deg * deg_to_rad, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

std::vector<Orientation> parse_orientations(const std::string& spec) {
  const std::string opt = "--orientations";
  if (spec.empty())
    throw InputError(cli, 0, opt, "give rx=..,ry=..,rz=.. or a CSV file");
  if (std::filesystem::is_regular_file(spec) ||
      (spec.size() > 4 && spec.substr(spec.size() - 4) == ".csv"))
    return read_orientation_csv(spec);
  std::vector<double> axes[3];
  bool given[3] = {false, false, false};
  int current = -1;
  for (const auto& token : split(spec, ',')) {
    const auto eq = token.find('=');
    std::string value = token;
    if (eq != std::string::npos) {
      const std::string name = token.substr(0, eq);
      current = name == "rx" ? 0 : name == "ry" ? 1 : name == "rz" ? 2 : -1;
      if (current < 0)
        throw InputError(cli, 0, opt, "unknown axis '" + name + "' (rx, ry, rz)");
      if (given[current])
        throw InputError(cli, 0, opt, name + " is given twice");
      given[current] = true;
      value = token.substr(eq + 1);
    } else if (current < 0) {
      throw InputError(cli, 0, opt, "expected rx=.., ry=.., rz=.. (degrees), got '" + spec + "'");
    }
    const auto list = parse_angle_list(value, opt);
    axes[current].insert(axes[current].end(), list.begin(), list.end());
  }
  for (auto& a : axes)
    if (a.empty())
      a.push_back(0.0);
  std::vector<Orientation> out;
  for (double rx : axes[0])
    for (double ry : axes[1])
      for (double rz : axes[2])
        out.push_back({rx, ry, rz});
  return out;
}

namespace {

Eigen::Vector3d parse_demanded_torque(const std::string& option, const std::string& text) {
  const auto parts = split(text, ',');
  if (parts.size() != 3)
    throw InputError(cli, 0, option, "expected three numbers Tx,Ty,Tz (N m), got '" + text + "'");
  Eigen::Vector3d v;
  for (int k = 0; k < 3; ++k)
    v(k) = parse_cli_number(option, parts[static_cast<std::size_t>(k)]);
  if (v.norm() == 0)
    throw InputError(cli, 0, option, "the demanded torque is zero");
  return v;
}

const OptionTable<ActuatorOptions>& actuator_option_table() {
  using O = ActuatorOptions;
  using S = const std::string&;
  static const auto table =
      OptionTable<O>("actuator")
          .value("--rotor", "GROUP", [](O& o, S, S v) { o.rotor = v; })
          .value("--orientations", "rx=..,ry=..,rz=..|FILE.csv",
                 [](O& o, S, S v) { o.orientations = v; })
          .value("--torque", "Tx,Ty,Tz",
                 [](O& o, S opt, S v) { o.torque_Nm = parse_demanded_torque(opt, v); })
          .flag("--analytic", [](O& o, S, S) { o.analytic = true; })
          .value("--param", "NAME=VALUE",
                 [](O& o, S, S v) { parse_cli_parameter(v, o.parameters); })
          .value("--order", "1|2", [](O& o, S, S v) { o.order = parse_cli_order(v); })
          .value("--mesh-scale", "S", [](O& o, S, S v) { o.mesh_scale = parse_cli_mesh_scale(v); })
          .value("--coil-quadrature", "N_R,N_ALPHA,PANELS,N_AZIMUTH",
                 [](O& o, S opt, S v) { o.coil_rule = parse_coil_rule(opt, v); })
          .flag("--verify", [](O& o, S, S) { o.verify = true; })
          .value("--accuracy", "PCT", [](O& o, S opt, S v) { parse_cli_adapt(opt, v, o.adapt); })
          .value("--max-passes", "N", [](O& o, S opt, S v) { parse_cli_adapt(opt, v, o.adapt); })
          .value("--max-unknowns", "N", [](O& o, S opt, S v) { parse_cli_adapt(opt, v, o.adapt); })
          .flag("--quiet", [](O& o, S, S) { o.quiet = true; })
          .value("--out", "DIR", [](O& o, S, S v) { o.out_dir = v; })
          .value("--coil-pitch", "SPEC", [](O& o, S, S v) { o.coil_pitch = v; });
  return table;
}

} // namespace

CoilRule parse_coil_rule(const std::string& option, const std::string& text) {
  const auto parts = split(text, ',');
  int n[4] = {0, 0, 0, 0};
  for (std::size_t k = 0; k < parts.size() && k < 4; ++k)
    n[k] = static_cast<int>(parse_cli_number(option, parts[k]));
  if (parts.size() != 4 || n[0] < 1 || n[1] < 1 || n[2] < 1 || n[3] < 4 || n[0] > 64 || n[1] > 64)
    throw InputError(cli, 0, option,
                     "expected N_R,N_ALPHA,ALPHA_PANELS,N_AZIMUTH (Gauss orders 1..64, at "
                     "least 4 azimuths), got '" +
                         text + "'");
  return {n[0], n[1], n[2], n[3]};
}

std::vector<OptionInfo> actuator_option_infos() {
  return actuator_option_table().options();
}

ActuatorOptions parse_actuator_options(const std::vector<std::string>& args) {
  ActuatorOptions o;
  const std::vector<std::string> positional = actuator_option_table().parse(args, o);
  if (positional.size() != 1)
    throw InputError(cli, 0, "", "actuator takes one case file");
  o.case_file = positional[0];
  if (o.rotor.empty())
    throw InputError(cli, 0, "--rotor", "name the rotor group");
  if (o.orientations.empty())
    throw InputError(cli, 0, "--orientations", "give rx=..,ry=..,rz=.. or a CSV file");
  // The torque-constant solves are field evaluations at the coils, not a named quantity: the
  // adaptive options refine the verification solves only.
  refuse_adapt_options_unless(o.adapt, o.verify, "refines the --verify solves: give --verify");
  if (o.out_dir.empty())
    o.out_dir = "out";
  return o;
}

void check_actuator_case(const CaseSpec& spec, const std::string& rotor) {
  if (spec.dimension != 3)
    throw InputError(spec.file, 0, "dimension", "the actuator command needs a 3D case");
  if (spec.geometry3d.coils.empty())
    throw InputError(spec.file, 0, "coils", "no coils: nothing to commutate");
  // rotate_group names the known groups when the rotor is not one of them.
  (void)rotate_group(spec, rotor, Eigen::Vector3d::UnitZ(), 0.0, Eigen::Vector3d::Zero());
  for (std::size_t k = 0; k < spec.geometry3d.coils.size(); ++k)
    if (spec.geometry3d.coils[k].group == rotor)
      throw InputError(spec.file, spec.coil_lines[k], "coils." + spec.geometry3d.coils[k].name,
                       "the coil is on the rotor '" + rotor +
                           "'; actuator coils are on the stator");
  StressSurface surface;
  try {
    surface = stress_surface(spec, rotor, std::nullopt);
  } catch (const InputError&) {
    throw InputError(cli, 0, "--rotor",
                     "coils or stator parts lie inside the sphere the rotor '" + rotor +
                         "' sweeps when it turns about the origin; the rotor must fit inside a "
                         "sphere that has every coil and stator part outside it");
  }
  if (surface.group_outside)
    throw InputError(cli, 0, "--rotor",
                     "the rotor '" + rotor +
                         "' lies outside the coils; the actuator command turns an inner rotor");
}

ActuatorResult run_actuator(const CaseSpec& spec, const ActuatorOptions& options,
                            const std::vector<Orientation>& orientations) {
  ActuatorResult r;
  r.method = options.analytic ? "charge_model" : "fe";
  r.orientations = orientations;
  std::vector<CoilField> coils;
  r.resistance_ohm.resize(static_cast<Eigen::Index>(spec.geometry3d.coils.size()));
  for (const auto& c : spec.geometry3d.coils) {
    coils.emplace_back(c);
    r.coil_names.push_back(c.name);
    r.resistance_ohm(static_cast<Eigen::Index>(coils.size() - 1)) = coils.back().resistance();
  }
  std::vector<Eigen::Matrix3d> rotations;
  for (const auto& o : orientations)
    rotations.push_back(rotor_rotation(o));
  const auto t0 = std::chrono::steady_clock::now();
  if (options.analytic) {
    r.gamma = analytic_gamma(spec, options.rotor, coils, rotations, options.coil_rule, r.notes,
                             options.progress);
    r.n_field_solves = 1;
  } else {
    r.gamma = fe_gamma(spec, options, orientations, coils, rotations, r.n_field_solves, r.notes);
    if (spec.adapt.enabled() || options.adapt.accuracy_pct)
      r.notes.push_back("the FE torque constants are from the case's mesh: the adaptive "
                        "refinement is the --verify solves' (for the torque they report)");
  }
  r.gamma_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (options.torque_Nm) {
    r.demands.push_back({"T_d", *options.torque_Nm, {}});
  } else {
    r.demands.push_back({"P_x", Eigen::Vector3d::UnitX(), {}});
    r.demands.push_back({"P_y", Eigen::Vector3d::UnitY(), {}});
    r.demands.push_back({"P_z", Eigen::Vector3d::UnitZ(), {}});
  }
  for (auto& d : r.demands)
    for (const auto& g : r.gamma)
      d.commutations.push_back(commutate(g, r.resistance_ohm, d.torque_Nm));
  return r;
}

namespace {

// A verification as the item runner carries it (studies/position_runner.hpp).
// The force entry of a verification solve: the Lorentz force and torque (about the origin) on
// all coils together, what --verify reports and an adaptive solve refines for.
const char* const verified_torque = "verify_coils";

ForceSpec all_coils_lorentz(const CaseSpec& spec) {
  ForceSpec f;
  f.name = verified_torque;
  f.kind = ForceSpec::Kind::lorentz;
  for (const auto& c : spec.geometry3d.coils)
    f.regions.push_back(c.name);
  return f;
}

struct VerificationRow {
  Verification v;
  bool ok = false;
  std::string error;
  double seconds = 0;
};

} // namespace

std::vector<Verification> verify_commutation(const CaseSpec& spec, const ActuatorOptions& options,
                                             const ActuatorResult& r) {
  std::vector<std::size_t> at{0, r.orientations.size() / 2, r.orientations.size() - 1};
  at.erase(std::unique(at.begin(), at.end()), at.end());
  RunOverrides ov;
  ov.mesh_scale = options.mesh_scale;
  ov.order = options.order;
  ov.progress = options.progress;
  // One item per demand and orientation, in the order they are reported.
  std::vector<std::pair<std::size_t, std::size_t>> items; // (demand, orientation)
  for (std::size_t d = 0; d < r.demands.size(); ++d)
    for (const std::size_t i : at)
      items.emplace_back(d, i);
  using Item = std::pair<std::size_t, std::size_t>;
  const auto planned = [&](const Item& item) {
    const ActuatorDemand& d = r.demands[item.first];
    Verification v;
    v.demand = d.name, v.orientation = r.orientations[item.second], v.demanded_Nm = d.torque_Nm;
    return v;
  };
  const PositionCodec<VerificationRow, Item> codec{
      [](const VerificationRow& row) {
        const Eigen::Vector3d& t = row.v.produced_Nm;
        nlohmann::json j{{"produced_Nm", {t.x(), t.y(), t.z()}}, {"solved", row.v.ok}};
        add_position_adapt(j, row.v.adapt); // its error_pct gives produced_error_Nm back
        return j;
      },
      [&](const nlohmann::json& j, const Item& item) -> std::optional<VerificationRow> {
        VerificationRow row;
        row.v = planned(item);
        for (int k = 0; k < 3; ++k)
          row.v.produced_Nm[k] = j.at("produced_Nm").at(k).get<double>();
        row.v.ok = j.at("solved").get<bool>();
        row.v.adapt = position_adapt_from_json(j);
        row.v.produced_error_Nm = position_adapt_error(row.v.adapt, row.v.produced_Nm.norm());
        return row;
      },
      {}};
  const auto rows = run_items<VerificationRow, Item>(
      items, 1, nullptr, codec,
      [&](VerificationRow& row, const Item& item) {
        row.v = planned(item);
        const Commutation& c = r.demands[item.first].commutations[item.second];
        if (!c.ok)
          return; // ill-conditioned: no currents to verify
        try {
          if (options.progress)
            options.progress->note("verify " + row.v.demand + " at (" + angles(row.v.orientation) +
                                   " deg): FE with the commutated currents");
          CaseSpec s = turned(spec, options.rotor, row.v.orientation);
          for (std::size_t k = 0; k < s.geometry3d.coils.size(); ++k)
            s.geometry3d.coils[k].current = c.currents(static_cast<Eigen::Index>(k));
          s.probes.clear();
          s.write_vtu = false;
          s.coil_inductance = false;
          s.forces = {all_coils_lorentz(s)};
          apply_adapt_overrides(s.adapt, options.adapt,
                                {cli, "--accuracy", "--max-passes", "--max-unknowns"});
          aim_adapt_at(s, verified_torque, "torque");
          const auto run = solve_case_3d(std::move(s), ov);
          row.v.produced_Nm = run->forces.front().torque;
          row.v.adapt = position_adapt(run->adapt);
          row.v.produced_error_Nm = position_adapt_error(row.v.adapt, row.v.produced_Nm.norm());
          row.v.ok = true;
        } catch (...) { // a solve that fails ends the command, as a serial run's does
          throw EndsRun{std::current_exception()};
        }
      },
      {}, options.world);
  std::vector<Verification> out;
  for (const auto& row : rows)
    out.push_back(row.v);
  return out;
}

std::string commutation_csv(const ActuatorResult& r, const ActuatorDemand& d) {
  std::string s = "rx_deg,ry_deg,rz_deg";
  for (const auto& n : r.coil_names)
    s += ",i_" + n + "_A";
  s += ",P_W,i_peak_A,cond_Gamma\n";
  for (std::size_t i = 0; i < r.orientations.size(); ++i) {
    const auto& c = d.commutations[i];
    s += angles(r.orientations[i]);
    // Ill-conditioned rows leave the currents, loss and peak empty.
    auto field = [&s, &c](double v) {
      s += ',';
      if (c.ok)
        s += number(v);
    };
    for (std::size_t k = 0; k < r.coil_names.size(); ++k)
      field(c.ok ? c.currents(static_cast<Eigen::Index>(k)) : 0.0);
    field(c.power_W);
    field(c.peak_A);
    s += ',';
    s += number(c.condition);
    s += '\n';
  }
  return s;
}

std::string torque_constants_csv(const ActuatorResult& r) {
  std::string s = "rx_deg,ry_deg,rz_deg,coil,kx,ky,kz\n";
  for (std::size_t i = 0; i < r.orientations.size(); ++i)
    for (std::size_t k = 0; k < r.coil_names.size(); ++k) {
      const auto col = r.gamma[i].col(static_cast<Eigen::Index>(k));
      s += angles(r.orientations[i]) + "," + r.coil_names[k] + "," + number(col.x()) + "," +
           number(col.y()) + "," + number(col.z()) + "\n";
    }
  return s;
}

int run_actuator_command(ActuatorOptions options) {
  if (!options.coil_pitch.empty())
    return run_coil_pitch_command(options);
  Progress progress;
  if (!options.quiet)
    options.progress = &progress;
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<Orientation> orientations = parse_orientations(options.orientations);
  const CaseSpec spec = read_case(options.case_file, options.parameters);
  check_actuator_case(spec, options.rotor);
  const ActuatorResult r = run_actuator(spec, options, orientations);
  // Under mpirun every process has computed r (the currents to verify); the verification
  // solves are dealt, and rank 0 alone writes and reports.
  const std::vector<Verification> verification =
      options.verify ? verify_commutation(spec, options, r) : std::vector<Verification>{};
  if (!options.world.is_root())
    return code_of_root(0);

  std::filesystem::create_directories(options.out_dir);
  OutputStage stage(options.out_dir);
  nlohmann::ordered_json j;
  j["command"] = "actuator";
  j["case"] = options.case_file;
  j["magfem_version"] = magfem_version();
  j["git_commit"] = magfem_git_commit();
  j["method"] = r.method;
  j["rotor"] = options.rotor;
  j["rotation_order"] = "R = Rz(rz) Ry(ry) Rx(rx): rx about the fixed x axis first, then ry "
                        "about y, then rz about z, through the origin";
  j["n_orientations"] = r.orientations.size();
  j["n_field_solves"] = r.n_field_solves;
  j["coil_quadrature"] = {{"n_r", options.coil_rule.n_r},
                          {"n_alpha", options.coil_rule.n_alpha},
                          {"alpha_panels", options.coil_rule.n_alpha_panels},
                          {"n_azimuth", options.coil_rule.n_azimuth}};
  j["torque_constants_seconds"] = r.gamma_seconds;
  j["coils"] = nlohmann::ordered_json::array();
  for (std::size_t k = 0; k < r.coil_names.size(); ++k)
    j["coils"].push_back({{"name", r.coil_names[k]},
                          {"resistance_ohm", r.resistance_ohm(static_cast<Eigen::Index>(k))}});
  std::vector<std::string> warnings;
  for (const auto& d : r.demands) {
    const std::string file = options.torque_Nm
                                 ? "commutation.csv"
                                 : "commutation_" + std::string(1, d.name.back()) + ".csv";
    stage.write_text(file, commutation_csv(r, d));
    const PowerStats s = power_stats(d);
    nlohmann::ordered_json e;
    e["torque_Nm"] = {d.torque_Nm.x(), d.torque_Nm.y(), d.torque_Nm.z()};
    e["file"] = file;
    e["P_avg_W"] = s.avg;
    e["P_max_W"] = s.max;
    e["P_min_W"] = s.min;
    e["P_max_at_deg"] = orientation_json(r, s.at_max);
    e["P_min_at_deg"] = orientation_json(r, s.at_min);
    e["n_ill_conditioned"] = s.n_ill;
    j[d.name] = e;
    for (std::size_t i = 0; i < d.commutations.size(); ++i)
      if (!d.commutations[i].ok)
        warnings.push_back(d.name + " at (" + angles(r.orientations[i]) +
                           ") deg: " + d.commutations[i].warning);
  }
  if (!options.torque_Nm) {
    double avg = 0;
    for (const auto& d : r.demands)
      avg += power_stats(d).avg / 3;
    j["P_xyz_avg_W"] = avg;
  }
  if (options.verify) {
    j["verification"] = nlohmann::ordered_json::array();
    for (const auto& v : verification) {
      nlohmann::ordered_json e;
      e["demand"] = v.demand;
      e["rx_deg"] = v.orientation.rx_deg;
      e["ry_deg"] = v.orientation.ry_deg;
      e["rz_deg"] = v.orientation.rz_deg;
      e["demanded_Nm"] = {v.demanded_Nm.x(), v.demanded_Nm.y(), v.demanded_Nm.z()};
      if (v.ok)
        e["produced_Nm"] = {v.produced_Nm.x(), v.produced_Nm.y(), v.produced_Nm.z()};
      else
        e["produced_Nm"] = nullptr;
      if (std::isfinite(v.produced_error_Nm))
        e["produced_error_estimate_Nm"] = v.produced_error_Nm; // of |produced_Nm|
      if (v.adapt.passes)
        e["adapt"] = position_adapt_summary(v.adapt);
      if (v.ok && v.adapt.passes && !v.adapt.converged) {
        char line[200];
        std::snprintf(line, sizeof line,
                      "verify %s at (%s) deg: adaptive refinement stopped after %d pass(es) "
                      "before reaching its accuracy (estimated error %.3g %%)",
                      v.demand.c_str(), angles(v.orientation).c_str(), v.adapt.passes,
                      v.adapt.error_pct);
        warnings.push_back(line);
      }
      j["verification"].push_back(e);
    }
  }
  stage.write_text("torque_constants.csv", torque_constants_csv(r));
  // Plotted outside the stage and copied in only if gnuplot made it: a registered name that is
  // never written would fail the commit.
  std::string why;
  const auto scratch = std::filesystem::temp_directory_path() /
                       ("magfem_power_map_" + std::to_string(::getpid()) + ".png");
  const bool plotted = plot_power_map(r, spec.file + " (" + r.method + ")", scratch, why);
  if (plotted) {
    std::filesystem::copy_file(scratch, stage.path_for("power_map.png"),
                               std::filesystem::copy_options::overwrite_existing);
    std::filesystem::remove(scratch);
  }
  if (!plotted)
    std::cerr << "magfem: note: no power_map.png: " << why << "\n";
  j["notes"] = r.notes;
  j["warnings"] = warnings;
  j["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  stage.write_text("summary.json", j.dump(2) + "\n");
  stage.commit();

  std::printf("%zu orientations x %zu coils, torque constants by %s in %.2f s (%d field %s)\n",
              r.orientations.size(), r.coil_names.size(), r.method.c_str(), r.gamma_seconds,
              r.n_field_solves, r.n_field_solves == 1 ? "solve" : "solves");
  for (const auto& d : r.demands) {
    const PowerStats s = power_stats(d);
    std::printf("%-4s T_d (%g, %g, %g) N m: P avg %.4g W, max %.4g W, min %.4g W", d.name.c_str(),
                d.torque_Nm.x(), d.torque_Nm.y(), d.torque_Nm.z(), s.avg, s.max, s.min);
    if (s.n_ill)
      std::printf(", %d ill-conditioned", s.n_ill);
    std::printf("\n");
  }
  for (const auto& v : verification)
    if (v.ok)
      std::printf("verify   %s at (%g, %g, %g) deg: demanded (%.4g, %.4g, %.4g), FE produced "
                  "(%.4g, %.4g, %.4g) N m%s\n",
                  v.demand.c_str(), v.orientation.rx_deg, v.orientation.ry_deg,
                  v.orientation.rz_deg, v.demanded_Nm.x(), v.demanded_Nm.y(), v.demanded_Nm.z(),
                  v.produced_Nm.x(), v.produced_Nm.y(), v.produced_Nm.z(),
                  verified_error_text(v).c_str());
  for (const auto& w : warnings)
    std::cerr << "magfem: warning: " << w << "\n";
  std::printf("wrote    %s/summary.json, torque_constants.csv, commutation%s.csv%s\n",
              options.out_dir.c_str(), options.torque_Nm ? "" : "_{x,y,z}",
              plotted ? ", power_map.png" : "");
  std::fflush(stdout);
  return code_of_root(0);
}

} // namespace magfem
