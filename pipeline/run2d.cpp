#include "pipeline/run2d.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "casefile/symmetry_check2d.hpp"
#include "core/output_stage.hpp"
#include "materials/material_library.hpp"
#include "mesh/mesh_error.hpp"
#include "mesh/mesher2d.hpp"
#include "pipeline/coil_results_axi.hpp"
#include "pipeline/demagnetization_results.hpp"
#include "pipeline/force2d.hpp"
#include "pipeline/inductance_matrix_output.hpp"
#include "pipeline/memory_guard.hpp"
#include "pipeline/result_checks.hpp"
#include "pipeline/run_case.hpp"
#include "pipeline/run_report.hpp"
#include "pipeline/run_summary.hpp"
#include "pipeline/section_results.hpp"
#include "pipeline/solver_summary.hpp"
#include "pipeline/symmetry2d.hpp"
#include "pipeline/vtu_materials.hpp"
#include "postproc/point_locator2d.hpp"
#include "postproc/probes2d.hpp"
#include "postproc/vtu_export2d.hpp"
#include "postproc/vtu_export_revolved.hpp"
#include "solver/assembler2d.hpp"
#include "solver/triangle_lagrange.hpp"

namespace magfem {
namespace {

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

} // namespace

nlohmann::ordered_json coils_json_2d(const std::vector<CoilResult2D>& coils) {
  auto j = nlohmann::ordered_json::array();
  for (const auto& c : coils) {
    j.push_back({{"name", c.name},
                 {"turns", c.turns},
                 {"current_A", c.current_A},
                 {"flux_linkage_Wb", c.flux_linkage_Wb},
                 {"inductance_H", c.inductance_H},
                 {"linkage_per_ampere_H", c.linkage_per_ampere_H}});
    if (!c.mirror_image.empty())
      j.back()["mirror_image"] = c.mirror_image;
  }
  return j;
}

nlohmann::ordered_json inductance_json_2d(const Run2D& run) {
  std::vector<std::string> names;
  for (const auto& c : run.coil_results)
    names.push_back(c.name);
  auto j = inductance_matrix_json(names, run.inductance_H);
  // Entries between two coils of mirrored pairs came from the complementary solve
  // (coil_results_axi.hpp); say which, when any did.
  const auto paired = [&](std::size_t i) { return !run.coil_results[i].mirror_image.empty(); };
  if (std::any_of(run.coil_results.begin(), run.coil_results.end(),
                  [](const auto& c) { return !c.mirror_image.empty(); })) {
    auto rows = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < run.coil_results.size(); ++i) {
      auto row = nlohmann::ordered_json::array();
      for (std::size_t k = 0; k < run.coil_results.size(); ++k)
        row.push_back(paired(i) && paired(k));
      rows.push_back(row);
    }
    j["complementary_solve"] = rows;
  }
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

namespace {

// The planar and axisymmetric stages of run_case (run_case.hpp): Lagrange triangles of order
// 1 or 2 for the vector potential A_z (planar) or r A_phi (axisymmetric, the weight r in the
// element), one process, Newton with CHOLMOD or CG.
class Discretisation2D {
public:
  using Run = Run2D;
  using DofMap = DofMap2D;
  using Field = Field2D;
  using Locator = PointLocator2D;
  using Assembler = Assembler2D;
  static constexpr const char* element_name = "triangles";

  Discretisation2D(Run2D& run, const RunOverrides& ov) : run_(run), ov_(ov) {}

  static void apply_overrides(CaseSpec& spec, const RunOverrides& ov) {
    magfem::apply_overrides(spec, ov);
  }
  static std::size_t n_elements(const Mesh2D& mesh) { return mesh.n_triangles(); }
  static double total_energy(const Run2D& run) { return run.energy.total_J_per_m; }

  // A planar or axisymmetric factor stays affordable up to the direct limit (nested
  // dissection fill grows like n log n in 2D), so the cost prediction, a second AMD ordering
  // of the whole matrix, is not run (it was a tenth of a 100k-unknown axisymmetric solve).
  void tune_linear_solver(LinearSolverOptions& options) const { options.direct_max_gflop = 0; }
  void check_before_mesh() const {}
  Mesh2D mesh() const { return mesh_case(run_.spec, ov_.refine_sizes); }
  void check_mesh() const {
    check_stress_surfaces_2d(run_.spec, run_.mesh);
    // The memory guard on the mesh itself, before anything large is assembled.
    check_memory_2d(static_cast<double>(run_.mesh.n_triangles()), run_.spec.order,
                    MemoryLimit{ov_.max_memory_gb, ov_.shared_memory_mb, ov_.parallel_runs},
                    ov_.mesh_scale > 0 ? ov_.mesh_scale : 1.0);
  }
  Problem2D build_problem() const { return magfem::build_problem(run_.spec, run_.mesh); }
  void prepare_dofs() const {}
  Assembler2D make_assembler() const { return Assembler2D(run_.problem, *run_.dofs); }
  void prepare_solver(const Assembler2D&) const {}
  NewtonReport solve(Assembler2D& assembler, Eigen::VectorXd& u) const {
    return solve_nonlinear(assembler, u, run_.spec.newton);
  }
  bool post_processes() const { return true; }

  EnergySummary2D summarize_energy(const std::vector<std::string>& names) const {
    return summarize_energy_2d(*run_.field, names);
  }
  void recover() const { run_.recovery = std::make_unique<PatchRecovery2D>(*run_.field); }
  PointLocator2D probe_locator() const { return PointLocator2D(run_.mesh); }
  ProbeTable sample_probe(const PointLocator2D& locator, const ProbeSpec& probe) const {
    return sample_probe_2d(*run_.field, locator, probe, run_.spec.length_unit, run_.recovery.get());
  }
  SectionFlux integrate_section(const SectionSpec& section) const {
    const double depth = run_.spec.stack_length > 0 ? run_.spec.stack_length : 1.0;
    return integrate_section_whole_2d(*run_.field, section, depth, run_.spec);
  }
  std::vector<ForceResult> forces() const { return compute_forces_2d(run_); }
  void coil_results(const Assembler2D& assembler, const Eigen::VectorXd& u) const {
    compute_coil_results_axi(run_, assembler, u);
  }
  void estimate_error() const {
    run_.error_estimate = estimate_error_2d(*run_.recovery, run_.energy.total_J_per_m);
  }
  void check_finite_fields() const {}
  void scale_to_whole_device() const { scale_to_whole_device_2d(run_); }
  std::vector<std::string> mesh_warnings() const { return {}; }

  // What the report writes (run_report.hpp).
  static constexpr int dimension = 2;
  static nlohmann::ordered_json dimension_json(const Run2D& run) {
    return run.spec.axisymmetric() ? nlohmann::ordered_json("axi") : nlohmann::ordered_json(2);
  }
  static void add_mesh_quality(nlohmann::ordered_json& j, const Run2D& run) {
    // Top-level min/max_angle_deg predate mesh_quality and stay for the scripts that read them.
    j["min_angle_deg"] = run.mesh.quality.min_angle_deg;
    j["max_angle_deg"] = run.mesh.quality.max_angle_deg;
    j["mesh_quality"] = {{"min_angle_deg", run.mesh.quality.min_angle_deg},
                         {"max_angle_deg", run.mesh.quality.max_angle_deg}};
  }
  // Planar energies and forces are per metre, times the stack length when the case has one.
  static double length(const Run2D& run) {
    return run.spec.stack_length > 0 ? run.spec.stack_length : 1.0;
  }
  static double energy_J(const Run2D& run) { return run.energy.total_J_per_m * length(run); }
  static std::string energy_per(const Run2D& run) {
    return run.spec.axisymmetric()     ? "body of revolution"
           : run.spec.stack_length > 0 ? "stack"
                                       : "metre of length";
  }
  static void add_symmetry(nlohmann::ordered_json& j, const Run2D& run) {
    add_symmetry_json_2d(j, run.spec);
  }
  static ErrorEstimateRecord error_record(const Run2D& run) {
    return {run.error_estimate.energy_error_pct, run.error_estimate.energy_norm_error_pct,
            run.error_estimate.indicator, run.error_estimate.total_eta2 * length(run),
            run.error_estimate.degraded_patches};
  }
  static int threads(const Run2D&) { return 1; }
  static int ranks(const Run2D&) { return 1; }
  static void add_solver_extras(nlohmann::ordered_json& j, const Run2D& run) {
    j["memory_guard"] = {
        {"estimated_peak_memory_MB",
         estimated_peak_memory_mb_2d(static_cast<double>(run.mesh.n_triangles()), run.spec.order)}};
  }
  static nlohmann::ordered_json region_json(const Run2D& run, std::size_t i) {
    const auto& r = run.energy.regions[i];
    if (r.area_m2 == 0)
      return nullptr;
    nlohmann::ordered_json row = {{"name", r.name},
                                  {"area_m2", r.area_m2},
                                  {"energy_J", r.energy_J_per_m * length(run)},
                                  {"peak_B_T", r.peak_B_T},
                                  {"nonlinear", r.nonlinear}};
    if (!r.from_image.empty())
      row["from_image"] = r.from_image;
    return row;
  }
  static void add_results(nlohmann::ordered_json& j, const Run2D& run) {
    if (!run.forces.empty()) {
      j["forces_per"] = energy_per(run);
      j["forces"] = forces_json(run.forces);
    }
    if (!run.sections.empty())
      j["sections"] = sections_json(run.sections, run.spec.sections, run.spec.regions);
    if (!run.coil_results.empty()) {
      j["coils"] = coils_json_2d(run.coil_results);
      j["inductance_H"] = inductance_json_2d(run);
    }
  }
  static void stage_vtu(OutputStage& stage, const Run2D& run, const VtuMaterials& materials) {
    VtuGrid grid =
        make_vtu_2d(*run.field, materials.of_region, 0, materials.names, materials.region_names);
    // eta_K^2 per cell (J/m planar, J axisymmetric).
    grid.cell_data.push_back(error_indicator_cells(run.problem, run.error_estimate.eta2));
    add_B_along_M(grid, run.demagnetization,
                  [&](std::size_t t) { return run.problem.is_shell(t); });
    write_vtu(stage.path_for("solution.vtu").string(), std::move(grid));
    if (run.spec.write_revolved_vtu)
      write_vtu(stage.path_for("solution_revolved.vtu").string(),
                make_vtu_revolved(*run.field, materials.of_region, 0, materials.names,
                                  materials.region_names));
  }
  static std::string describe_head(const Run2D& run) {
    char buf[512];
    std::string s;
    std::snprintf(buf, sizeof buf, "mesh     %zu triangles, %zu nodes, min angle %.1f deg\n",
                  run.mesh.n_triangles(), run.mesh.n_nodes(), run.mesh.quality.min_angle_deg);
    s += buf;
    s += describe_solve_line(run.spec.order, run.free_unknowns, run.dofs->n_dofs(), run.report);
    std::snprintf(buf, sizeof buf, "energy   %.6g %s\n", run.energy.total_J_per_m,
                  run.spec.axisymmetric() ? "J (body of revolution)" : "J/m");
    s += buf;
    std::snprintf(buf, sizeof buf,
                  "error    estimated energy error %.3g %% (energy norm %.3g %%, %s)\n",
                  run.error_estimate.energy_error_pct, run.error_estimate.energy_norm_error_pct,
                  run.error_estimate.indicator.c_str());
    s += buf;
    if (run.adapt)
      s += describe_adapt_result(*run.adapt);
    for (const auto& r : run.energy.regions)
      if (r.nonlinear && r.area_m2 > 0) {
        std::snprintf(buf, sizeof buf, "iron     %-20s peak |B| %.3f T\n", r.name.c_str(),
                      r.peak_B_T);
        s += buf;
      }
    return s;
  }
  static bool forces_per_metre(const Run2D& run) {
    return run.spec.stack_length <= 0 && !run.spec.axisymmetric();
  }
  static const char* flux_unit(const Run2D& run) {
    return run.spec.stack_length > 0 || run.spec.axisymmetric() ? "Wb" : "Wb/m";
  }
  static std::string describe_coils(const Run2D& run) {
    std::string s;
    char buf[512];
    for (const auto& c : run.coil_results) {
      std::snprintf(buf, sizeof buf,
                    "coil     %-20s linkage %.6g Wb, L = dlambda/dI = %.6g H (differential), "
                    "linkage / I = %.6g H (apparent)\n",
                    c.name.c_str(), c.flux_linkage_Wb, c.inductance_H, c.linkage_per_ampere_H);
      s += buf;
    }
    // Once per mirrored pair, after the coils.
    for (std::size_t i = 0; i < run.coil_results.size(); ++i)
      if (const auto& c = run.coil_results[i]; !c.mirror_image.empty() && c.name < c.mirror_image)
        s += "pair     " + c.name + " and " + c.mirror_image +
             " are mirror images: the share drives both; their self and mutual inductance "
             "from a second solve with the plane's other condition\n";
    if (run.inductance_H.rows() > 1 && run.inductance_H.rows() <= 4)
      s += "L = dlambda/dI (H, differential):\n" + describe_inductance_matrix(run.inductance_H);
    return s;
  }
  static std::string describe_time(const Run2D& run) {
    char buf[512];
    std::snprintf(
        buf, sizeof buf,
        "time     mesh %.3f s, assemble %.3f s, solve %.3f s, post %.3f s, total %.3f s\n",
        run.timings.mesh, run.timings.assemble, run.timings.solve, run.timings.postprocess,
        run.timings.total);
    return buf;
  }

private:
  Run2D& run_;
  const RunOverrides& ov_;
};

} // namespace

std::unique_ptr<Run2D> run_case_2d(CaseSpec spec, const RunOverrides& overrides) {
  return run_case<Discretisation2D>(std::move(spec), overrides);
}

nlohmann::ordered_json summary_json_2d(const Run2D& run) {
  return summary_json<Discretisation2D>(run);
}

std::vector<std::string> write_outputs_2d(const Run2D& run, const std::filesystem::path& out_dir) {
  return write_outputs<Discretisation2D>(run, out_dir);
}

std::string describe_run_2d(const Run2D& run) {
  return describe_run<Discretisation2D>(run);
}

} // namespace magfem
