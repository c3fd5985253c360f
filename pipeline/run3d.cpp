#include "pipeline/run3d.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "casefile/symmetry_check3d.hpp"
#include "core/constants.hpp"
#include "core/output_stage.hpp"
#include "core/thread_count.hpp"
#include "materials/material_library.hpp"
#include "mesh/mesh_error.hpp"
#include "mesh/mesh_fingerprint3d.hpp"
#include "mesh/mesher3d.hpp"
#include "pipeline/demagnetization_results.hpp"
#include "pipeline/force3d.hpp"
#include "pipeline/memory_guard.hpp"
#include "pipeline/mesh_pieces_on_processes.hpp"
#include "pipeline/mirror_image_regions.hpp"
#include "pipeline/resource_usage.hpp"
#include "pipeline/result_checks.hpp"
#include "pipeline/run_case.hpp"
#include "pipeline/run_report.hpp"
#include "pipeline/run_summary.hpp"
#include "pipeline/section_results.hpp"
#include "pipeline/solver_summary.hpp"
#include "pipeline/vtu_materials.hpp"
#include "postproc/point_locator3d.hpp"
#include "postproc/probes3d.hpp"
#include "postproc/vtu_export3d.hpp"
#include "solver/assembler3d.hpp"
#include "solver/distributed_linear_solver.hpp"
#include "solver/distributed_rows.hpp"
#include "solver/distributed_solve3d.hpp"
#include "solver/mpi_context.hpp"
#include "solver/p1_coarse_space.hpp"
#include "solver/tet_quadrature.hpp"

namespace magfem {
namespace {

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
    return build_mesh_3d(spec.geometry3d, probe_surfaces(spec), memory_guard(spec, ov, estimate),
                         ov.world.distributed() ? mesh_pieces_on_processes(ov.world)
                                                : PieceRunner3D{});
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
// (a part on one side is whole in the model; its image beyond is another part, not meshed,
// reported as the mirror of the first: pipeline/mirror_image_regions.hpp).
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
  const std::vector<int> images = share_images(run.spec);
  fill_mirror_image_regions(run.energy.regions, images);
  for (std::size_t i = 0; i < images.size() && i < run.mesh.part_volumes.size(); ++i)
    if (images[i] >= 0)
      run.mesh.part_volumes[i] = run.mesh.part_volumes[std::size_t(images[i])];
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
  spec.geometry3d.options.element_order = spec.order;
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

namespace {

// The 3D stages of run_case (run_case.hpp): Lagrange tetrahedra of order 1 or 2 for the
// reduced scalar potential (coils as a Biot-Savart source field), Newton with CHOLMOD, CG with
// AMG or p-multigrid, or under mpirun a distributed linear solve; symmetry planes mesh a share
// of the device, scaled back to the whole after post-processing.
class Discretisation3D {
public:
  using Run = Run3D;
  using DofMap = DofMap3D;
  using Field = Field3D;
  using Locator = PointLocator3D;
  using Assembler = Assembler3D;
  static constexpr const char* element_name = "tetrahedra";

  Discretisation3D(Run3D& run, const RunOverrides& ov) : run_(run), ov_(ov), world_(ov.world) {
    run_.ranks = world_.size;
  }

  static void apply_overrides(CaseSpec& spec, const RunOverrides& ov) {
    magfem::apply_overrides(spec, ov);
  }
  static std::size_t n_elements(const Mesh3D& mesh) { return mesh.n_tets(); }
  static double total_energy(const Run3D& run) { return run.energy.total_J; }

  // 3D systems fill in so much that CHOLMOD's predicted cost passes direct_max_gflop far
  // below this size (a 97k-unknown P2 sphere already goes to CG; 237k P2 unknowns predict
  // 870 GFlop), while the AMD analysis behind the prediction takes seconds at a million
  // unknowns (2 s of the 32-magnet benchmark at 630k): systems this large skip it.
  void tune_linear_solver(LinearSolverOptions& options) const {
    options.direct_limit = std::min(options.direct_limit, 200'000);
  }
  void check_before_mesh() const {
    if (!run_.spec.geometry3d.coils.empty()) {
      run_.coils = std::make_unique<CaseCoils>(run_.spec.geometry3d.coils, fe_source_options());
      check_coils_in_air(run_.spec, *run_.coils);
    }
  }
  Mesh3D mesh() const { return mesh_case(run_.spec, ov_, run_.mesh_estimate); }
  void check_mesh() const {
    // Said now (a solve can take minutes) and again in the summary.
    if (world_.is_root() && ov_.say_mesh_warnings)
      for (const auto& w : run_.mesh.warnings)
        std::cerr << "magfem: warning: " + w + "\n" << std::flush;
    if (world_.distributed())
      check_same_mesh_everywhere(run_.mesh);
    check_stress_surfaces_3d(run_.spec, run_.mesh);
  }
  Problem3D build_problem() const { return magfem::build_problem(run_.spec, run_.mesh); }
  void prepare_dofs() const {
    // P2 edge nodes on spherical interfaces go onto the sphere: flat facets would otherwise
    // limit the field error near curved magnet faces to O(h^2) in the geometry.
    if (run_.spec.order == 2)
      run_.dofs->curve_to_spheres(run_.mesh, sphere_surfaces(run_.spec.geometry3d, run_.mesh));
    const std::vector<std::size_t> source_tets = partition_rows();
    if (run_.coils) {
      announce_stage(ov_.progress,
                     "coil source field: " + std::to_string(run_.coils->n_coils()) + " coils at " +
                         std::to_string(run_.mesh.n_tets() *
                                        tet_rule(SourceFieldTable3D::rule_degree).size()) +
                         " quadrature points");
      // Distributed: each process evaluates the source field at the tetrahedra it assembles
      // (own-row assembly: those of its rows; else its contiguous share); rank 0, which
      // post-processes, gets the whole table.
      run_.coil_source =
          make_coil_source_3d(run_.problem, *run_.dofs, *run_.coils, share(),
                              run_.spec.newton.linear.distributed_rows ? &source_tets : nullptr);
      if (world_.distributed())
        run_.coil_source.table.gather_to_root();
      announce_stage(ov_.progress, "assembly");
      run_.problem.source = &run_.coil_source;
    }
  }
  // Distributed: this process's share of the tetrahedra, one thread (the processes share the
  // cores). With p-multigrid (P2) the share is own-row assembly's (partition_rows): the run
  // keeps an assembler of no tetrahedra (the numbering) and solve() assembles the share's,
  // which the solve frees before its memory peaks (distributed_solve3d.hpp).
  Assembler3D make_assembler() const {
    if (run_.spec.newton.linear.distributed_rows)
      return Assembler3D(run_.problem, *run_.dofs,
                         {1, {}, std::make_shared<const std::vector<std::size_t>>()});
    return Assembler3D(run_.problem, *run_.dofs,
                       AssemblyOptions3D{world_.distributed() ? 1 : 0, share(), nullptr});
  }
  void prepare_solver(const Assembler3D& assembler) const {
    run_.threads = assembler.threads();
    if (run_.spec.order == 2 && !run_.spec.newton.linear.distributed_rows)
      set_coarse_space(assembler.dof_to_equation());
  }
  NewtonReport solve(Assembler3D& assembler, Eigen::VectorXd& u) const {
    if (!world_.distributed()) {
      NewtonOptions newton = run_.spec.newton;
      // The coils' sensitivity solves reuse a linear system's matrix and preconditioner.
      newton.keep_linear_factorization = run_.coils && run_.spec.coil_inductance;
      return solve_nonlinear(assembler, u, newton);
    }
    const auto t_share = std::chrono::steady_clock::now();
    std::shared_ptr<const Assembler3D> share = distributed_share(assembler);
    const double share_s = seconds_since(t_share);
    // The inductance's solves below assemble the share again: kept for them.
    const bool sensitivities = run_.coils && run_.spec.coil_inductance;
    const std::shared_ptr<const Assembler3D> kept = sensitivities ? share : nullptr;
    NewtonReport report = solve_distributed(std::move(share), world_.size, run_.spec.newton, u);
    report.assemble_s += share_s;
    // The inductance matrix's solves need every process: done here, before rank 0 goes on
    // alone. (A Newton that did not converge ends the run on every process anyway.)
    if (report.converged && sensitivities) {
      const auto t0 = std::chrono::steady_clock::now();
      run_.coil_sensitivities = current_sensitivities_distributed(
          *kept, world_.size, u, run_.coils->n_coils(),
          distributed_sensitivity_solver_options(run_.spec.newton.linear));
      run_.coil_sensitivity_s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    lend_node_cores_to_root();
    return report;
  }
  // Rank 0 holds the solution and alone post-processes.
  bool post_processes() const { return world_.is_root(); }

  // After recover(): the recovery's peak |B| per tet (B at every DOF node of every tet
  // evaluated once, not again here).
  EnergySummary3D summarize_energy(const std::vector<std::string>& names) const {
    return summarize_energy_3d(*run_.field, names, &run_.recovered_B.element_peak_B());
  }
  // Nodal B per region, once for the VTU and the energy summary's peak |B|; the patch
  // recovery, once for the probes and the error estimates.
  void recover() const {
    run_.recovered_B = RecoveredB3D(*run_.field);
    run_.recovery = std::make_unique<PatchRecovery3D>(*run_.field);
  }
  // A grid over the tets near the probe points only, not the whole mesh (1 s of
  // benchmark32's post-processing went into a grid of all 1.6 M tets for 2116 points).
  PointLocator3D probe_locator() const {
    std::vector<Eigen::Vector3d> points;
    for (const ProbeSpec& probe : run_.spec.probes) {
      const std::vector<Eigen::Vector3d> p = probe_points_3d(probe);
      points.insert(points.end(), p.begin(), p.end());
    }
    return PointLocator3D(run_.mesh, points);
  }
  ProbeTable sample_probe(const PointLocator3D& locator, const ProbeSpec& probe) const {
    return sample_probe_3d(*run_.field, locator, probe, run_.spec.length_unit, *run_.recovery);
  }
  // Sections integrate the element field itself: a flux is an integral, which the recovered
  // (smoothed) B would only approximate, and the element B is exact in B.n per element.
  SectionFlux integrate_section(const SectionSpec& section) const {
    return integrate_section_3d(*run_.field, section);
  }
  std::vector<ForceResult> forces() const {
    auto forces = compute_forces_3d(run_);
    for (auto& f : coil_lorentz_forces(run_))
      forces.push_back(f);
    return forces;
  }
  void coil_results(const Assembler3D& assembler, const Eigen::VectorXd& u) const {
    run_.coil_results = compute_coil_results(run_, assembler, u);
    run_.report.factorized.reset(); // its memory is not needed after the sensitivity solves
  }
  // The energy-norm estimate and one for each stress-tensor and Lorentz force, from one patch
  // recovery.
  void estimate_error() const {
    const PatchRecovery3D& recovery = *run_.recovery;
    run_.error_estimate = estimate_error_3d(recovery, run_.energy.total_J);
    estimate_force_errors_3d(run_, recovery, run_.forces);
    estimate_lorentz_errors_3d(run_, recovery, run_.forces);
  }
  void check_finite_fields() const {
    check_finite(run_.recovered_B.values(), "recovered flux density");
  }
  void scale_to_whole_device() const { magfem::scale_to_whole_device(run_); }
  std::vector<std::string> mesh_warnings() const { return run_.mesh.warnings; }

  // What the report writes (run_report.hpp).
  static constexpr int dimension = 3;
  static nlohmann::ordered_json dimension_json(const Run3D&) { return 3; }
  static void add_mesh_quality(nlohmann::ordered_json& j, const Run3D& run) {
    j["mesh_quality"] = {{"min_dihedral_deg", run.mesh.quality.min_dihedral_deg},
                         {"max_dihedral_deg", run.mesh.quality.max_dihedral_deg},
                         {"max_radius_edge", run.mesh.quality.max_radius_edge},
                         {"curved_tets", run.dofs->n_curved()},
                         {"straightened_edge_nodes", run.dofs->n_straightened()}};
  }
  static double energy_J(const Run3D& run) { return run.energy.total_J; }
  static std::string energy_per(const Run3D&) { return "device"; }
  // What was meshed, and that energies, linkages and inductances are the whole device's.
  static void add_symmetry(nlohmann::ordered_json& j, const Run3D& run) {
    const auto& planes = run.spec.geometry3d.symmetry;
    if (planes.empty())
      return;
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const auto& p : planes)
      list.push_back({{"plane", axis_name(p.axis)}, {"field", field_name(p.field)}});
    j["symmetry"] = list;
    j["symmetry_factor"] = symmetry_factor(planes);
  }
  static ErrorEstimateRecord error_record(const Run3D& run) {
    const auto& e = run.error_estimate;
    return {e.energy_error_pct, e.energy_norm_error_pct, e.indicator, e.error_norm2_J,
            e.degraded_patches};
  }
  static int threads(const Run3D& run) { return run.threads; }
  static int ranks(const Run3D& run) { return run.ranks; }
  static void add_solver_extras(nlohmann::ordered_json& j, const Run3D& run) {
    // The coils' inductance matrix (part of postprocess), 3D only.
    j["timings_s"]["inductance"] = run.coil_results.inductance_s;
    // Rank 0 post-processes alone, on the cores the other processes lent it.
    j["post_processing_cores"] = cores_in_affinity();
    // TetGen met the domain as two pieces cut at this sphere (0: one piece).
    j["mesh_split_radius_mm"] = run.mesh.split_radius * 1e3;
    j["memory_guard"] = {
        {"estimated_tetrahedra", std::lround(run.mesh_estimate.tetrahedra)},
        {"estimated_peak_memory_MB",
         estimated_peak_memory_mb(run.mesh_estimate.tetrahedra, run.spec.order,
                                  static_cast<int>(run.spec.geometry3d.coils.size()))}};
  }
  static nlohmann::ordered_json region_json(const Run3D& run, std::size_t i) {
    const auto& r = run.energy.regions[i];
    if (r.volume_m3 == 0)
      return nullptr;
    nlohmann::ordered_json row = {{"name", r.name},
                                  {"volume_m3", r.volume_m3},
                                  {"energy_J", r.energy_J},
                                  {"peak_B_T", r.peak_B_T},
                                  {"nonlinear", r.nonlinear}};
    if (i < run.mesh.part_volumes.size())
      row["meshed_volume_m3"] = run.mesh.part_volumes[i];
    if (!r.from_image.empty())
      row["from_image"] = r.from_image;
    return row;
  }
  static void add_results(nlohmann::ordered_json& j, const Run3D& run) {
    if (!run.sections.empty())
      j["sections"] = sections_json(run.sections, run.spec.sections, run.spec.regions);
    if (run.coils)
      add_coil_results_json(j, run.coil_results);
    if (!run.forces.empty()) {
      j["forces_per"] = "device";
      j["forces"] = forces_json(run.forces);
    }
  }
  static void stage_vtu(OutputStage& stage, const Run3D& run, const VtuMaterials& materials) {
    VtuGrid grid = make_vtu_3d(*run.field, run.recovered_B.dof_average(), materials.of_region, 0,
                               materials.names, materials.region_names);
    // eta_K^2 (J) per cell.
    grid.cell_data.push_back(error_indicator_cells(run.problem, run.error_estimate.eta2_J));
    add_B_along_M(grid, run.demagnetization,
                  [&](std::size_t t) { return run.problem.is_shell(t); });
    write_vtu(stage.path_for("solution.vtu").string(), std::move(grid));
  }
  static std::string describe_head(const Run3D& run) {
    char buf[640];
    std::snprintf(buf, sizeof buf, "mesh     %zu tetrahedra, %zu nodes, dihedral %.1f..%.1f deg\n",
                  run.mesh.n_tets(), run.mesh.n_nodes(), run.mesh.quality.min_dihedral_deg,
                  run.mesh.quality.max_dihedral_deg);
    std::string s = buf;
    s += describe_solve_line(run.spec.order, run.free_unknowns, run.dofs->n_dofs(), run.report);
    std::snprintf(buf, sizeof buf, "energy   %.6g J%s\n", run.energy.total_J,
                  run.spec.geometry3d.symmetry.empty() ? ""
                                                       : " (whole device; the model is its share)");
    s += buf;
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
                  run.error_estimate.indicator.c_str(), run.timings.error_estimate);
    s += buf;
    if (run.adapt)
      s += describe_adapt_result(*run.adapt);
    return s;
  }
  static bool forces_per_metre(const Run3D&) { return false; }
  static const char* flux_unit(const Run3D&) { return "Wb"; }
  static std::string describe_coils(const Run3D& run) {
    return magfem::describe_coils(run.coil_results);
  }
  static std::string describe_time(const Run3D& run) {
    char buf[640];
    std::snprintf(buf, sizeof buf,
                  "time     mesh %.2f s, assemble %.2f s, solve %.2f s (set-up %.2f s), post "
                  "%.2f s, total %.2f s, peak %.0f MB\n",
                  run.timings.mesh, run.timings.assemble, run.timings.solve,
                  run.report.linear_setup_s, run.timings.postprocess, run.timings.total,
                  peak_memory_mb());
    return buf;
  }

private:
  // The P1 functions on the same tetrahedra: the coarse level of the p-multigrid
  // preconditioner (O(unknowns) to build, unused by the other solvers), and the shell's
  // equations for its smoother. Distributed, every process builds the whole of them and uses
  // its own rows.
  void set_coarse_space(const std::vector<int>& dof_to_eq) const {
    auto& linear = run_.spec.newton.linear;
    linear.coarse_prolongation =
        std::make_shared<const Eigen::SparseMatrix<double, Eigen::RowMajor>>(
            p1_prolongation(*run_.dofs, dof_to_eq));
    if (run_.problem.boundary == OuterKind3D::open)
      linear.smoother_block = std::make_shared<const std::vector<int>>(
          element_equations(*run_.dofs, dof_to_eq, run_.mesh.n_tets(),
                            [&](std::size_t t) { return run_.problem.is_shell(t); }));
  }
  // Own-row assembly (solver/distributed_rows.hpp) for a distributed P2 solve with p-multigrid:
  // the rows partitioned before the coil source field and the assembly, and the tetrahedra
  // touching this process's rows. Returns the tetrahedra whose source field this process
  // evaluates (with coils; else none).
  std::vector<std::size_t> partition_rows() const {
    auto& linear = run_.spec.newton.linear;
    linear.distributed_rows = nullptr;
    if (!world_.distributed() || run_.spec.order != 2)
      return {};
    const Assembler3D numbering(run_.problem, *run_.dofs,
                                {1, {}, std::make_shared<const std::vector<std::size_t>>()});
    const std::vector<int>& dof_to_eq = numbering.dof_to_equation();
    set_coarse_space(dof_to_eq);
    if (!distributed_runs_pmg(linear))
      return {};
    auto rows = std::make_shared<DistributedRows>(
        partition_distributed_rows(vertex_coupling_pattern(run_.mesh, *run_.dofs, dof_to_eq),
                                   *linear.coarse_prolongation, linear.smoother_block.get()));
    rows->tets = tets_touching_own_rows(*run_.dofs, run_.mesh.n_tets(), dof_to_eq, *rows);
    std::vector<std::size_t> source_tets;
    if (run_.coils)
      source_tets = source_table_tets(*run_.dofs, run_.mesh.n_tets(), dof_to_eq, *rows, share());
    linear.distributed_rows = std::move(rows);
    return source_tets;
  }
  // The assembler of this process's tetrahedra for the distributed solve: own-row assembly's
  // (built here, let go by the solve), else `assembler` itself (not owned).
  std::shared_ptr<const Assembler3D> distributed_share(const Assembler3D& assembler) const {
    const auto& rows = run_.spec.newton.linear.distributed_rows;
    if (!rows)
      return std::shared_ptr<const Assembler3D>(std::shared_ptr<void>(), &assembler);
    return std::make_shared<const Assembler3D>(
        run_.problem, *run_.dofs,
        AssemblyOptions3D{
            1, {}, std::shared_ptr<const std::vector<std::size_t>>(rows, &rows->tets)});
  }
  // The tetrahedra this process assembles (all of them in a serial run).
  ElementRange share() const {
    return world_.distributed() ? element_share(run_.mesh.n_tets(), world_.rank, world_.size)
                                : ElementRange{};
  }

  Run3D& run_;
  const RunOverrides& ov_;
  const MpiWorld& world_;
};

} // namespace

std::unique_ptr<Run3D> run_case_3d(CaseSpec spec, const RunOverrides& overrides) {
  return run_case<Discretisation3D>(std::move(spec), overrides);
}

nlohmann::ordered_json summary_json_3d(const Run3D& run) {
  return summary_json<Discretisation3D>(run);
}

std::vector<std::string> write_outputs_3d(const Run3D& run, const std::filesystem::path& out_dir) {
  return write_outputs<Discretisation3D>(run, out_dir);
}

std::string describe_run_3d(const Run3D& run) {
  return describe_run<Discretisation3D>(run);
}

} // namespace magfem
