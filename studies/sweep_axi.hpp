#pragma once
// `magfem sweep CASE --move GROUP --axis z --positions START:STEP:END` for axisymmetric cases:
// translate a group of regions along the axis, solve each position and tabulate the axial
// force on the group (force versus separation of a voice coil, a solenoid plunger pair, ...).
//
// The force is the Lorentz force F_z = -int J_phi B_r 2 pi r dA: on the group's current
// regions when it has any, else, reversed, on the other current regions (Newton's third law:
// the isolated system feels no net force). A group that carries no current and faces none (a
// magnet over iron) takes the stress-tensor force of the case's one `contour` force on a
// region of the group, whose box moves with it.
// Positions run on a small pool of threads like the 3D sweep; a failed position is recorded.
#include <functional>
#include <stop_token>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "casefile/case_spec.hpp"
#include "solver/mpi_context.hpp"
#include "studies/position_adapt.hpp"

namespace magfem {

class RunCheckpoint;

struct AxiSweepOptions {
  std::string group;               // RegionSpec::group to move
  std::vector<double> positions_m; // axial displacements of the group, metres
  int jobs = 0;                    // worker threads (0: one per core)
  double mesh_scale = 0;           // RunOverrides::mesh_scale
  int order = 0;                   // RunOverrides::order
  double max_memory_gb = 0;        // RunOverrides::max_memory_gb (studies/position_memory.hpp)
  // Finished positions found there are not solved again; new ones are recorded (not owned).
  RunCheckpoint* checkpoint = nullptr;
  // Under mpirun: the processes the positions are dealt to (as SweepOptions::world).
  MpiWorld world{};
  // A stop asked here starts no further position (studies/position_runner.hpp).
  std::stop_token stop;
};

struct AxiSweepRow {
  double position_m = 0;
  double fz_N = 0; // axial force on the group
  bool ok = false;
  std::string error;
  double seconds = 0;
  long unknowns = 0;
  PositionAdapt adapt; // with an adapt: section (refined for Fz)
};

// The case with every region of `group` moved by dz (metres) along the axis; radial
// magnetization centres move with their regions. Throws InputError (naming --move) if the
// case is not axisymmetric or no region is in the group.
CaseSpec move_group_axi(const CaseSpec& spec, const std::string& group, double dz);

// How the sweep takes the force on the group, as its summary.json `method` says: "lorentz",
// "lorentz_reaction" (on the other current regions, reversed) or "stress_tensor_contour".
// Throws InputError as run_sweep_axi when there is no way.
std::string sweep_axi_method(const CaseSpec& spec, const std::string& group);

using AxiSweepProgress = std::function<void(int done, int total)>;
// Throws InputError if the force on the group cannot be had (sweep_axi_method). Under
// mpirun every process calls this; rank 0 gets the rows, the others none.
std::vector<AxiSweepRow> run_sweep_axi(const CaseSpec& spec, const AxiSweepOptions& options,
                                       const AxiSweepProgress& progress = {});

// The options part of an axial sweep's checkpoint identity (as sweep_checkpoint_options).
std::string sweep_axi_checkpoint_options(const AxiSweepOptions& o);

// sweep.csv: position_mm,Fz_N (successful positions, in the given order).
std::string sweep_axi_csv(const std::vector<AxiSweepRow>& rows);

// summary.json of the sweep but the peak memory the command line adds: case, method, group,
// positions (position_mm, ok, seconds, unknowns, error of a failed one), failed_positions.
// Also magfem.sweep's `summary` in Python.
// One warning per position whose adaptive refinement stopped at a limit.
std::vector<std::string> sweep_axi_warnings(const std::vector<AxiSweepRow>& rows);

nlohmann::ordered_json sweep_axi_summary(const CaseSpec& spec, const std::vector<AxiSweepRow>& rows,
                                         const AxiSweepOptions& options);

} // namespace magfem
