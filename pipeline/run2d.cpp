#include "pipeline/run2d.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>

#include <nlohmann/json.hpp>

#include "casefile/symmetry_check2d.hpp"
#include "core/output_stage.hpp"
#include "materials/material_library.hpp"
#include "mesh/mesh_error.hpp"
#include "mesh/mesher2d.hpp"
#include "pipeline/force2d.hpp"
#include "pipeline/result_checks.hpp"
#include "pipeline/result_tables.hpp"
#include "pipeline/demagnetization_results.hpp"
#include "pipeline/run_summary.hpp"
#include "pipeline/section_results.hpp"
#include "pipeline/solver_summary.hpp"
#include "pipeline/symmetry2d.hpp"
#include "pipeline/vtu_materials.hpp"
#include "postproc/coil_linkage_axi.hpp"
#include "postproc/point_locator2d.hpp"
#include "postproc/probes2d.hpp"
#include "postproc/vtu_export2d.hpp"
#include "postproc/vtu_export_revolved.hpp"
#include "solver/assembler2d.hpp"
#include "solver/current_sensitivity2d.hpp"
#include "solver/triangle_lagrange.hpp"

namespace magfem {
namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

Mesh2D mesh_case(const CaseSpec& spec, const SizeField2D* refine_sizes) {
  check_symmetry_2d(spec); // before meshing: the share would stand for a different device
  try {
    return build_mesh_2d(spec.geometry2d, refine_sizes);
  } catch (const MeshError& e) {
    throw_mesh_error_2d(spec, e);
  }
}

Problem2D build_problem(const CaseSpec& spec, const Mesh2D& mesh) {
  Problem2D p;
  p.mesh = &mesh;
  p.order = spec.order;
  p.boundary = spec.geometry2d.outer.kind;
  p.symmetry = spec.geometry2d.symmetry;
  p.air.material = MaterialLibrary::bundled().find("air");
  const auto areas = whole_part_areas(spec, mesh);
  for (std::size_t i = 0; i < spec.regions.size(); ++i) {
    const auto& r = spec.regions[i];
    RegionPhysics2D phys{r.material, r.magnetization, r.current_density};
    // Ampere-turns over the meshed area, so the total current is exactly N I.
    if (r.ampere_turns != 0)
      phys.current_density = r.ampere_turns / areas[i];
    p.parts.push_back(phys);
  }
  return p;
}

// The sensitivity solves of the differential inductance stop at 1e-9 relative residual when
// they are iterative (as in 3D, coil_run3d.cpp); direct solves are exact whatever it is.
LinearSolverOptions sensitivity_options(LinearSolverOptions options) {
  options.cg_tolerance = std::max(options.cg_tolerance, 1e-9);
  // Part of post-processing: its factorization is no stage of its own on the console (it
  // reported "factorization" after "post-processing").
  options.progress = nullptr;
  return options;
}

// Axisymmetric coils: the linkage with the total field (lambda / I is the apparent
// inductance, which counts the magnets' flux) and the differential inductance d lambda / dI,
// the linkage of the field's response to the coil's current at the operating point.
std::vector<CoilResult2D> coil_results(const Run2D& run, const Assembler2D& assembler,
                                       const Eigen::VectorXd& u) {
  std::vector<CoilResult2D> out;
  if (!run.spec.axisymmetric())
    return out;
  const auto areas = whole_part_areas(run.spec, run.mesh);
  std::vector<CurrentPerAmpere2D> per_ampere;
  for (std::size_t i = 0; i < run.spec.regions.size(); ++i) {
    const RegionSpec& r = run.spec.regions[i];
    if (r.turns == 0)
      continue;
    CoilResult2D c{r.name, r.turns, r.current};
    c.flux_linkage_Wb = flux_linkage_axi(*run.field, static_cast<int>(i), r.turns);
    c.linkage_per_ampere_H = r.current != 0 ? c.flux_linkage_Wb / r.current : 0.0;
    out.push_back(c);
    per_ampere.push_back({static_cast<int>(i), r.turns / areas[i]});
  }
  const auto du = current_sensitivities_2d(run.problem, *run.dofs, assembler, u, per_ampere,
                                           sensitivity_options(run.spec.newton.linear));
  for (std::size_t k = 0; k < out.size(); ++k) {
    const Field2D response(run.problem, *run.dofs, assembler.expand(du[k]));
    out[k].inductance_H = flux_linkage_axi(response, per_ampere[k].part, out[k].turns);
  }
  return out;
}

// The per-element indicator eta_K^2 (J/m planar, J axisymmetric) as cell data, in the order
// of make_vtu_2d's cells (the shell is not written).
void add_error_indicator(VtuGrid& grid, const Run2D& run) {
  VtuArray a{"error_indicator", 1, {}};
  for (std::size_t t = 0; t < run.mesh.n_triangles(); ++t)
    if (!run.problem.is_shell(t))
      a.values.push_back(run.error.eta2[t]);
  grid.cell_data.push_back(std::move(a));
}

} // namespace

nlohmann::ordered_json coils_json_2d(const std::vector<CoilResult2D>& coils) {
  auto j = nlohmann::ordered_json::array();
  for (const auto& c : coils)
    j.push_back({{"name", c.name},
                 {"turns", c.turns},
                 {"current_A", c.current_A},
                 {"flux_linkage_Wb", c.flux_linkage_Wb},
                 {"inductance_H", c.inductance_H},
                 {"linkage_per_ampere_H", c.linkage_per_ampere_H}});
  return j;
}

void throw_mesh_error_2d(const CaseSpec& spec, const MeshError& e) {
  // Point at the region that caused it when we know it, else at the mesh settings. The
  // mesher's polygon `vertices` are the case file's `points`.
  const std::string field = e.field == "vertices" ? "points" : e.field;
  for (std::size_t i = 0; i < spec.regions.size(); ++i)
    if (const auto& r = spec.regions[i]; r.name == e.part)
      throw InputError(spec.file, r.line,
                       "regions[" + std::to_string(i) + "]" + (field.empty() ? "" : "." + field),
                       e.reason);
  throw InputError(spec.file, spec.boundary_line, e.field.empty() ? "mesh" : "mesh." + e.field,
                   e.reason);
}

namespace {

void apply_overrides(CaseSpec& spec, const RunOverrides& ov) {
  if (ov.order)
    spec.order = ov.order;
  if (ov.mesh_scale > 0)
    spec.geometry2d.options.size_scale *= ov.mesh_scale;
  if (ov.domain_radius > 0)
    spec.geometry2d.outer.radius = ov.domain_radius;
}

} // namespace

Mesh2D mesh_case_2d(CaseSpec& spec, const RunOverrides& overrides) {
  apply_overrides(spec, overrides);
  return mesh_case(spec, overrides.refine_sizes);
}

std::unique_ptr<Run2D> run_case_2d(CaseSpec spec, const RunOverrides& ov) {
  const auto t_start = Clock::now();
  auto run = std::make_unique<Run2D>();
  apply_overrides(spec, ov);
  run->spec = std::move(spec);
  run->spec.newton.linear.progress = ov.progress;
  // A planar or axisymmetric factor stays affordable up to the direct limit (nested
  // dissection fill grows like n log n in 2D), so the cost prediction, a second AMD ordering
  // of the whole matrix, is not run (it was a tenth of a 100k-unknown axisymmetric solve).
  run->spec.newton.linear.direct_max_gflop = 0;
  auto stage = [&](const std::string& what) {
    if (ov.progress)
      ov.progress->stage(what);
  };

  auto t0 = Clock::now();
  stage("meshing");
  run->mesh = mesh_case(run->spec, ov.refine_sizes);
  run->timings.mesh = since(t0);
  check_stress_surfaces_2d(run->spec, run->mesh); // before the solve: fail fast

  run->problem = build_problem(run->spec, run->mesh);
  t0 = Clock::now();
  stage("assembly: " + std::to_string(run->mesh.n_triangles()) + " triangles, order " +
        std::to_string(run->spec.order));
  run->dofs = std::make_unique<DofMap2D>(run->mesh, run->spec.order);
  Assembler2D assembler(run->problem, *run->dofs);
  const double setup = since(t0);

  Eigen::VectorXd u;
  run->report = solve_nonlinear(assembler, u, run->spec.newton);
  run->timings.assemble = setup + run->report.assemble_s;
  run->timings.solve = run->report.solve_s;
  if (!run->report.converged)
    throw SolveError("the solver did not converge: " + run->report.message);

  check_finite(u, "solution");

  t0 = Clock::now();
  stage("post-processing");
  run->field = std::make_unique<Field2D>(run->problem, *run->dofs, assembler.expand(u));
  std::vector<std::string> names;
  for (const auto& r : run->spec.regions)
    names.push_back(r.name);
  run->energy = summarize_energy_2d(*run->field, names);
  const auto t_estimate = Clock::now();
  run->error = estimate_error_2d(*run->field, run->energy.total_J_per_m);
  run->timings.error_estimate = since(t_estimate);
  const PointLocator2D locator(run->mesh);
  for (const auto& probe : run->spec.probes)
    run->probes.push_back(sample_probe_2d(*run->field, locator, probe, run->spec.length_unit));
  const double depth = run->spec.stack_length > 0 ? run->spec.stack_length : 1.0;
  for (const auto& section : run->spec.sections)
    run->sections.push_back(integrate_section_whole_2d(*run->field, section, depth, run->spec));
  check_sections_inside(run->sections, run->spec);
  run->forces = compute_forces_2d(*run);
  run->coils = coil_results(*run, assembler, u);
  scale_to_whole_device_2d(*run);
  check_finite(run->energy.total_J_per_m, "magnetic energy");
  check_forces_finite(run->forces);
  run->warnings = bh_extrapolation_warnings(run->spec.regions, run->energy.regions);
  run->demagnetization = check_demagnetization(*run->field, run->spec, run->warnings);
  run->timings.postprocess = since(t0);
  run->timings.total = since(t_start);
  return run;
}

nlohmann::ordered_json summary_json_2d(const Run2D& run) {
  nlohmann::ordered_json j;
  const bool axi = run.spec.axisymmetric();
  add_run_header(j, {run.spec.file, axi ? nlohmann::ordered_json("axi") : nlohmann::ordered_json(2),
                     run.spec.order, run.mesh.n_triangles(), run.mesh.n_nodes(),
                     static_cast<std::size_t>(run.dofs->n_dofs())});
  // Top-level min/max_angle_deg predate mesh_quality and stay for the scripts that read them.
  j["min_angle_deg"] = run.mesh.quality.min_angle_deg;
  j["max_angle_deg"] = run.mesh.quality.max_angle_deg;
  j["mesh_quality"] = {{"min_angle_deg", run.mesh.quality.min_angle_deg},
                       {"max_angle_deg", run.mesh.quality.max_angle_deg}};
  const double length = run.spec.stack_length > 0 ? run.spec.stack_length : 1.0;
  const std::string per = axi                         ? "body of revolution"
                          : run.spec.stack_length > 0 ? "stack"
                                                      : "metre of length";
  add_energy(j, run.energy.total_J_per_m * length, per);
  add_symmetry_json_2d(j, run.spec);
  add_error_estimate(j,
                     {run.error.energy_error_pct, run.error.energy_norm_error_pct,
                      run.error.indicator, run.error.total_eta2 * length},
                     run.timings.error_estimate);
  add_solve_record(j, run.report, run.timings, 1, 1);
  auto& regions = j["regions"];
  for (const auto& r : run.energy.regions) {
    if (r.area_m2 == 0)
      continue;
    regions.push_back({{"name", r.name},
                       {"area_m2", r.area_m2},
                       {"energy_J", r.energy_J_per_m * length},
                       {"peak_B_T", r.peak_B_T},
                       {"nonlinear", r.nonlinear}});
  }
  for (const auto& p : run.probes)
    j["probes"].push_back(p.name + ".csv");
  if (!run.forces.empty()) {
    j["forces_per"] = per;
    j["forces"] = forces_json(run.forces);
  }
  if (!run.sections.empty())
    j["sections"] = sections_json(run.sections, run.spec.sections, run.spec.regions);
  if (!run.coils.empty())
    j["coils"] = coils_json_2d(run.coils);
  if (run.adapt)
    j["adapt"] = adapt_json(*run.adapt);
  add_demagnetization(j, run.demagnetization, 2);
  j["warnings"] = run.warnings;
  return j;
}

std::vector<std::string> write_outputs_2d(const Run2D& run, const std::filesystem::path& out_dir) {
  std::filesystem::create_directories(out_dir);
  OutputStage stage(out_dir);
  stage_probe_tables(stage, run.probes);

  if (run.spec.write_vtu) {
    const VtuMaterials materials = vtu_materials(run.spec.regions);
    const auto& material_names = materials.names;
    const auto& material_of_part = materials.of_region;
    VtuGrid grid = make_vtu_2d(*run.field, material_of_part, 0, material_names);
    add_error_indicator(grid, run);
    add_B_along_M(grid, run.demagnetization, [&](std::size_t t) { return run.problem.is_shell(t); });
    write_vtu(stage.path_for("solution.vtu").string(), grid);
    if (run.spec.write_revolved_vtu)
      write_vtu(stage.path_for("solution_revolved.vtu").string(),
                make_vtu_revolved(*run.field, material_of_part, 0, material_names));
  }

  stage_force_and_section_tables(stage, run.forces, run.sections, run.spec.regions);
  stage.write_text("summary.json", summary_json_2d(run).dump(2) + "\n");
  stage.commit();
  return stage.written();
}

std::string describe_run_2d(const Run2D& run) {
  char buf[512];
  std::string s;
  std::snprintf(buf, sizeof buf,
                "mesh     %zu triangles, %zu nodes, min angle %.1f deg\n"
                "solve    order %d, %d unknowns, %s, residual %.2e\n",
                run.mesh.n_triangles(), run.mesh.n_nodes(), run.mesh.quality.min_angle_deg,
                run.spec.order, run.dofs->n_dofs(), describe_solver(run.report).c_str(),
                run.report.residual_history.back());
  s += buf;
  std::snprintf(buf, sizeof buf, "energy   %.6g %s\n", run.energy.total_J_per_m,
                run.spec.axisymmetric() ? "J (body of revolution)" : "J/m");
  s += buf;
  std::snprintf(
      buf, sizeof buf, "error    estimated energy error %.3g %% (energy norm %.3g %%, %s)\n",
      run.error.energy_error_pct, run.error.energy_norm_error_pct, run.error.indicator.c_str());
  s += buf;
  if (run.adapt)
    s += describe_adapt_result(*run.adapt);
  for (const auto& r : run.energy.regions)
    if (r.nonlinear && r.area_m2 > 0) {
      std::snprintf(buf, sizeof buf, "iron     %-20s peak |B| %.3f T\n", r.name.c_str(),
                    r.peak_B_T);
      s += buf;
    }
  s += describe_forces(run.forces, run.spec.stack_length <= 0 && !run.spec.axisymmetric());
  for (const auto& f : run.sections) {
    std::snprintf(buf, sizeof buf, "section  %-20s flux %.6g %s, mean Bn %.6g T, mean |B| %.6g T\n",
                  f.name.c_str(), f.total.flux_Wb,
                  run.spec.stack_length > 0 || run.spec.axisymmetric() ? "Wb" : "Wb/m",
                  f.total.Bn_avg_T(), f.total.B_avg_T());
    s += buf;
  }
  for (const auto& c : run.coils) {
    std::snprintf(buf, sizeof buf,
                  "coil     %-20s linkage %.6g Wb, L = dlambda/dI = %.6g H (differential), "
                  "linkage / I = %.6g H (apparent)\n",
                  c.name.c_str(), c.flux_linkage_Wb, c.inductance_H, c.linkage_per_ampere_H);
    s += buf;
  }
  std::snprintf(buf, sizeof buf,
                "time     mesh %.3f s, assemble %.3f s, solve %.3f s, post %.3f s, total %.3f s\n",
                run.timings.mesh, run.timings.assemble, run.timings.solve, run.timings.postprocess,
                run.timings.total);
  s += buf;
  for (const auto& w : run.warnings)
    s += "warning  " + w + "\n";
  return s;
}

} // namespace magfem
