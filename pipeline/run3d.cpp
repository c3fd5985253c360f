#include "pipeline/run3d.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "casefile/symmetry_check3d.hpp"
#include "core/constants.hpp"
#include "core/output_stage.hpp"
#include "materials/material_library.hpp"
#include "mesh/mesh_error.hpp"
#include "mesh/mesh_fingerprint3d.hpp"
#include "mesh/mesher3d.hpp"
#include "pipeline/demagnetization_results.hpp"
#include "pipeline/force3d.hpp"
#include "pipeline/memory_guard.hpp"
#include "pipeline/resource_usage.hpp"
#include "pipeline/result_checks.hpp"
#include "pipeline/result_tables.hpp"
#include "pipeline/run_summary.hpp"
#include "pipeline/section_results.hpp"
#include "pipeline/solver_summary.hpp"
#include "pipeline/vtu_materials.hpp"
#include "postproc/point_locator3d.hpp"
#include "postproc/probes3d.hpp"
#include "postproc/vtu_export3d.hpp"
#include "solver/assembler3d.hpp"
#include "solver/distributed_solve3d.hpp"
#include "solver/mpi_context.hpp"
#include "solver/p1_coarse_space.hpp"
#include "solver/tet_quadrature.hpp"

namespace magfem {
namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Sphere probes tell the mesher where to refine (MeshOptions3D::probe_size).
std::vector<ProbeSurface> probe_surfaces(const CaseSpec& spec) {
  std::vector<ProbeSurface> out;
  if (spec.geometry3d.options.probe_size <= 0)
    return out;
  for (const auto& p : spec.probes)
    if (p.kind == ProbeSpec::Kind::sphere)
      out.push_back({p.center, p.radius, p.theta_min, p.theta_max, p.phi_min, p.phi_max});
  // Stress-tensor spheres too: the force integrand is quadratic in B, so its error is twice
  // the field error there.
  for (const auto& f : spec.forces)
    if (f.kind == ForceSpec::Kind::sphere)
      for (double r : {f.radius, f.check_radius})
        if (r > 0)
          out.push_back({f.center, r, 0, pi, 0, 2 * pi});
  return out;
}

// The memory guard as the mesher calls it (estimate first, then the check).
MeshSizeCheck memory_guard(const CaseSpec& spec, const RunOverrides& ov, MeshEstimate3D& estimate) {
  return [&spec, &ov, &estimate](const MeshEstimate3D& e, const std::function<double(double)>& at) {
    estimate = e;
    const MemoryLimit limit{ov.max_memory_gb, ov.shared_memory_mb, ov.parallel_runs};
    check_memory(e, spec.order, static_cast<int>(spec.geometry3d.coils.size()), limit,
                 ov.mesh_scale > 0 ? ov.mesh_scale : 1.0, at);
  };
}

// A mesher error as an input error at the line of the part it names (else the boundary's).
InputError input_error_of(const CaseSpec& spec, const MeshError& e) {
  for (std::size_t i = 0; i < spec.regions.size(); ++i)
    if (const auto& r = spec.regions[i]; r.name == e.part)
      return InputError(
          spec.file, r.line,
          "regions[" + std::to_string(i) + "]" + (e.field.empty() ? "" : "." + e.field), e.what());
  return InputError(spec.file, spec.boundary_line, e.field.empty() ? "mesh" : "mesh." + e.field,
                    e.what());
}

Mesh3D mesh_case(const CaseSpec& spec, const RunOverrides& ov, MeshEstimate3D& estimate) {
  check_symmetry_3d(spec); // before meshing: the share would stand for a different device
  try {
    return build_mesh_3d(spec.geometry3d, probe_surfaces(spec), memory_guard(spec, ov, estimate));
  } catch (const MeshError& e) {
    throw input_error_of(spec, e);
  }
}

Problem3D build_problem(const CaseSpec& spec, const Mesh3D& mesh) {
  Problem3D p;
  p.mesh = &mesh;
  p.order = spec.order;
  p.boundary = spec.geometry3d.outer.kind;
  p.air.material = MaterialLibrary::bundled().find("air");
  for (const auto& r : spec.regions)
    p.parts.push_back(RegionPhysics3D{r.material, r.magnetization});
  return p;
}

// Why a case cannot be solved by several processes ("" if it can), found before meshing.
// Newton would need every residual evaluation of its line search distributed, and the coils'
// inductance solves reuse the serial linear solver: both stay on one process for now.
std::string distributed_refusal(const CaseSpec& spec) {
  for (const auto& r : spec.regions)
    if (r.material->is_nonlinear())
      return "region '" + r.name + "' is nonlinear (material '" + r.material->name +
             "'): Newton iterations are not distributed; run this case without mpirun";
  if (!spec.geometry3d.coils.empty())
    return "coils are not distributed (their inductance solves run on one process); run this "
           "case without mpirun";
  return "";
}

// Every process meshed the case on its own; the element shares only make sense if the
// meshes are the same. TetGen is deterministic for the same input, so a difference means
// different inputs or builds: an internal error, never a silently wrong assembly.
void check_same_mesh_everywhere(const Mesh3D& mesh) {
  if (!same_on_every_rank(mesh_fingerprint(mesh)))
    throw std::runtime_error("the processes of this mpirun meshed the case differently (mesh "
                             "fingerprints differ); run the same magfem build and case on "
                             "every process");
}

// The model's share -> the whole device (mesh/symmetry_plane3d.hpp). Energies: 2 per plane
// in all (the energy density is even about each plane), and per part 2 per plane that cuts it
// (a part on one side is whole in the model; its image beyond is another part, not meshed).
// Flux linkages and inductances: 2 per plane, every coil being its own mirror image
// (check_symmetry_3d) so that B . h_k is even too. Forces, torques and probes need nothing:
// they sample the whole device's field through the mirror (PointLocator3D).
void scale_to_whole_device(Run3D& run) {
  if (run.spec.geometry3d.symmetry.empty())
    return;
  const double factor = symmetry_factor(run.spec.geometry3d.symmetry);
  const std::vector<double> per_part = region_symmetry_factors(run.spec);
  run.energy.total_J *= factor;
  for (std::size_t i = 0; i < run.energy.regions.size(); ++i) {
    auto& r = run.energy.regions[i];
    const double f = i < per_part.size() ? per_part[i] : factor; // then air and the shell
    r.energy_J *= f;
    r.volume_m3 *= f;
    if (i < run.mesh.part_volumes.size())
      run.mesh.part_volumes[i] *= f;
  }
  run.error_estimate.error_norm2_J *= factor;
  run.error_estimate.energy_norm2_J *= factor;
  for (auto& c : run.coil_results.coils)
    c.flux_linkage_Wb *= factor;
  run.coil_results.inductance_H *= factor;
}

} // namespace

namespace {

void apply_overrides(CaseSpec& spec, const RunOverrides& ov) {
  if (ov.order)
    spec.order = ov.order;
  if (ov.mesh_scale > 0)
    spec.geometry3d.options.size_scale *= ov.mesh_scale;
  if (ov.domain_radius > 0)
    spec.geometry3d.outer.radius = ov.domain_radius;
  spec.geometry3d.options.spheres_curved = spec.order == 2; // DofMap3D::curve_to_spheres
}

} // namespace

Mesh3D mesh_case_3d(CaseSpec& spec, const RunOverrides& overrides, MeshEstimate3D& estimate) {
  apply_overrides(spec, overrides);
  if (!spec.geometry3d.coils.empty())
    check_coils_in_air(spec, CaseCoils(spec.geometry3d.coils, fe_source_options()));
  return mesh_case(spec, overrides, estimate);
}

MeshEstimate3D check_memory_3d(CaseSpec spec, const RunOverrides& ov) {
  apply_overrides(spec, ov);
  MeshEstimate3D estimate;
  return estimate_geometry_mesh_3d(spec.geometry3d, probe_surfaces(spec),
                                   memory_guard(spec, ov, estimate));
}

double estimated_memory_mb_3d(CaseSpec spec, const RunOverrides& ov) {
  apply_overrides(spec, ov);
  const MeshEstimate3D e = estimate_geometry_mesh_3d(spec.geometry3d, probe_surfaces(spec));
  return estimated_peak_memory_mb(e.tetrahedra, spec.order,
                                  static_cast<int>(spec.geometry3d.coils.size()));
}

std::unique_ptr<Run3D> run_case_3d(CaseSpec spec, const RunOverrides& ov) {
  const auto t_start = Clock::now();
  auto run = std::make_unique<Run3D>();
  apply_overrides(spec, ov);
  run->spec = std::move(spec);
  run->spec.newton.linear.progress = ov.progress;
  // 3D systems fill in so much that CHOLMOD's predicted cost passes direct_max_gflop far
  // below this size (a 97k-unknown P2 sphere already goes to CG; 237k P2 unknowns predict
  // 870 GFlop), while the AMD analysis behind the prediction takes seconds at a million
  // unknowns (2 s of the 32-magnet benchmark at 630k): systems this large skip it.
  auto& limit = run->spec.newton.linear.direct_limit;
  limit = std::min(limit, 200'000);
  auto stage = [&](const std::string& what) {
    if (ov.progress)
      ov.progress->stage(what);
  };
  const MpiWorld& world = ov.world;
  run->ranks = world.size;
  if (world.distributed())
    if (const std::string why = distributed_refusal(run->spec); !why.empty())
      throw InputError(run->spec.file, 0, "",
                       why + " (" + std::to_string(world.size) + " processes asked for)");

  if (!run->spec.geometry3d.coils.empty()) {
    run->coils = std::make_unique<CaseCoils>(run->spec.geometry3d.coils, fe_source_options());
    check_coils_in_air(run->spec, *run->coils); // before the mesh: fail fast
  }
  auto t0 = Clock::now();
  stage("meshing");
  run->mesh = mesh_case(run->spec, ov, run->mesh_estimate);
  run->timings.mesh = since(t0);
  // Said now (a solve can take minutes) and again in the summary.
  if (world.is_root())
    for (const auto& w : run->mesh.warnings)
      std::cerr << "magfem: warning: " + w + "\n" << std::flush;
  if (world.distributed())
    check_same_mesh_everywhere(run->mesh);
  check_stress_surfaces_3d(run->spec, run->mesh); // before the solve: fail fast

  run->problem = build_problem(run->spec, run->mesh);
  t0 = Clock::now();
  stage("assembly: " + std::to_string(run->mesh.n_tets()) + " tetrahedra, order " +
        std::to_string(run->spec.order));
  run->dofs = std::make_unique<DofMap3D>(run->mesh, run->spec.order);
  // P2 edge nodes on spherical interfaces go onto the sphere: flat facets would otherwise
  // limit the field error near curved magnet faces to O(h^2) in the geometry.
  if (run->spec.order == 2)
    run->dofs->curve_to_spheres(run->mesh, sphere_surfaces(run->spec.geometry3d, run->mesh));
  if (run->coils) {
    stage("coil source field: " + std::to_string(run->coils->n_coils()) + " coils at " +
          std::to_string(run->mesh.n_tets() * tet_rule(SourceFieldTable3D::rule_degree).size()) +
          " quadrature points");
    run->coil_source = make_coil_source_3d(run->problem, *run->dofs, *run->coils);
    stage("assembly");
    run->problem.source = &run->coil_source;
  }
  // Distributed: one thread per process (the processes share the cores).
  Assembler3D assembler(run->problem, *run->dofs, AssemblyOptions3D{world.distributed() ? 1 : 0});
  run->threads = assembler.threads();
  // The P1 functions on the same tetrahedra: the coarse level of the p-multigrid
  // preconditioner (O(unknowns) to build, unused by the other solvers and not distributed).
  if (run->spec.order == 2 && !world.distributed())
    run->spec.newton.linear.coarse_prolongation =
        std::make_shared<const Eigen::SparseMatrix<double, Eigen::RowMajor>>(
            p1_prolongation(*run->dofs, assembler.dof_to_equation()));
  if (run->spec.order == 2 && !world.distributed() && run->problem.boundary == OuterKind3D::open)
    run->spec.newton.linear.smoother_block = std::make_shared<const std::vector<int>>(
        element_equations(*run->dofs, assembler.dof_to_equation(), run->mesh.n_tets(),
                          [&](std::size_t t) { return run->problem.is_shell(t); }));
  const double setup = since(t0);

  Eigen::VectorXd u;
  if (world.distributed())
    run->report = solve_linear_distributed(assembler, *run->dofs, run->mesh.n_tets(), world.rank,
                                           world.size, run->spec.newton.linear, u);
  else
    run->report = solve_nonlinear(assembler, u, run->spec.newton);
  run->timings.assemble = setup + run->report.assemble_s;
  run->timings.solve = run->report.solve_s;
  if (!run->report.converged)
    throw SolveError("the solver did not converge: " + run->report.message);
  if (!world.is_root()) { // rank 0 holds the solution and alone post-processes
    run->timings.total = since(t_start);
    return run;
  }

  check_finite(u, "solution");

  t0 = Clock::now();
  stage("post-processing");
  run->field = std::make_unique<Field3D>(run->problem, *run->dofs, assembler.expand(u));
  std::vector<std::string> names;
  for (const auto& r : run->spec.regions)
    names.push_back(r.name);
  run->energy = summarize_energy_3d(*run->field, names);
  const PointLocator3D locator(run->mesh);
  run->recovered_B = RecoveredB3D(*run->field);
  for (const auto& probe : run->spec.probes)
    run->probes.push_back(
        sample_probe_3d(*run->field, locator, probe, run->spec.length_unit, &run->recovered_B));
  // Sections integrate the element field itself: a flux is an integral, which the recovered
  // (smoothed) B would only approximate, and the element B is exact in B.n per element.
  for (const auto& section : run->spec.sections)
    run->sections.push_back(integrate_section_3d(*run->field, section));
  check_sections_inside(run->sections, run->spec);
  run->forces = compute_forces_3d(*run);
  for (auto& f : coil_lorentz_forces(*run))
    run->forces.push_back(f);
  run->coil_results = compute_coil_results(*run, assembler, u);
  // Every solve says how accurate it is (issue 29): the energy-norm estimate and one for
  // each stress-tensor force, from one patch recovery.
  const auto t_estimate = Clock::now();
  const PatchRecovery3D recovery(*run->field);
  run->error_estimate = estimate_error_3d(recovery, run->energy.total_J);
  estimate_force_errors_3d(*run, recovery, run->forces);
  run->error_estimate_s = since(t_estimate);
  run->timings.error_estimate = run->error_estimate_s;
  check_finite(run->recovered_B.values(), "recovered flux density");
  check_finite(run->energy.total_J, "magnetic energy");
  check_forces_finite(run->forces);
  scale_to_whole_device(*run);
  run->warnings = run->mesh.warnings;
  for (auto& w : bh_extrapolation_warnings(run->spec.regions, run->energy.regions))
    run->warnings.push_back(std::move(w));
  run->demagnetization = check_demagnetization(*run->field, run->spec, run->warnings);
  run->timings.postprocess = since(t0);
  run->timings.total = since(t_start);
  return run;
}

nlohmann::ordered_json summary_json_3d(const Run3D& run) {
  nlohmann::ordered_json j;
  add_run_header(j, {run.spec.file, 3, run.spec.order, run.mesh.n_tets(), run.mesh.n_nodes(),
                     static_cast<std::size_t>(run.dofs->n_dofs())});
  j["mesh_quality"] = {{"min_dihedral_deg", run.mesh.quality.min_dihedral_deg},
                       {"max_dihedral_deg", run.mesh.quality.max_dihedral_deg},
                       {"max_radius_edge", run.mesh.quality.max_radius_edge},
                       {"curved_tets", run.dofs->n_curved()},
                       {"straightened_edge_nodes", run.dofs->n_straightened()}};
  add_energy(j, run.energy.total_J, "device");
  if (const auto& planes = run.spec.geometry3d.symmetry; !planes.empty()) {
    // What was meshed, and that energies, linkages and inductances are the whole device's.
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const auto& p : planes)
      list.push_back({{"plane", axis_name(p.axis)}, {"field", field_name(p.field)}});
    j["symmetry"] = list;
    j["symmetry_factor"] = symmetry_factor(planes);
  }
  add_error_estimate(j,
                     {run.error_estimate.energy_error_pct, run.error_estimate.energy_norm_error_pct,
                      run.error_estimate.indicator, run.error_estimate.error_norm2_J},
                     run.error_estimate_s);
  add_solve_record(j, run.report, run.timings, run.threads, run.ranks);
  // The coils' inductance matrix (part of postprocess), 3D only.
  j["timings_s"]["inductance"] = run.coil_results.inductance_s;
  j["memory_guard"] = {
      {"estimated_tetrahedra", std::lround(run.mesh_estimate.tetrahedra)},
      {"estimated_peak_memory_MB",
       estimated_peak_memory_mb(run.mesh_estimate.tetrahedra, run.spec.order,
                                static_cast<int>(run.spec.geometry3d.coils.size()))}};
  auto& regions = j["regions"];
  for (std::size_t i = 0; i < run.energy.regions.size(); ++i) {
    const auto& r = run.energy.regions[i];
    if (r.volume_m3 == 0)
      continue;
    nlohmann::ordered_json reg = {{"name", r.name},
                                  {"volume_m3", r.volume_m3},
                                  {"energy_J", r.energy_J},
                                  {"peak_B_T", r.peak_B_T},
                                  {"nonlinear", r.nonlinear}};
    if (i < run.mesh.part_volumes.size())
      reg["meshed_volume_m3"] = run.mesh.part_volumes[i];
    regions.push_back(reg);
  }
  for (const auto& p : run.probes)
    j["probes"].push_back(p.name + ".csv");
  if (!run.sections.empty()) {
    j["sections"] = sections_json(run.sections, run.spec.sections, run.spec.regions);
  }
  if (run.coils) {
    j["coils"] = coil_results_json(run.coil_results);
    if (run.coil_results.inductance_H.size() > 0) {
      std::vector<std::string> names;
      for (const auto& c : run.coil_results.coils)
        names.push_back(c.name);
      nlohmann::ordered_json l = nlohmann::ordered_json::array();
      for (Eigen::Index i = 0; i < run.coil_results.inductance_H.rows(); ++i) {
        std::vector<double> row;
        for (Eigen::Index k = 0; k < run.coil_results.inductance_H.cols(); ++k)
          row.push_back(run.coil_results.inductance_H(i, k));
        l.push_back(row);
      }
      j["inductance_H"] = {{"names", names}, {"matrix", l}};
    }
    j["coil_warnings"] = run.coil_results.warnings;
  }
  if (!run.forces.empty()) {
    j["forces_per"] = "device";
    j["forces"] = forces_json(run.forces);
  }
  if (run.adapt)
    j["adapt"] = adapt_json(*run.adapt);
  add_demagnetization(j, run.demagnetization, 3);
  j["warnings"] = run.warnings;
  return j;
}

std::vector<std::string> write_outputs_3d(const Run3D& run, const std::filesystem::path& out_dir) {
  std::filesystem::create_directories(out_dir);
  OutputStage stage(out_dir);
  stage_probe_tables(stage, run.probes);
  if (run.spec.write_vtu) {
    const VtuMaterials materials = vtu_materials(run.spec.regions);
    const auto& material_names = materials.names;
    const auto& material_of_part = materials.of_region;
    VtuGrid grid =
        make_vtu_3d(*run.field, run.recovered_B.dof_average(), material_of_part, 0, material_names);
    // eta_K^2 (J) per cell, in the cells' order (the shell is left out of the grid).
    VtuArray indicator{"error_indicator", 1, {}};
    for (std::size_t t = 0; t < run.mesh.n_tets(); ++t)
      if (!run.problem.is_shell(t))
        indicator.values.push_back(run.error_estimate.eta2_J[t]);
    grid.cell_data.push_back(std::move(indicator));
    add_B_along_M(grid, run.demagnetization, [&](std::size_t t) { return run.problem.is_shell(t); });
    write_vtu(stage.path_for("solution.vtu").string(), grid);
  }
  stage_force_and_section_tables(stage, run.forces, run.sections, run.spec.regions);
  stage.write_text("summary.json", summary_json_3d(run).dump(2) + "\n");
  stage.commit();
  return stage.written();
}

std::string describe_run_3d(const Run3D& run) {
  char buf[640];
  std::snprintf(
      buf, sizeof buf,
      "mesh     %zu tetrahedra, %zu nodes, dihedral %.1f..%.1f deg\n"
      "solve    order %d, %d unknowns, %s, residual %.2e\n"
      "energy   %.6g J%s\n",
      run.mesh.n_tets(), run.mesh.n_nodes(), run.mesh.quality.min_dihedral_deg,
      run.mesh.quality.max_dihedral_deg, run.spec.order, run.dofs->n_dofs(),
      describe_solver(run.report).c_str(), run.report.residual_history.back(), run.energy.total_J,
      run.spec.geometry3d.symmetry.empty() ? "" : " (whole device; the model is its share)");
  std::string s = buf;
  if (run.dofs->n_straightened() > 0)
    s += "note     " + std::to_string(run.dofs->n_straightened()) +
         " edge nodes on spheres kept straight: curving them would fold their tets (a finer "
         "mesh there curves them)\n";
  for (const auto& note : run.report.notes)
    s += "note     " + note + "\n";
  for (const auto& r : run.energy.regions)
    if (r.nonlinear && r.volume_m3 > 0) {
      std::snprintf(buf, sizeof buf, "iron     %-20s peak |B| %.3f T\n", r.name.c_str(),
                    r.peak_B_T);
      s += buf;
    }
  std::snprintf(buf, sizeof buf,
                "error    estimated energy error %.3g %% (energy norm %.3g %%, %s, %.2f s)\n",
                run.error_estimate.energy_error_pct, run.error_estimate.energy_norm_error_pct,
                run.error_estimate.indicator.c_str(), run.error_estimate_s);
  s += buf;
  if (run.adapt)
    s += describe_adapt_result(*run.adapt);
  s += describe_forces(run.forces, false);
  for (const auto& f : run.sections) {
    std::snprintf(buf, sizeof buf, "section  %-20s flux %.6g Wb, mean Bn %.6g T, mean |B| %.6g T\n",
                  f.name.c_str(), f.total.flux_Wb, f.total.Bn_avg_T(), f.total.B_avg_T());
    s += buf;
  }
  s += describe_coils(run.coil_results);
  std::snprintf(buf, sizeof buf,
                "time     mesh %.2f s, assemble %.2f s, solve %.2f s (set-up %.2f s), post %.2f s, "
                "total %.2f s, peak %.0f MB\n",
                run.timings.mesh, run.timings.assemble, run.timings.solve,
                run.report.linear_setup_s, run.timings.postprocess, run.timings.total,
                peak_memory_mb());
  s += buf;
  for (const auto& w : run.warnings)
    s += "warning  " + w + "\n";
  return s;
}

} // namespace magfem
