#pragma once
// What a solve reports, planar, axisymmetric and 3D alike: summary.json, the output folder
// (probe CSVs, solution.vtu, forces.csv, sections.csv, summary.json, all-or-nothing) and the
// console summary, each written once over the discretisation D of run_case.hpp.
//
// What D provides for them (static, on a const run):
//   summary   dimension (2 or 3); dimension_json(run) (2, "axi", 3); add_mesh_quality(j, run);
//   energy_J(run) and
//             energy_per(run) (what the energy is the whole of); add_symmetry(j, run);
//             error_record(run); threads(run), ranks(run); add_solver_extras(j, run);
//             region_json(run, i) (null: left out); add_results(j, run) (forces, sections,
//             coils, in the order the dimension has always written them)
//   outputs   stage_vtu(stage, run, materials)
//   console   describe_head(run) (mesh, solve, energy, error, iron, adapt lines);
//             forces_per_metre(run); flux_unit(run); describe_coils(run); describe_time(run)
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/output_stage.hpp"
#include "pipeline/adapt_loop.hpp"
#include "pipeline/demagnetization_results.hpp"
#include "pipeline/force_results.hpp"
#include "pipeline/result_tables.hpp"
#include "pipeline/run_summary.hpp"
#include "pipeline/vtu_materials.hpp"
#include "postproc/vtu_writer.hpp"

namespace magfem {

template <class D> nlohmann::ordered_json summary_json(const typename D::Run& run) {
  nlohmann::ordered_json j;
  add_run_header(j, {run.spec.file, D::dimension_json(run), run.spec.order, D::n_elements(run.mesh),
                     run.mesh.n_nodes(), static_cast<std::size_t>(run.dofs->n_dofs()),
                     static_cast<std::size_t>(run.free_unknowns)});
  D::add_mesh_quality(j, run);
  add_energy(j, D::energy_J(run), D::energy_per(run));
  D::add_symmetry(j, run);
  add_error_estimate(j, D::error_record(run), run.timings.error_estimate);
  add_solve_record(j, run.report, run.timings, D::threads(run), D::ranks(run));
  D::add_solver_extras(j, run);
  auto& regions = j["regions"];
  for (std::size_t i = 0; i < run.energy.regions.size(); ++i)
    if (auto row = D::region_json(run, i); !row.is_null())
      regions.push_back(std::move(row));
  for (const auto& p : run.probes)
    j["probes"].push_back(p.name + ".csv");
  D::add_results(j, run);
  if (run.adapt)
    j["adapt"] = adapt_json(*run.adapt);
  add_demagnetization(j, run.demagnetization, D::dimension);
  j["warnings"] = run.warnings;
  return j;
}

template <class D>
std::vector<std::string> write_outputs(const typename D::Run& run,
                                       const std::filesystem::path& out_dir) {
  std::filesystem::create_directories(out_dir);
  OutputStage stage(out_dir);
  stage_probe_tables(stage, run.probes);
  if (run.spec.write_vtu)
    D::stage_vtu(stage, run, vtu_materials(run.spec.regions));
  stage_force_and_section_tables(stage, run.forces, run.sections, run.spec.regions);
  stage.write_text("summary.json", summary_json<D>(run).dump(2) + "\n");
  stage.commit();
  return stage.written();
}

template <class D> std::string describe_run(const typename D::Run& run) {
  std::string s = D::describe_head(run);
  s += describe_forces(run.forces, D::forces_per_metre(run));
  char buf[512];
  for (const auto& f : run.sections) {
    std::snprintf(buf, sizeof buf, "section  %-20s flux %.6g %s, mean Bn %.6g T, mean |B| %.6g T\n",
                  f.name.c_str(), f.total.flux_Wb, D::flux_unit(run), f.total.Bn_avg_T(),
                  f.total.B_avg_T());
    s += buf;
  }
  s += D::describe_coils(run);
  s += D::describe_time(run);
  for (const auto& w : run.warnings)
    s += "warning  " + w + "\n";
  return s;
}

// The per-element error indicator eta_K^2 as VTU cell data, in the order the VTU writes the
// cells (the open boundary's shell is not written).
template <class Problem>
VtuArray error_indicator_cells(const Problem& problem, const std::vector<double>& eta2) {
  VtuArray a{"error_indicator", 1, {}};
  for (std::size_t t = 0; t < eta2.size(); ++t)
    if (!problem.is_shell(t))
      a.values.push_back(eta2[t]);
  return a;
}

} // namespace magfem
