#include "studies/sweep_axi.hpp"

#include <cstdio>

#include "core/input_error.hpp"
#include "pipeline/run2d.hpp"
#include "pipeline/run_checkpoint.hpp"
#include "pipeline/solve_case.hpp"
#include "studies/group_motion2d.hpp"
#include "studies/position_memory.hpp"
#include "studies/position_runner.hpp"

namespace magfem {
namespace {

const std::string cli = "<command line>";

bool in_group(const CaseSpec& spec, const std::string& region, const std::string& group) {
  for (const auto& r : spec.regions)
    if (r.name == region)
      return r.group == group;
  return false;
}

// The request that yields the force on the group, in this order: the Lorentz force on its
// current regions; the Lorentz force on the others' (then `reversed`: the group feels the
// reaction); the case's own `contour` force on a region of the group (a magnet or iron over a
// plate: the stress tensor on the revolved box around it, which moves with it, at the case's
// margin). Otherwise bad input that says which force entry to add.
ForceSpec group_force(const CaseSpec& spec, const std::string& group, bool& reversed) {
  ForceSpec f;
  f.name = "sweep";
  f.kind = ForceSpec::Kind::lorentz;
  std::vector<std::string> others;
  for (const auto& r : spec.regions) {
    if (!r.carries_current())
      continue;
    (r.group == group ? f.regions : others).push_back(r.name);
  }
  reversed = f.regions.empty() && !others.empty();
  if (reversed)
    f.regions = others;
  if (!f.regions.empty())
    return f;
  std::vector<const ForceSpec*> contours;
  for (const auto& c : spec.forces)
    if (c.kind == ForceSpec::Kind::contour && in_group(spec, c.regions.front(), group))
      contours.push_back(&c);
  if (contours.size() == 1)
    return *contours.front();
  if (contours.empty())
    throw InputError(cli, 0, "--move",
                     "no region carries current and no `contour` force of " + spec.file +
                         " is on a region of group '" + group +
                         "': add one, e.g. forces: [{name: F, type: contour, region: NAME, "
                         "margin: M}] with M inside the air around it, and the sweep takes "
                         "the stress-tensor force on it");
  throw InputError(spec.file, contours[1]->line, "forces",
                   "two `contour` forces are on regions of group '" + group +
                       "' and no region carries current: keep one for the sweep");
}

} // namespace

std::string sweep_axi_method(const CaseSpec& spec, const std::string& group) {
  bool reversed = false;
  const ForceSpec f = group_force(spec, group, reversed);
  if (f.kind == ForceSpec::Kind::contour)
    return "stress_tensor_contour";
  return reversed ? "lorentz_reaction" : "lorentz";
}

namespace {

// The case one position solves: moved, with the group's force alone (a sweep wants the force
// only: no probes, no VTU) and an `adapt:` aimed at its Fz; `reversed` as group_force says.
CaseSpec position_case(const CaseSpec& base, const AxiSweepOptions& o, double dz, bool& reversed) {
  CaseSpec spec = move_group_axi(base, o.group, dz);
  spec.forces = {group_force(spec, o.group, reversed)};
  spec.probes.clear();
  spec.write_vtu = false;
  aim_adapt_at(spec, spec.forces.front().name, "Fz");
  return spec;
}

void solve_position(AxiSweepRow& row, const CaseSpec& base, const AxiSweepOptions& o,
                    const RunOverrides& fe, double dz) {
  row.position_m = dz;
  bool reversed = false;
  CaseSpec spec = position_case(base, o, dz, reversed);
  const auto run = solve_case_2d(std::move(spec), fe);
  row.fz_N = (reversed ? -1.0 : 1.0) * run->forces.front().force.z();
  row.unknowns = static_cast<long>(run->dofs->n_dofs());
  row.adapt = position_adapt(run->adapt);
}

nlohmann::json row_to_json(const AxiSweepRow& row) {
  nlohmann::json j = {{"fz_N", row.fz_N}, {"seconds", row.seconds}, {"unknowns", row.unknowns}};
  add_position_adapt(j, row.adapt);
  return j;
}

AxiSweepRow row_from_json(const nlohmann::json& saved, double dz) {
  AxiSweepRow row;
  row.position_m = dz;
  row.fz_N = saved.at("fz_N").get<double>();
  row.seconds = saved.at("seconds").get<double>();
  row.unknowns = saved.at("unknowns").get<long>();
  row.adapt = position_adapt_from_json(saved);
  row.ok = true;
  return row;
}

} // namespace

CaseSpec move_group_axi(const CaseSpec& spec, const std::string& group, double dz) {
  if (!spec.axisymmetric())
    throw InputError(cli, 0, "--move", "--move sweeps axisymmetric cases (dimension: axi)");
  RigidMotion2D along_axis;
  along_axis.shift = Vec2(0, dz);
  return move_group2d(spec, group, along_axis, "--move");
}

std::vector<AxiSweepRow> run_sweep_axi(const CaseSpec& spec, const AxiSweepOptions& o,
                                       const AxiSweepProgress& progress) {
  move_group_axi(spec, o.group, 0.0); // bad input fails here, not once per position
  bool reversed = false;
  group_force(spec, o.group, reversed);
  RunOverrides fe;
  fe.order = o.order;
  fe.mesh_scale = o.mesh_scale;
  fe.max_memory_gb = o.max_memory_gb;
  int n_jobs = default_position_workers(o.world, o.jobs, static_cast<int>(o.positions_m.size()));
  if (!o.positions_m.empty())
    n_jobs = plan_positions_2d(position_case(spec, o, o.positions_m.front(), reversed), fe, n_jobs,
                               o.world, o.jobs);
  return run_positions<AxiSweepRow>(
      o.positions_m, n_jobs, o.checkpoint, {row_to_json, row_from_json, {}},
      [&](AxiSweepRow& row, double dz) { solve_position(row, spec, o, fe, dz); }, progress, o.world,
      o.stop);
}

std::string sweep_axi_checkpoint_options(const AxiSweepOptions& o) {
  return o.group + " order " + std::to_string(o.order) + " mesh-scale " +
         RunCheckpoint::mesh_scale_key(o.mesh_scale);
}

std::string sweep_axi_csv(const std::vector<AxiSweepRow>& rows) {
  std::string out = "position_mm,Fz_N\n";
  char buf[128];
  for (const auto& r : rows)
    if (r.ok) {
      std::snprintf(buf, sizeof buf, "%.10g,%.10g\n", r.position_m * 1e3, r.fz_N);
      out += buf;
    }
  return out;
}

nlohmann::ordered_json sweep_axi_summary(const CaseSpec& spec, const std::vector<AxiSweepRow>& rows,
                                         const AxiSweepOptions& options) {
  nlohmann::ordered_json j;
  j["case"] = spec.file;
  j["method"] = sweep_axi_method(spec, options.group);
  j["group"] = options.group;
  int failed = 0;
  for (const auto& r : rows) {
    nlohmann::ordered_json p = {{"position_mm", 1e3 * r.position_m},
                                {"ok", r.ok},
                                {"seconds", r.seconds},
                                {"unknowns", r.unknowns}};
    if (r.adapt.passes)
      p["adapt"] = position_adapt_summary(r.adapt);
    if (!r.ok)
      p["error"] = r.error, ++failed;
    j["positions"].push_back(p);
  }
  j["failed_positions"] = failed;
  if (const auto warnings = sweep_axi_warnings(rows); !warnings.empty())
    j["warnings"] = warnings;
  return j;
}

std::vector<std::string> sweep_axi_warnings(const std::vector<AxiSweepRow>& rows) {
  std::vector<std::string> out;
  for (const auto& r : rows)
    if (const std::string w = position_adapt_warning("position_mm", 1e3 * r.position_m, r.adapt);
        r.ok && !w.empty())
      out.push_back(w);
  return out;
}

} // namespace magfem
