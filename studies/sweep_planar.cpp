#include "studies/sweep_planar.hpp"

#include <cmath>

#include "core/constants.hpp"
#include "core/input_error.hpp"
#include "pipeline/run2d.hpp"
#include "studies/position_runner.hpp"

namespace magfem {
namespace {

const std::string cli = "<command line>";

// Turns a point of the plane about c by the rotation R.
struct Turn {
  Eigen::Rotation2Dd R;
  Vec2 c;
  Vec2 at(const Vec2& x) const { return c + R * (x - c); }
  void operator()(Disk& s) const { s.center = at(s.center); }
  void operator()(Annulus& s) const { s.center = at(s.center); }
  void operator()(AnnularSector& s) const {
    s.center = at(s.center);
    s.angle_start += R.angle();
    s.angle_end += R.angle();
  }
  void operator()(Rectangle& s) const {
    s.center = at(s.center);
    s.rotation += R.angle();
  }
  void operator()(Polygon& s) const {
    for (Vec2& v : s.vertices)
      v = at(v);
  }
};

// The force request on the group (see the header), with the torque about the point.
ForceSpec group_force(const CaseSpec& spec, const std::string& group, const Vec3& point) {
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
    throw InputError(cli, 0, "--rotate",
                     "group '" + group + "' of " + spec.file +
                         " carries no current and the case has no `band` or `circle` force "
                         "around it: add one, e.g. forces: [{name: rotor, type: band, center: "
                         "[0, 0], r_inner: R1, r_outer: R2}] in the air gap");
  f.torque_point = point;
  return f;
}

void solve_position(SweepRow& row, const CaseSpec& base, const SweepOptions& o, double angle_deg) {
  row.angle_deg = angle_deg;
  row.method = "planar";
  CaseSpec spec = rotate_group_planar(base, o.group, angle_deg * deg_to_rad, o.point);
  const ForceSpec f = group_force(spec, o.group, o.point);
  row.method = f.kind == ForceSpec::Kind::lorentz ? "lorentz"
               : f.kind == ForceSpec::Kind::band  ? "arkkio_band"
                                                  : "stress_circle";
  spec.forces = {f};
  spec.probes.clear(); // a sweep wants the force only
  spec.write_vtu = false;
  RunOverrides ov;
  ov.order = o.order;
  ov.mesh_scale = o.mesh_scale;
  const auto run = run_case_2d(std::move(spec), ov);
  row.torque = run->forces.front().torque;
  row.force = run->forces.front().force;
  row.unknowns = static_cast<long>(run->dofs->n_dofs());
}

} // namespace

CaseSpec rotate_group_planar(const CaseSpec& spec, const std::string& group, double angle_rad,
                             const Eigen::Vector3d& point) {
  if (spec.dimension != 2 || spec.axisymmetric())
    throw InputError(cli, 0, "--rotate", "this sweep turns groups of planar 2D cases");
  const Turn turn{Eigen::Rotation2Dd(angle_rad), point.head<2>()};
  const Eigen::Matrix3d R3 = Eigen::AngleAxisd(angle_rad, Eigen::Vector3d::UnitZ()).matrix();
  CaseSpec out = spec;
  bool found = false;
  for (std::size_t i = 0; i < out.regions.size(); ++i) {
    if (out.regions[i].group != group)
      continue;
    found = true;
    std::visit(turn, out.geometry2d.parts[i].shape);
    Magnetization& m = out.regions[i].magnetization;
    m.direction = R3 * m.direction;
    m.center.head<2>() = turn.at(m.center.head<2>());
  }
  if (!found)
    throw InputError(cli, 0, "--rotate",
                     "no region of " + spec.file + " is in group '" + group + "'");
  // A stress circle or band around the group turns with it (it stays put when centred on
  // the point, the usual rotor).
  for (auto& f : out.forces)
    if (f.kind == ForceSpec::Kind::circle || f.kind == ForceSpec::Kind::band)
      f.center.head<2>() = turn.at(f.center.head<2>());
  return out;
}

std::vector<SweepRow> run_sweep_planar(const CaseSpec& spec, const SweepOptions& o,
                                       const SweepProgress& progress, SweepJobs* jobs) {
  if ((o.axis.normalized() - Eigen::Vector3d::UnitZ()).norm() > 1e-12)
    throw InputError(cli, 0, "--axis", "a planar 2D case turns about z only");
  if (o.analytic)
    throw InputError(cli, 0, "--analytic", "planar 2D sweeps are FE only");
  if (o.surface_radius)
    throw InputError(cli, 0, "--surface-radius",
                     "planar 2D sweeps take the case's band or circle force");
  // Mistakes every position would repeat fail here, on the main thread.
  group_force(rotate_group_planar(spec, o.group, 0.0, o.point), o.group, o.point);
  const int total = static_cast<int>(o.angles_deg.size());
  const int workers = default_position_workers(o.world, o.jobs, total);
  if (jobs)
    jobs->requested = jobs->used = workers;
  return run_positions<SweepRow>(
      o.angles_deg, workers, o.checkpoint, {sweep_row_to_json, sweep_row_from_json, {}},
      [&](SweepRow& row, double angle_deg) { solve_position(row, spec, o, angle_deg); }, progress,
      o.world, o.stop);
}

} // namespace magfem
