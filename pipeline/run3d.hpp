#pragma once
// The 3D pipeline: case -> TetGen mesh -> scalar-potential problem -> Newton -> probes,
// energy, VTU. Mirrors run2d.hpp.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "mesh/mesh3d.hpp"
#include "mesh/mesh_estimate3d.hpp"
#include "pipeline/adapt_loop.hpp"
#include "pipeline/coil_run3d.hpp"
#include "pipeline/run2d.hpp"
#include "postproc/demagnetization.hpp"
#include "postproc/energy3d.hpp"
#include "postproc/error_estimate3d.hpp"
#include "postproc/field3d.hpp"
#include "postproc/patch_recovery3d.hpp"
#include "postproc/recovered_b3d.hpp"
#include "postproc/section_flux3d.hpp"
#include "solver/coil_source3d.hpp"
#include "solver/current_sensitivity3d.hpp"
#include "solver/dof_map3d.hpp"
#include "solver/problem3d.hpp"

namespace magfem {

struct Run3D {
  CaseSpec spec;
  Mesh3D mesh;
  MeshEstimate3D mesh_estimate; // before meshing (the memory guard's)
  std::unique_ptr<DofMap3D> dofs;
  int free_unknowns = 0; // the DOFs the system solves for: dofs less those boundary values fix
  Problem3D problem;
  std::unique_ptr<CaseCoils> coils; // null without coils
  CoilSource3D coil_source;         // problem.source points here when there are coils
  std::unique_ptr<Field3D> field;
  NewtonReport report;
  EnergySummary3D energy;
  RecoveredB3D recovered_B; // nodal B per region, computed once (VTU point data, peak |B|)
  // The superconvergent patch recovery of `field`, computed once: what the probes read (one
  // order better than the nodal averages) and what the error estimates compare with.
  std::unique_ptr<PatchRecovery3D> recovery;
  std::vector<ProbeTable> probes;
  std::vector<SectionFlux> sections; // parallel to spec.sections
  std::vector<ForceResult> forces;
  CoilResults coil_results;
  // A distributed run: du/dI per coil (free DOFs) with their variational correction, solved by
  // all processes together right after the solve (the inductance matrix needs them; rank 0
  // alone post-processes), and the seconds that took. Empty otherwise: the post-processing
  // solves for them.
  CurrentSensitivities3D coil_sensitivities;
  double coil_sensitivity_s = 0;
  ErrorEstimate3D error_estimate;        // energy-norm indicator per tet and in all
  std::vector<std::string> warnings;     // pipeline/result_checks.hpp
  DemagnetizationResult demagnetization; // per magnet: B . m_hat against the knee
  Timings timings;
  int threads = 1;                   // element-loop threads of the assembly
  int ranks = 1;                     // processes that solved it (MPI_COMM_WORLD under mpirun)
  std::optional<AdaptHistory> adapt; // set by run_adaptive_3d (adapt3d.hpp)
};

// Under mpirun (overrides.world.distributed()) every process calls this: each meshes the
// case (the meshes must agree bit for bit, else an internal error on all), assembles its
// share of the elements and takes part in the solve (solver/distributed_solve3d.hpp: Newton
// for nonlinear iron, and the coils' sensitivity solves for the inductance matrix); rank 0
// alone post-processes; the others return a Run3D without field and results, to be neither
// described nor written.
std::unique_ptr<Run3D> run_case_3d(CaseSpec spec, const RunOverrides& overrides = {});
// The memory guard's estimate of the peak memory (MB) run_case_3d would need for this case,
// from the size field alone (no mesh is made; seconds on large cases).
double estimated_memory_mb_3d(CaseSpec spec, const RunOverrides& overrides = {});
// The memory guard of run_case_3d without meshing: InputError (exit 2) naming the
// --mesh-scale that would fit when the case cannot be solved within the limit. A geometry
// the mesher rejects throws its MeshError (run_case_3d would name the part). Returns the
// estimate it checked.
MeshEstimate3D check_memory_3d(CaseSpec spec, const RunOverrides& overrides = {});
// The mesh run_case_3d would solve on (the overrides applied to spec, the memory guard
// included; straight-sided: order 2 curves the sphere edges later): `magfem mesh`.
Mesh3D mesh_case_3d(CaseSpec& spec, const RunOverrides& overrides, MeshEstimate3D& estimate);
// summary.json's content (what write_outputs_3d writes; also Solution.summary in Python).
nlohmann::ordered_json summary_json_3d(const Run3D& run);
std::vector<std::string> write_outputs_3d(const Run3D& run, const std::filesystem::path& out_dir);
std::string describe_run_3d(const Run3D& run);

} // namespace magfem
