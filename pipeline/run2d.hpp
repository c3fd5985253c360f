#pragma once
// The 2D pipeline, stage by stage: case -> mesh -> problem -> assemble/solve -> postprocess.
// A library (not just main) so that tests run whole cases in-process.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "casefile/case_spec.hpp"
#include "core/progress.hpp"
#include "mesh/mesh2d.hpp"
#include "mesh/mesh_error.hpp"
#include "mesh/size_field2d.hpp"
#include "pipeline/adapt_loop.hpp"
#include "pipeline/force_results.hpp"
#include "pipeline/timings.hpp"
#include "postproc/demagnetization.hpp"
#include "postproc/energy2d.hpp"
#include "postproc/error_estimate2d.hpp"
#include "postproc/field2d.hpp"
#include "postproc/patch_recovery2d.hpp"
#include "postproc/probe_table.hpp"
#include "postproc/section_flux2d.hpp"
#include "solver/dof_map2d.hpp"
#include "solver/mpi_context.hpp"
#include "solver/newton.hpp"
#include "solver/problem2d.hpp"

namespace magfem {

// Command-line overrides of case settings (refinement studies, quick checks).
struct RunOverrides {
  int order = 0;                // 0 = as in the case
  double mesh_scale = 0;        // 0 = as in the case; multiplies every mesh size
  double domain_radius = 0;     // metres; 0 = as in the case
  double max_memory_gb = 0;     // memory guard limit (memory_guard.hpp); 0 = available now
  Progress* progress = nullptr; // console progress (not owned); null = silent
  // Memory guard, for runs that go on at once (sweep --jobs): their number and the limit
  // they share, fixed once for all (MB; 0 = measured at the check). Each gets its share.
  int parallel_runs = 1;
  double shared_memory_mb = 0;
  // The processes of an mpirun solving this case together (3D linear cases only; run3d.hpp).
  MpiWorld world{};
  // Adaptive refinement (adapt2d.hpp): the size bound of the mesher's refinement for this
  // pass (not owned; null = the case's sizes).
  const SizeField2D* refine_sizes = nullptr;
  // 3D: print the mesh's warnings as soon as it is made (they stay in Run3D::mesh.warnings and
  // the summary either way). A sweep says them once for all its positions instead
  // (studies/position_mesh_warnings.hpp).
  bool say_mesh_warnings = true;
};

// An axisymmetric coil (region with turns and current): its flux linkage with the total field,
// the differential inductance d lambda / dI at the operating point (in linear media the
// self-inductance, magnets and other currents aside) and the apparent one, linkage / current
// (which counts the magnets' and other coils' flux).
struct CoilResult2D {
  std::string name;
  double turns = 0, current_A = 0, flux_linkage_Wb = 0;
  double inductance_H = 0;         // d lambda / dI
  double linkage_per_ampere_H = 0; // lambda / I (0 at zero current)
  // The other coil of a mirrored pair about the plane z = 0 (coil_results_axi.hpp), else empty.
  std::string mirror_image;
};
// summary.json's "coils" (also the Python module's Solution.coils).
nlohmann::ordered_json coils_json_2d(const std::vector<CoilResult2D>& coils);
struct Run2D;
// summary.json's "inductance_H": the matrix and, when mirrored pairs are present, which
// entries came from the complementary solve.
nlohmann::ordered_json inductance_json_2d(const Run2D& run);

struct Run2D {
  CaseSpec spec;
  Mesh2D mesh;
  std::unique_ptr<DofMap2D> dofs;
  int free_unknowns = 0; // the DOFs the system solves for: dofs less those boundary values fix
  Problem2D problem;
  std::unique_ptr<Field2D> field;
  // The superconvergent patch recovery of `field`: what the probes read (and the Python B).
  std::unique_ptr<PatchRecovery2D> recovery;
  NewtonReport report;
  EnergySummary2D energy;
  ErrorEstimate2D error_estimate; // ZZ estimate of the discretisation error (error_estimate2d.hpp)
  std::vector<ProbeTable> probes;
  std::vector<ForceResult> forces;
  std::vector<SectionFlux> sections;      // parallel to spec.sections (per energy_per)
  std::vector<CoilResult2D> coil_results; // axisymmetric only
  Eigen::MatrixXd inductance_H; // d lambda / dI between run.coil_results (H), axisymmetric only
  std::vector<std::string> warnings;     // pipeline/result_checks.hpp
  DemagnetizationResult demagnetization; // per magnet: B . m_hat against the knee
  Timings timings;
  std::optional<AdaptHistory> adapt; // set by run_adaptive_2d (adapt2d.hpp)
};

// A mesher error (bad part) as the InputError naming the case file's region and field.
[[noreturn]] void throw_mesh_error_2d(const CaseSpec& spec, const MeshError& e);

// The mesh run_case_2d would solve on (the overrides applied to spec): `magfem mesh`.
Mesh2D mesh_case_2d(CaseSpec& spec, const RunOverrides& overrides);

// Meshes and solves; throws InputError (bad case), SolveError (no convergence).
std::unique_ptr<Run2D> run_case_2d(CaseSpec spec, const RunOverrides& overrides = {});

// summary.json's content (what write_outputs_2d writes; also Solution.summary in Python).
nlohmann::ordered_json summary_json_2d(const Run2D& run);
// Writes summary.json, one CSV per probe and solution.vtu, all-or-nothing.
std::vector<std::string> write_outputs_2d(const Run2D& run, const std::filesystem::path& out_dir);

// Prints the short human summary.
std::string describe_run_2d(const Run2D& run);

} // namespace magfem
