#pragma once
// `magfem sweep`: rotate a rigid group of parts through a list of angles (or translate it
// through a list of offsets along an axis), solve each position (FE or analytic) and tabulate
// the torque about the origin and the force on the group.
//
// Positions are independent: they run on a small pool of worker threads, a failed position is
// recorded with its message and the others go on. The FE force comes from the Maxwell stress
// tensor on a sphere in the air gap that separates the group from the rest; the mesh is
// refined on that sphere (it is added as a probe surface) so that remeshing at every angle
// leaves little noise. The analytic force is the harmonic-form interaction when every magnet
// is axisymmetric about its own axis through the origin and a sphere separates the group
// from the rest (analytic/axisymmetric_interaction.hpp: microseconds, with a truncation
// bound), and the charge interaction otherwise (mu_r = 1 magnets in air).
#include <functional>
#include <optional>
#include <stop_token>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <nlohmann/json.hpp>

#include "casefile/case_spec.hpp"
#include "solver/mpi_context.hpp"
#include "studies/position_adapt.hpp"
#include "studies/position_memory.hpp"

namespace magfem {

class RunCheckpoint;

// How the group moves from one position to the next.
enum class SweepMotion {
  rotate,   // about `axis` through `point` by each of angles_deg
  translate // along `axis` by each of offsets_m (the force surface is chosen at each position)
};

// What a sweep reports and an adaptive sweep refines each position for (position_adapt.hpp):
// the torque of a rotation, the force of a translation.
inline const char* sweep_output(SweepMotion m) {
  return m == SweepMotion::translate ? "force" : "torque";
}

struct SweepOptions {
  std::string group; // Part3D::group to move
  SweepMotion motion = SweepMotion::rotate;
  Eigen::Vector3d axis = Eigen::Vector3d::UnitY(); // rotation axis or direction (any length)
  Eigen::Vector3d point = Eigen::Vector3d::Zero(); // a point on the rotation axis, metres
  // 3D translate: the torque is about `point` carried with the group (--point given), else
  // about the origin. (Planar translations always carry `point`; rotations turn about it.)
  bool carry_point = false;
  std::vector<double> angles_deg;       // rotate: positions
  std::vector<double> offsets_m;        // translate: positions
  bool analytic = false;                // charge model instead of FE
  std::optional<double> surface_radius; // metres; default: middle of the gap
  int jobs = 0;                         // worker threads (0: one per core)
  double mesh_scale = 0;                // FE: RunOverrides::mesh_scale
  int order = 0;                        // FE: RunOverrides::order
  double max_memory_gb = 0;             // FE: RunOverrides::max_memory_gb
  double analytic_tolerance = 1e-6;     // analytic: charge interaction tolerance
  // Finished positions found there are not solved again; new ones are recorded (not owned).
  RunCheckpoint* checkpoint = nullptr;
  // Under mpirun: the processes the positions are dealt to (studies/position_runner.hpp);
  // `jobs` is then per process, and the checkpoint rank 0's alone.
  MpiWorld world{};
  // A stop asked here starts no further position (studies/position_runner.hpp).
  std::stop_token stop;
};

struct SweepRow {
  double angle_deg = 0; // the position: degrees (rotate) or the offset in mm (translate)
  // About the origin, N m (planar and carry_point translations: about the carried point)
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();
  Eigen::Vector3d force = Eigen::Vector3d::Zero(); // on the group, N
  bool ok = false;
  std::string error; // why the position failed
  double seconds = 0;
  long unknowns = 0; // FE only
  // How the position was computed: "harmonic_interaction", "exterior_field_interaction",
  // "charge_pair_interaction" or "maxwell_stress_sphere"; for the harmonic form its degrees
  // and (rigorous) truncation bounds, for the other analytic ones their estimated error
  // (analytic/exterior_field_interaction.hpp, pair_interaction.hpp).
  std::string method;
  int n_max = 0;
  double torque_bound = 0, force_bound = 0; // N m, N (FE: the stress sphere's estimate)
  // FE with an `adapt:` section: the passes, and whether the sweep's output (torque of a
  // rotation, force of a translation) reached the accuracy.
  PositionAdapt adapt;
  // FE: the warnings of the position's mesh (an unresolved gap...), said once per kind for the
  // whole sweep (sweep_warnings).
  std::vector<std::string> mesh_warnings;
};

// The case with every part of `group` rotated by angle (radians, right-hand rule) about the
// axis through `point`; magnetizations turn with their parts. Throws InputError if no part
// belongs to the group or the case is not 3D.
CaseSpec rotate_group(const CaseSpec& spec, const std::string& group, const Eigen::Vector3d& axis,
                      double angle_rad, const Eigen::Vector3d& point);

// The case with every part and coil of `group` moved by `displacement` (metres); magnetizations
// move with their parts. Throws InputError (naming --move) if no part belongs to the group or
// the case is not 3D.
CaseSpec translate_group(const CaseSpec& spec, const std::string& group,
                         const Eigen::Vector3d& displacement);

// The positions as rows, sweep.csv and summary.json report them: degrees (rotate) or mm
// (translate); and the case moved to one of them.
std::vector<double> sweep_positions(const SweepOptions& options);
CaseSpec move_group(const CaseSpec& spec, const SweepOptions& options, double position);
// The point a 3D position's torque is about (metres): the origin, or with carry_point the
// sweep's point moved with the group to that position (mm, as sweep_positions gives it).
Eigen::Vector3d sweep_torque_point(const SweepOptions& options, double position);
// "angle_deg" or "position_mm": the position's column and key.
std::string sweep_position_key(SweepMotion motion);

// Radius (metres) of a sphere about the origin lying in air between the group and the rest,
// and whether the group is outside it. Throws InputError if the two do not separate radially.
struct StressSurface {
  double radius = 0;
  bool group_outside = false;
};
StressSurface stress_surface(const CaseSpec& spec, const std::string& group,
                             std::optional<double> radius);

// Parses "START:STEP:END" (END included within round-off) or "A,B,C"; throws InputError
// naming `option` (also used for --positions).
std::vector<double> parse_angle_list(const std::string& text,
                                     const std::string& option = "--angles");
// Parses "x,y,z" (three numbers); throws InputError naming the option.
Eigen::Vector3d parse_vector3(const std::string& option, const std::string& text);
// Parses x|y|z or "ax,ay,az" (planar cases also "ax,ay": a direction in the plane); throws
// InputError.
Eigen::Vector3d parse_axis(const std::string& text, bool planar = false);

// How many positions ran at once: SweepJobs (studies/position_memory.hpp); FE positions run
// as many at once as fit in the memory guard's limit.

// The options part of a sweep's checkpoint identity (pipeline/run_checkpoint.hpp): the group,
// the axis, point and surface radius as the caller was given them (text), the method, order
// and mesh scale. The command line and Python share it, so that each resumes the other's.
std::string sweep_checkpoint_options(const SweepOptions& o, const std::string& axis,
                                     const std::string& point, const std::string& surface_radius);

// A finished row as the checkpoint keeps it (every field, doubles exactly), and back; shared
// by the 3D and planar sweeps.
nlohmann::json sweep_row_to_json(const SweepRow& row);
SweepRow sweep_row_from_json(const nlohmann::json& saved, double angle_deg);

using SweepProgress = std::function<void(int done, int total)>;
// Under mpirun every process calls this; rank 0 gets the rows, the others none.
std::vector<SweepRow> run_sweep(const CaseSpec& spec, const SweepOptions& options,
                                const SweepProgress& progress = {}, SweepJobs* jobs = nullptr);

// The method of the rows ("mixed" if they differ; failed rows do not count; if none
// succeeded, the one the options ask for), and a line for the terminal on what it was
// (harmonic: degrees and worst truncation bound against the peak).
// (FE: the stress sphere's largest estimated torque and force errors against the peaks.)
std::string sweep_method(const std::vector<SweepRow>& rows, const SweepOptions& options);
std::string sweep_method_note(const std::vector<SweepRow>& rows, const SweepOptions& options);

// One warning per position whose adaptive refinement stopped at a limit before its accuracy.
std::vector<std::string> sweep_warnings(const std::vector<SweepRow>& rows,
                                        const SweepOptions& options);

// sweep.csv: angle_deg,Tx,Ty,Tz,Fx,Fy,Fz (successful positions only, in the order given);
// position_mm,... for a translation.
std::string sweep_csv(const std::vector<SweepRow>& rows, SweepMotion motion = SweepMotion::rotate);

// summary.json of a rotating sweep (3D or planar) but the provenance and the peak memory the
// command line adds: case, method, group, axis, positions (angle_deg, ok, seconds, and per
// method unknowns, truncation bounds or error estimates, the error of a failed one),
// failed_positions, jobs. Also magfem.sweep's `summary` in Python.
nlohmann::ordered_json sweep_summary(const std::string& case_file,
                                     const std::vector<SweepRow>& rows, const SweepOptions& options,
                                     const SweepJobs& jobs);

} // namespace magfem
