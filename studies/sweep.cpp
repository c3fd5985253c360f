#include "studies/sweep.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "analytic/axisymmetric_interaction.hpp"
#include "analytic/exterior_field_interaction.hpp"
#include "analytic/pair_interaction.hpp"
#include "core/constants.hpp"
#include "core/input_error.hpp"
#include "mesh/mesh_error.hpp"
#include "pipeline/analytic_scene.hpp"
#include "pipeline/force3d.hpp"
#include "pipeline/memory_guard.hpp"
#include "pipeline/run3d.hpp"
#include "pipeline/run_checkpoint.hpp"
#include "pipeline/solve_case.hpp"
#include "studies/position_mesh_warnings.hpp"
#include "studies/position_runner.hpp"

namespace magfem {
namespace {

const std::string cli = "<command line>";

bool in_group(const Part3D& part, const std::string& group) {
  return part.group == group;
}

// Radial range [min, max] about the origin of a part, from its surface sampled on a fine grid
// in the local frame. Sampling can only miss the extreme by about one grid step, which the
// margin covers. Exact for spherical segments centred on the origin.
// Distances from the origin that a coil's bundle spans (conservative for off-centre coils).
std::pair<double, double> coil_radial_range(const Coil3D& coil) {
  const double c = coil.placement.translation.norm();
  if (const auto* s = std::get_if<SphericalCoil>(&coil.shape); s && c == 0)
    return {s->r_inner, s->r_outer};
  double reach = 0;
  if (const auto* s = std::get_if<SphericalCoil>(&coil.shape))
    reach = s->r_outer;
  else if (const auto* s = std::get_if<Solenoid>(&coil.shape))
    reach = std::hypot(s->r_outer, 0.5 * s->length);
  else if (const auto* s = std::get_if<Racetrack>(&coil.shape))
    reach = std::hypot(std::hypot(0.5 * s->straight_x + s->inner_radius + s->width,
                                  0.5 * s->straight_y + s->inner_radius + s->width),
                       0.5 * s->height);
  return {std::max(0.0, c - reach), c + reach};
}

std::pair<double, double> radial_range(const Part3D& part) {
  if (const auto* seg = std::get_if<SphericalSegment>(&part.shape))
    if (part.placement.translation.norm() == 0)
      return {seg->r_inner, seg->r_outer};
  std::vector<Vec3> local;
  constexpr int n = 48;
  std::visit(
      [&](const auto& s) {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, SphericalSegment>) {
          for (double r : {s.r_inner, s.r_outer})
            for (int i = 0; i <= n; ++i)
              for (int j = 0; j <= n; ++j) {
                const double t = s.theta_min + (s.theta_max - s.theta_min) * i / n;
                const double p = s.phi_min + (s.phi_max - s.phi_min) * j / n;
                local.emplace_back(r * std::sin(t) * std::cos(p), r * std::sin(t) * std::sin(p),
                                   r * std::cos(t));
              }
          for (int i = 0; i <= n; ++i) // the flat faces reach inward along every ray
            for (int k = 0; k <= n; ++k) {
              const double r = s.r_inner + (s.r_outer - s.r_inner) * k / n;
              const double t = s.theta_min + (s.theta_max - s.theta_min) * i / n;
              local.emplace_back(r * std::sin(t) * std::cos(s.phi_min),
                                 r * std::sin(t) * std::sin(s.phi_min), r * std::cos(t));
            }
        } else if constexpr (std::is_same_v<T, Cylinder>) {
          for (double r : {s.r_inner, s.r_outer})
            for (int i = 0; i <= n; ++i)
              for (int j = 0; j < n; ++j) {
                const double p = 2 * pi * j / n;
                local.emplace_back(r * std::cos(p), r * std::sin(p), s.height * i / n);
              }
          for (double z : {0.0, s.height})
            for (int k = 0; k <= n; ++k)
              for (int j = 0; j < n; ++j) {
                const double r = s.r_inner + (s.r_outer - s.r_inner) * k / n, p = 2 * pi * j / n;
                local.emplace_back(r * std::cos(p), r * std::sin(p), z);
              }
        } else if constexpr (std::is_same_v<T, TriangleSurface>) {
          // Corners and centroids: the closest point of a large facet may lie between them,
          // which the margin below covers only for facets under extent / n across.
          local = s.points;
          for (const auto& t : s.triangles)
            local.push_back((s.points[t[0]] + s.points[t[1]] + s.points[t[2]]) / 3);
        } else {
          for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= n; ++j)
              for (int k = 0; k <= n; ++k)
                if (i == 0 || i == n || j == 0 || j == n || k == 0 || k == n)
                  local.emplace_back(s.size.x() * (double(i) / n - 0.5),
                                     s.size.y() * (double(j) / n - 0.5),
                                     s.size.z() * (double(k) / n - 0.5));
        }
      },
      part.shape);
  double lo = std::numeric_limits<double>::max(), hi = 0, extent = 0;
  for (const auto& x : local) {
    const double r = part.placement.to_global(x).norm();
    lo = std::min(lo, r), hi = std::max(hi, r), extent = std::max(extent, x.norm());
  }
  const double margin = extent / n;
  return {std::max(0.0, lo - margin), hi + margin};
}

std::vector<double> parse_list(const std::string& option, const std::string& text, char sep) {
  std::vector<double> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, sep)) {
    try {
      std::size_t used = 0;
      out.push_back(std::stod(item, &used));
      if (used != item.size())
        throw std::invalid_argument(item);
    } catch (const std::exception&) {
      throw InputError(cli, 0, option, "expected a number, got '" + item + "' in '" + text + "'");
    }
  }
  return out;
}

// The harmonic-form interaction if the magnets qualify (concentric axisymmetric bodies,
// groups separated by a sphere), otherwise nothing: the caller falls back to the charge
// interaction by face pairs (analytic/pair_interaction.hpp), which covers any arrangement.
std::optional<AxisymmetricInteraction> harmonic_position(const std::vector<AnalyticMagnet>& group,
                                                         const std::vector<AnalyticMagnet>& rest) {
  try {
    return axisymmetric_interaction(group, rest);
  } catch (const std::invalid_argument&) {
    return std::nullopt; // not covered
  } catch (const std::domain_error&) {
    return std::nullopt; // gap too thin for the series
  }
}

// Magnets of any shape around (or inside) concentric axisymmetric bodies that a sphere
// separates from them: the exterior harmonic field of the bodies at the charges of the others
// (analytic/exterior_field_interaction.hpp). Force and torque on `group`, or nothing.
std::optional<ExteriorFieldInteraction> exterior_position(const std::vector<AnalyticMagnet>& group,
                                                          const std::vector<AnalyticMagnet>& rest,
                                                          const Vec3& torque_point,
                                                          double tolerance) {
  ExteriorFieldOptions o;
  o.tolerance = tolerance;
  for (const bool group_outside : {true, false}) {
    try {
      ExteriorFieldInteraction r = group_outside
                                       ? exterior_field_interaction(group, rest, torque_point, o)
                                       : exterior_field_interaction(rest, group, torque_point, o);
      if (!group_outside) // action = reaction, torques about the same point
        r.on.force = -r.on.force, r.on.torque = -r.on.torque;
      return r;
    } catch (const std::invalid_argument&) {
      // not this way round
    } catch (const std::domain_error&) {
      // the charges come too close to the sphere for the series
    }
  }
  return std::nullopt;
}

// The FE overrides of every position (the memory guard's sharing is set by run_sweep).
RunOverrides fe_overrides(const SweepOptions& o) {
  RunOverrides ov;
  ov.order = o.order;
  ov.mesh_scale = o.mesh_scale;
  ov.max_memory_gb = o.max_memory_gb;
  ov.say_mesh_warnings = false; // once for the sweep, with the positions (sweep_warnings)
  return ov;
}

// What FE solves at one position: the rotated case with the stress sphere of `surface`, and
// no probes or VTU (a sweep wants forces only).
CaseSpec fe_position_case(CaseSpec spec, const StressSurface& surface) {
  spec.probes.clear();
  spec.write_vtu = false;
  return with_stress_sphere(std::move(spec), surface.radius, "sweep");
}

// Force and torque (about sweep_torque_point) on the moved group at one position.
void solve_position(SweepRow& row, const CaseSpec& base, const SweepOptions& o,
                    const RunOverrides& fe, double angle_deg) {
  row.angle_deg = angle_deg;
  CaseSpec spec = move_group(base, o, angle_deg);
  const Vec3 point = sweep_torque_point(o, angle_deg);
  ForceResult on_group;
  if (o.analytic) {
    const AnalyticScene scene = analytic_scene(spec);
    if (!scene.spheres.empty())
      throw InputError(spec.file, 0, "regions",
                       "sweep --analytic: the charge interaction has no permeable boundaries");
    std::vector<AnalyticMagnet> group, rest;
    for (const auto& m : scene.magnets) {
      bool member = false;
      for (const auto& p : spec.geometry3d.parts)
        if (p.name == m.name)
          member = in_group(p, o.group);
      (member ? group : rest).push_back(m);
    }
    if (auto harmonic = harmonic_position(group, rest)) {
      // About the origin: moved to the point by T_P = T_0 - P x F, and the force's bound
      // with it.
      on_group.force = harmonic->force;
      on_group.torque = harmonic->torque - point.cross(harmonic->force);
      row.method = "harmonic_interaction";
      row.n_max = harmonic->n_max;
      row.torque_bound = harmonic->torque_bound + point.norm() * harmonic->force_bound;
      row.force_bound = harmonic->force_bound;
    } else if (auto ext = exterior_position(group, rest, point, o.analytic_tolerance)) {
      on_group.force = ext->on.force;
      on_group.torque = ext->on.torque;
      row.method = "exterior_field_interaction";
      row.torque_bound = ext->torque_error;
      row.force_bound = ext->force_error;
    } else {
      PairInteractionOptions popt;
      popt.tolerance = o.analytic_tolerance;
      const PairInteraction p = pair_interaction(group, rest, point, popt);
      on_group.force = p.on_A.force;
      on_group.torque = p.on_A.torque;
      row.method = "charge_pair_interaction";
      row.torque_bound = p.torque_error;
      row.force_bound = p.force_error;
    }
  } else {
    const StressSurface surface = stress_surface(spec, o.group, o.surface_radius);
    CaseSpec position = fe_position_case(std::move(spec), surface);
    position.forces.back().torque_point = point;
    // An adaptive sweep refines each position for what the sweep reports: the torque of a
    // rotation, the force of a translation (the case's own quantities may name forces or
    // probes a sweep does not compute).
    aim_adapt_at(position, "sweep", sweep_output(o.motion));
    const auto run = solve_case_3d(std::move(position), fe);
    const ForceResult& inside = run->forces.back();
    // Newton's third law: what acts on the contents of the sphere acts, reversed, on the
    // rest of the (isolated) system, torque about the same point included.
    on_group = inside;
    if (surface.group_outside)
      on_group.force = -inside.force, on_group.torque = -inside.torque;
    row.unknowns = static_cast<long>(run->dofs->n_dofs());
    row.method = "maxwell_stress_sphere";
    if (inside.estimated)
      row.torque_bound = inside.torque_err.norm(), row.force_bound = inside.force_err.norm();
    row.adapt = position_adapt(run->adapt);
    row.mesh_warnings = run->mesh.warnings;
  }
  row.force = on_group.force;
  row.torque = on_group.torque;
}

// FE positions share the memory guard's limit (studies/position_memory.hpp), from the first
// position's estimate. A first position that cannot be estimated (a bad part) is left to fail
// as a position, with its message.
void plan_jobs(const CaseSpec& spec, const SweepOptions& o, const std::vector<double>& angles,
               SweepJobs& jobs) {
  if (o.analytic || jobs.requested * o.world.size_on_node < 2)
    return;
  try {
    const CaseSpec first = move_group(spec, o, angles.front());
    jobs.position_memory_mb = estimated_memory_mb_3d(
        fe_position_case(first, stress_surface(first, o.group, o.surface_radius)), fe_overrides(o));
  } catch (const std::exception&) {
    return;
  }
  fit_jobs_to_memory(jobs, o.max_memory_gb, o.world, o.jobs);
}

} // namespace

CaseSpec rotate_group(const CaseSpec& spec, const std::string& group, const Eigen::Vector3d& axis,
                      double angle_rad, const Eigen::Vector3d& point) {
  if (spec.dimension != 3)
    throw InputError(spec.file, 0, "dimension", "sweeps rotate 3D groups; this case is 2D");
  CaseSpec out = spec;
  const Mat3 r = Eigen::AngleAxisd(angle_rad, axis.normalized()).toRotationMatrix();
  bool found = false;
  for (std::size_t i = 0; i < out.geometry3d.parts.size(); ++i) {
    auto& part = out.geometry3d.parts[i];
    if (!in_group(part, group))
      continue;
    found = true;
    part.placement = part.placement.rotated(axis, angle_rad, point);
    out.regions[i].magnetization = out.regions[i].magnetization.rotated(r, point);
  }
  for (auto& coil : out.geometry3d.coils)
    if (coil.group == group) {
      found = true;
      coil.placement = coil.placement.rotated(axis, angle_rad, point);
    }
  if (!found) {
    std::string groups;
    for (const auto& p : spec.geometry3d.parts)
      if (!p.group.empty() && groups.find("'" + p.group + "'") == std::string::npos)
        groups += (groups.empty() ? "" : ", ") + ("'" + p.group + "'");
    throw InputError(cli, 0, "--rotate",
                     "no part of " + spec.file + " is in group '" + group +
                         "' (groups: " + (groups.empty() ? std::string("none") : groups) + ")");
  }
  return out;
}

CaseSpec translate_group(const CaseSpec& spec, const std::string& group,
                         const Eigen::Vector3d& displacement) {
  if (spec.dimension != 3)
    throw InputError(cli, 0, "--move", "this sweep translates groups of 3D cases");
  CaseSpec out = spec;
  bool found = false;
  for (std::size_t i = 0; i < out.geometry3d.parts.size(); ++i) {
    auto& part = out.geometry3d.parts[i];
    if (!in_group(part, group))
      continue;
    found = true;
    part.placement.translation += displacement;
    out.regions[i].magnetization.center += displacement;
  }
  for (auto& coil : out.geometry3d.coils)
    if (coil.group == group)
      found = true, coil.placement.translation += displacement;
  if (!found)
    throw InputError(cli, 0, "--move", "no part of " + spec.file + " is in group '" + group + "'");
  return out;
}

std::vector<double> sweep_positions(const SweepOptions& o) {
  if (o.motion == SweepMotion::rotate)
    return o.angles_deg;
  std::vector<double> mm;
  for (const double d : o.offsets_m)
    mm.push_back(1e3 * d);
  return mm;
}

CaseSpec move_group(const CaseSpec& spec, const SweepOptions& o, double position) {
  if (o.motion == SweepMotion::rotate)
    return rotate_group(spec, o.group, o.axis, position * deg_to_rad, o.point);
  return translate_group(spec, o.group, 1e-3 * position * o.axis.normalized());
}

std::string sweep_checkpoint_options(const SweepOptions& o, const std::string& axis,
                                     const std::string& point, const std::string& surface_radius) {
  return o.group + " axis " + axis + " point " + point + " surface-radius " + surface_radius +
         (o.analytic ? " analytic" : " fe") + " order " + std::to_string(o.order) + " mesh-scale " +
         RunCheckpoint::mesh_scale_key(o.mesh_scale);
}

Eigen::Vector3d sweep_torque_point(const SweepOptions& o, double position) {
  if (o.motion != SweepMotion::translate || !o.carry_point)
    return Vec3::Zero();
  return o.point + 1e-3 * position * o.axis.normalized();
}

std::string sweep_position_key(SweepMotion motion) {
  return motion == SweepMotion::rotate ? "angle_deg" : "position_mm";
}

StressSurface stress_surface(const CaseSpec& spec, const std::string& group,
                             std::optional<double> radius) {
  double group_lo = std::numeric_limits<double>::max(), group_hi = 0;
  double rest_lo = std::numeric_limits<double>::max(), rest_hi = 0;
  for (std::size_t i = 0; i < spec.geometry3d.parts.size(); ++i) {
    const auto& part = spec.geometry3d.parts[i];
    if (spec.regions[i].material->kind == MaterialKind::linear &&
        spec.regions[i].material->mu_r == 1.0 && !in_group(part, group))
      continue; // air regions (mesh aids) do not feel forces
    const auto [lo, hi] = radial_range(part);
    if (in_group(part, group))
      group_lo = std::min(group_lo, lo), group_hi = std::max(group_hi, hi);
    else
      rest_lo = std::min(rest_lo, lo), rest_hi = std::max(rest_hi, hi);
  }
  for (const auto& coil : spec.geometry3d.coils) {
    const auto [lo, hi] = coil_radial_range(coil);
    if (coil.group == group)
      group_lo = std::min(group_lo, lo), group_hi = std::max(group_hi, hi);
    else
      rest_lo = std::min(rest_lo, lo), rest_hi = std::max(rest_hi, hi);
  }
  StressSurface s;
  if (group_lo >= rest_hi)
    s = {0.5 * (group_lo + rest_hi), true};
  else if (rest_lo >= group_hi)
    s = {0.5 * (rest_lo + group_hi), false};
  else
    throw InputError(cli, 0, "--rotate",
                     "group '" + group +
                         "' and the other parts are not separated by a sphere about the origin; "
                         "the Maxwell stress tensor needs one in air between them");
  if (radius) {
    const double r = *radius;
    const bool outside = s.group_outside;
    const bool fits = outside ? (r > rest_hi && r < group_lo) : (r > group_hi && r < rest_lo);
    if (!fits)
      throw InputError(cli, 0, "--surface-radius",
                       "the sphere must lie in the air between the group and the rest");
    s.radius = r;
  }
  return s;
}

std::vector<double> parse_angle_list(const std::string& text, const std::string& option) {
  if (text.find(':') != std::string::npos) {
    const auto v = parse_list(option, text, ':');
    if (v.size() != 3 || !(v[1] > 0) || v[2] < v[0])
      throw InputError(cli, 0, option, "expected START:STEP:END with STEP > 0 and END >= START");
    std::vector<double> out;
    const int n = static_cast<int>(std::floor((v[2] - v[0]) / v[1] + 1e-9));
    for (int i = 0; i <= n; ++i)
      out.push_back(v[0] + i * v[1]);
    return out;
  }
  auto out = parse_list(option, text, ',');
  if (out.empty())
    throw InputError(cli, 0, option, "no values given");
  return out;
}

Eigen::Vector3d parse_vector3(const std::string& option, const std::string& text) {
  const auto v = parse_list(option, text, ',');
  if (v.size() != 3)
    throw InputError(cli, 0, option, "expected three numbers x,y,z");
  return Vec3(v[0], v[1], v[2]);
}

Eigen::Vector3d parse_axis(const std::string& text, bool planar) {
  if (text == "x")
    return Vec3::UnitX();
  if (text == "y")
    return Vec3::UnitY();
  if (text == "z")
    return Vec3::UnitZ();
  auto v = parse_list("--axis", text, ',');
  if (planar && v.size() == 2)
    v.push_back(0.0); // a direction in the plane
  if (v.size() != 3 || Vec3(v[0], v[1], v[2]).norm() == 0)
    throw InputError(cli, 0, "--axis",
                     planar ? "expected x, y, z or a non-zero vector ax,ay[,az]"
                            : "expected x, y, z or a non-zero vector ax,ay,az");
  return Vec3(v[0], v[1], v[2]).normalized();
}

nlohmann::json sweep_row_to_json(const SweepRow& r) {
  nlohmann::json j = {{"angle_deg", r.angle_deg},
                      {"torque", {r.torque.x(), r.torque.y(), r.torque.z()}},
                      {"force", {r.force.x(), r.force.y(), r.force.z()}},
                      {"seconds", r.seconds},
                      {"unknowns", r.unknowns},
                      {"method", r.method},
                      {"n_max", r.n_max},
                      {"torque_bound", r.torque_bound},
                      {"force_bound", r.force_bound}};
  add_position_adapt(j, r.adapt);
  if (!r.mesh_warnings.empty())
    j["mesh_warnings"] = r.mesh_warnings;
  return j;
}

SweepRow sweep_row_from_json(const nlohmann::json& j, double /*angle_deg: stored in j*/) {
  SweepRow r;
  r.angle_deg = j.at("angle_deg").get<double>();
  for (int k = 0; k < 3; ++k)
    r.torque[k] = j.at("torque").at(k).get<double>(),
    r.force[k] = j.at("force").at(k).get<double>();
  r.seconds = j.at("seconds").get<double>();
  r.unknowns = j.at("unknowns").get<long>();
  r.method = j.at("method").get<std::string>();
  r.n_max = j.at("n_max").get<int>();
  r.torque_bound = j.at("torque_bound").get<double>();
  r.force_bound = j.at("force_bound").get<double>();
  r.adapt = position_adapt_from_json(j);
  r.mesh_warnings = j.value("mesh_warnings", std::vector<std::string>{});
  r.ok = true;
  return r;
}

std::vector<SweepRow> run_sweep(const CaseSpec& spec, const SweepOptions& options,
                                const SweepProgress& progress, SweepJobs* jobs_used) {
  // Fail early, on the main thread, for mistakes that every position would repeat.
  (void)move_group(spec, options, 0.0);
  if (!options.analytic)
    (void)stress_surface(spec, options.group, options.surface_radius);
  else
    (void)analytic_scene(spec);

  // A position that alone needs more memory than the limit: every position would fail the
  // guard, so the sweep is bad input (exit 2, naming the --mesh-scale that fits), as for solve.
  // A first position the mesher rejects is left to fail as a position, with its message.
  const std::vector<double> positions = sweep_positions(options);
  if (!options.analytic && !positions.empty()) {
    const CaseSpec first = move_group(spec, options, positions.front());
    try {
      check_memory_3d(
          fe_position_case(first, stress_surface(first, options.group, options.surface_radius)),
          fe_overrides(options));
    } catch (const MeshError&) {
    }
  }

  const int total = static_cast<int>(positions.size());
  SweepJobs jobs;
  jobs.requested = default_position_workers(options.world, options.jobs, total);
  jobs.used = jobs.requested;
  plan_jobs(spec, options, positions, jobs);
  if (jobs_used)
    *jobs_used = jobs;
  const int workers = jobs.used;
  RunOverrides fe = fe_overrides(options);
  share_memory(fe, jobs, options.world);
  return run_positions<SweepRow>(
      positions, workers, options.checkpoint, {sweep_row_to_json, sweep_row_from_json, {}},
      [&](SweepRow& row, double angle_deg) { solve_position(row, spec, options, fe, angle_deg); },
      progress, options.world, options.stop);
}

std::string sweep_method(const std::vector<SweepRow>& rows, const SweepOptions& options) {
  std::string method;
  for (const auto& r : rows)
    if (r.ok && !r.method.empty())
      method = method.empty() || method == r.method ? r.method : "mixed";
  if (method.empty())
    method = options.analytic ? "charge_pair_interaction" : "maxwell_stress_sphere";
  return method;
}

std::vector<std::string> sweep_warnings(const std::vector<SweepRow>& rows,
                                        const SweepOptions& options) {
  std::vector<std::pair<double, std::vector<std::string>>> meshes;
  for (const auto& r : rows)
    if (r.ok) // every solved position: "k of n positions"
      meshes.emplace_back(r.angle_deg, r.mesh_warnings);
  std::vector<std::string> out = grouped_mesh_warnings(sweep_position_key(options.motion), meshes);
  for (const auto& r : rows)
    if (const std::string w =
            position_adapt_warning(sweep_position_key(options.motion), r.angle_deg, r.adapt);
        r.ok && !w.empty())
      out.push_back(w);
  return out;
}

std::string sweep_method_note(const std::vector<SweepRow>& rows, const SweepOptions& options) {
  const std::string method = sweep_method(rows, options);
  double peak = 0, bound = 0, force_peak = 0, force_bound = 0;
  int n_max = 0;
  for (const auto& r : rows)
    if (r.ok)
      peak = std::max(peak, r.torque.norm()), bound = std::max(bound, r.torque_bound),
      n_max = std::max(n_max, r.n_max), force_peak = std::max(force_peak, r.force.norm()),
      force_bound = std::max(force_bound, r.force_bound);
  char line[240];
  if (method == "maxwell_stress_sphere" && (bound > 0 || force_bound > 0)) {
    std::snprintf(line, sizeof line,
                  "method   maxwell_stress_sphere: estimated error up to %.2g N m in the torque "
                  "(%.2g of the peak), %.2g N in the force (%.2g of the peak)",
                  bound, peak > 0 ? bound / peak : 0.0, force_bound,
                  force_peak > 0 ? force_bound / force_peak : 0.0);
    return line;
  }
  if (method != "harmonic_interaction" && method != "charge_pair_interaction" &&
      method != "exterior_field_interaction")
    return "method   " + method;
  if (method != "harmonic_interaction")
    std::snprintf(line, sizeof line,
                  "method   %s: estimated torque error %.2g N m (%.2g of the peak)", method.c_str(),
                  bound, peak > 0 ? bound / peak : 0.0);
  else
    std::snprintf(line, sizeof line,
                  "method   harmonic_interaction: degrees <= %d, torque truncation bound %.2g N m "
                  "(%.2g of the peak)",
                  n_max, bound, peak > 0 ? bound / peak : 0.0);
  return line;
}

std::string sweep_csv(const std::vector<SweepRow>& rows, SweepMotion motion) {
  std::string out = sweep_position_key(motion) + ",Tx,Ty,Tz,Fx,Fy,Fz\n";
  char line[256];
  for (const auto& r : rows) {
    if (!r.ok)
      continue;
    std::snprintf(line, sizeof line, "%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g\n", r.angle_deg,
                  r.torque.x(), r.torque.y(), r.torque.z(), r.force.x(), r.force.y(), r.force.z());
    out += line;
  }
  return out;
}

nlohmann::ordered_json sweep_summary(const std::string& case_file,
                                     const std::vector<SweepRow>& rows, const SweepOptions& options,
                                     const SweepJobs& jobs) {
  nlohmann::ordered_json j;
  j["case"] = case_file;
  j["method"] = sweep_method(rows, options);
  j["group"] = options.group;
  if (options.motion == SweepMotion::translate)
    j["motion"] = "translate";
  j["axis"] = {options.axis.x(), options.axis.y(), options.axis.z()};
  if (options.motion == SweepMotion::translate && options.carry_point) // at position 0
    j["torque_point_m"] = {options.point.x(), options.point.y(), options.point.z()};
  const std::string key = sweep_position_key(options.motion);
  int failed = 0;
  for (const auto& r : rows) {
    nlohmann::ordered_json p = {{key, r.angle_deg}, {"ok", r.ok}, {"seconds", r.seconds}};
    if (r.unknowns)
      p["unknowns"] = r.unknowns;
    if (r.n_max) // harmonic interaction: the series' length and rigorous truncation bounds
      p["n_max"] = r.n_max, p["torque_bound_Nm"] = r.torque_bound,
      p["force_bound_N"] = r.force_bound;
    else if (r.torque_bound > 0 || r.force_bound > 0) // the other analytic forms, FE
      p["torque_error_estimate_Nm"] = r.torque_bound, p["force_error_estimate_N"] = r.force_bound;
    if (r.adapt.passes)
      p["adapt"] = position_adapt_summary(r.adapt);
    if (!r.ok)
      p["error"] = r.error, ++failed;
    j["positions"].push_back(p);
  }
  j["failed_positions"] = failed;
  const std::vector<std::string> warnings = sweep_warnings(rows, options);
  if (!warnings.empty())
    j["warnings"] = warnings;
  j["jobs"] = {{"requested", jobs.requested}, {"used", jobs.used}};
  // The memory estimate when this process's positions shared the limit (as a serial run
  // records it; under mpirun with one position at a time per process the file stays the
  // serial --jobs 1 one).
  if (jobs.position_memory_mb > 0 && jobs.requested > 1)
    j["jobs"]["estimated_position_memory_MB"] = jobs.position_memory_mb,
    j["jobs"]["memory_limit_MB"] = jobs.memory_limit_mb;
  return j;
}

} // namespace magfem
