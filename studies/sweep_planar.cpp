#include "studies/sweep_planar.hpp"

#include <cmath>

#include "core/constants.hpp"
#include "core/input_error.hpp"
#include "pipeline/run2d.hpp"
#include "pipeline/solve_case.hpp"
#include "studies/group_motion2d.hpp"
#include "studies/position_memory.hpp"
#include "studies/position_runner.hpp"

namespace magfem {
namespace {

const std::string cli = "<command line>";

// The force request on the group (see the header), with the torque about the point.
ForceSpec group_force(const CaseSpec& spec, const std::string& group, const Vec3& point,
                      const std::string& option) {
  ForceSpec f;
  f.name = "sweep";
  f.kind = ForceSpec::Kind::lorentz;
  for (const auto& r : spec.regions)
    if (r.group == group && r.carries_current())
      f.regions.push_back(r.name);
  if (f.regions.empty()) {
    for (const auto kind : {ForceSpec::Kind::band, ForceSpec::Kind::circle}) {
      std::vector<const ForceSpec*> found;
      for (const auto& c : spec.forces)
        if (c.kind == kind)
          found.push_back(&c);
      if (found.size() > 1)
        throw InputError(spec.file, found[1]->line, "forces",
                         "two " + std::string(kind == ForceSpec::Kind::band ? "band" : "circle") +
                             " forces: the sweep takes the force on group '" + group +
                             "' from one; keep one");
      if (found.size() == 1) {
        f = *found.front();
        break;
      }
    }
  }
  if (f.kind == ForceSpec::Kind::lorentz && f.regions.empty())
    throw InputError(cli, 0, option,
                     "group '" + group + "' of " + spec.file +
                         " carries no current and the case has no `band` or `circle` force "
                         "around it: add one, e.g. forces: [{name: rotor, type: band, center: "
                         "[0, 0], r_inner: R1, r_outer: R2}] in the air gap");
  f.torque_point = point;
  return f;
}

const char* option_of(SweepMotion motion) {
  return motion == SweepMotion::rotate ? "--rotate" : "--move";
}

// The case carried by `motion` (see move_group2d), with the stress circles and bands: they
// surround the group (the header), so they go with it; a rotor's band, centred on the point
// of its turn, stays put.
CaseSpec carry_group(const CaseSpec& spec, const std::string& group, const RigidMotion2D& motion,
                     const std::string& option) {
  if (spec.dimension != 2 || spec.axisymmetric())
    throw InputError(cli, 0, option, "this sweep moves groups of planar 2D cases");
  CaseSpec out = move_group2d(spec, group, motion, option);
  for (auto& f : out.forces)
    if (f.kind == ForceSpec::Kind::circle || f.kind == ForceSpec::Kind::band)
      f.center.head<2>() = motion.at(f.center.head<2>());
  return out;
}

// One position (degrees or mm, as sweep_positions gives them): the carried case and the
// point the torque is taken about, the sweep's point carried with the group (a translated
// magnet's torque about its own centre stays about its centre).
struct PlanarPosition {
  CaseSpec spec;
  Vec3 point;
};

PlanarPosition planar_position(const CaseSpec& base, const SweepOptions& o, double position) {
  if (o.motion == SweepMotion::rotate)
    return {rotate_group_planar(base, o.group, position * deg_to_rad, o.point), o.point};
  const Vec3 d = 1e-3 * position * o.axis.normalized();
  return {translate_group_planar(base, o.group, d), o.point + d};
}

// The case one position solves: carried, with the group's force alone (a sweep wants the
// force only: no probes, no VTU) and an `adapt:` aimed at it; its force kind names the method.
CaseSpec position_case(const CaseSpec& base, const SweepOptions& o, double position) {
  auto [spec, point] = planar_position(base, o, position);
  spec.forces = {group_force(spec, o.group, point, option_of(o.motion))};
  spec.probes.clear();
  spec.write_vtu = false;
  aim_adapt_at(spec, spec.forces.front().name, sweep_output(o.motion));
  return spec;
}

void solve_position(SweepRow& row, const CaseSpec& base, const SweepOptions& o,
                    const RunOverrides& fe, double position) {
  row.angle_deg = position;
  row.method = "planar";
  CaseSpec spec = position_case(base, o, position);
  const ForceSpec::Kind kind = spec.forces.front().kind;
  row.method = kind == ForceSpec::Kind::lorentz ? "lorentz"
               : kind == ForceSpec::Kind::band  ? "arkkio_band"
                                                : "stress_circle";
  const auto run = solve_case_2d(std::move(spec), fe);
  row.torque = run->forces.front().torque;
  row.force = run->forces.front().force;
  row.unknowns = static_cast<long>(run->dofs->n_dofs());
  row.adapt = position_adapt(run->adapt);
}

} // namespace

CaseSpec rotate_group_planar(const CaseSpec& spec, const std::string& group, double angle_rad,
                             const Eigen::Vector3d& point) {
  RigidMotion2D turn;
  turn.angle_rad = angle_rad;
  turn.center = point.head<2>();
  return carry_group(spec, group, turn, "--rotate");
}

CaseSpec translate_group_planar(const CaseSpec& spec, const std::string& group,
                                const Eigen::Vector3d& displacement) {
  RigidMotion2D shift;
  shift.shift = displacement.head<2>();
  return carry_group(spec, group, shift, "--move");
}

std::vector<SweepRow> run_sweep_planar(const CaseSpec& spec, const SweepOptions& o,
                                       const SweepProgress& progress, SweepJobs* jobs) {
  const Vec3 axis = o.axis.normalized();
  if (o.motion == SweepMotion::rotate && (axis - Vec3::UnitZ()).norm() > 1e-12)
    throw InputError(cli, 0, "--axis", "a planar 2D case turns about z only");
  if (o.motion == SweepMotion::translate && std::abs(axis.z()) > 1e-12)
    throw InputError(cli, 0, "--axis",
                     "a planar 2D group moves in its plane: x, y or a direction dx,dy");
  if (o.analytic)
    throw InputError(cli, 0, "--analytic", "planar 2D sweeps are FE only");
  if (o.surface_radius)
    throw InputError(cli, 0, "--surface-radius",
                     "planar 2D sweeps take the case's band or circle force");
  // Mistakes every position would repeat fail here, on the main thread.
  const PlanarPosition at_rest = planar_position(spec, o, 0.0);
  group_force(at_rest.spec, o.group, at_rest.point, option_of(o.motion));
  const std::vector<double> positions = sweep_positions(o);
  const int total = static_cast<int>(positions.size());
  RunOverrides fe;
  fe.order = o.order;
  fe.mesh_scale = o.mesh_scale;
  fe.max_memory_gb = o.max_memory_gb;
  int workers = default_position_workers(o.world, o.jobs, total);
  if (total > 0)
    workers = plan_positions_2d(position_case(spec, o, positions.front()), fe, workers, o.world,
                                o.jobs, jobs);
  else if (jobs)
    jobs->requested = jobs->used = workers;
  return run_positions<SweepRow>(
      positions, workers, o.checkpoint, {sweep_row_to_json, sweep_row_from_json, {}},
      [&](SweepRow& row, double position) { solve_position(row, spec, o, fe, position); }, progress,
      o.world, o.stop);
}

} // namespace magfem
