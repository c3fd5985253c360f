#pragma once
// `magfem actuator CASE.yaml --rotor GROUP --orientations SPEC [--torque Tx,Ty,Tz]
//  [--analytic] [--param NAME=VALUE ..] [--mesh-scale S] [--order 1|2] [--out DIR]`
//  [--verify [--accuracy PCT [--max-passes N] [--max-unknowns N]]]
//  [--coil-pitch START:STEP:END] (the thesis's coil-pitch study, studies/actuator_coil_pitch.hpp):
// a multi-coil spherical actuator (thesis ch. 5-6) over a set of rotor orientations. For each
// orientation: the torque constants Gamma of every coil (analytic/torque_constants.hpp), the
// currents of eq. 5.4 for the demanded torque with their copper loss, peak and cond(Gamma)
// (analytic/commutation.hpp). Without --torque, the three unit torques (1 N m about x, y, z) give
// P_x, P_y, P_z as the thesis's power study does (Figs. 5.8-5.14).
//
// Sign: Gamma and T_d are the Lorentz torque on the coils, as the thesis's eqs. 3.23 and 5.2
// define them; the rotor receives -T_d.
//
// --verify: at the first, middle and last orientation, FE with the commutated currents in the
// coils (the rotor turned into place): the Lorentz torque on all coils together against T_d.
// It includes what Gamma leaves out (the coils' pull on the iron, ~i^2). With the case's
// adapt: or --accuracy each of these solves refines for that torque (a `lorentz` force over
// every coil, pipeline/solve_case.hpp), and reports its estimated error beside it. Under mpirun
// (`mpirun -n N magfem actuator ... --verify`) these solves are dealt to the processes.
//
// Orientation (rx, ry, rz) in degrees: the rotor turned first by rx about the fixed x axis,
// then by ry about the fixed y axis, then by rz about the fixed z axis, all through the
// origin: R = Rz(rz) Ry(ry) Rx(rx).
//
// Field: --analytic uses the charge model with spherical imaging (analytic/charge_model.hpp;
// the harmonic model cannot image an inner iron sphere). FE solves the magnets and iron
// without coil currents, once if the field turns rigidly with the rotor (every magnetic part
// on the rotor or a sphere about the origin), else once per orientation with the rotor turned
// (studies/sweep.hpp rotate_group).
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "analytic/commutation.hpp"
#include "analytic/torque_constants.hpp"
#include "casefile/adapt_spec.hpp"
#include "casefile/case_parameter.hpp"
#include "casefile/case_spec.hpp"
#include "core/option_table.hpp"
#include "solver/mpi_context.hpp"
#include "studies/position_adapt.hpp"

namespace magfem {
class Progress;
struct Run3D;
struct RunOverrides;
} // namespace magfem

namespace magfem {

struct Orientation {
  double rx_deg = 0, ry_deg = 0, rz_deg = 0;
};

// R = Rz(rz) Ry(ry) Rx(rx).
Eigen::Matrix3d rotor_rotation(const Orientation& o);

// "rx=A,ry=B,rz=C" where each value is START:STEP:END (END included within round-off), a
// number, or numbers separated by commas ("rx=0,15,ry=0"); a missing axis is 0. The grid
// varies rz fastest, then ry, then rx. Anything that names an existing file (or ends in .csv)
// is read as a CSV with the header rx_deg,ry_deg,rz_deg. Throws InputError naming
// --orientations.
std::vector<Orientation> parse_orientations(const std::string& spec);

struct ActuatorOptions {
  std::string case_file;
  std::string rotor;
  std::string orientations;
  std::optional<Eigen::Vector3d> torque_Nm; // none: unit torques about x, y, z
  bool analytic = false;
  ParameterOverrides parameters;
  double mesh_scale = 0; // FE: RunOverrides
  int order = 0;
  bool verify = false;
  AdaptOverrides adapt;   // --verify: --accuracy, --max-passes, --max-unknowns over adapt:
  CoilRule coil_rule;     // quadrature over each coil (analytic/torque_constants.hpp)
  std::string coil_pitch; // --coil-pitch START:STEP:END (deg): the study of
                          // studies/actuator_coil_pitch.hpp instead of the case's coils
  std::string out_dir;
  bool quiet = false;           // --quiet: no progress lines
  Progress* progress = nullptr; // console progress (not owned); null = silent
  // Under mpirun (--verify): the processes the verification solves are dealt to
  // (studies/position_runner.hpp); every process computes the torque constants and
  // commutations (they choose the currents), rank 0 alone gets the verifications and writes.
  MpiWorld world{};
};

// --coil-quadrature's "N_R,N_ALPHA,ALPHA_PANELS,N_AZIMUTH"; throws InputError naming `option`.
CoilRule parse_coil_rule(const std::string& option, const std::string& text);

// Parses the arguments after `actuator`; throws InputError naming the option.
// The command's options, one table (also what `magfem help actuator` and the completion offer).
std::vector<OptionInfo> actuator_option_infos();
ActuatorOptions parse_actuator_options(const std::vector<std::string>& args);

struct ActuatorDemand {
  std::string name; // "T_d", or "P_x", "P_y", "P_z"
  Eigen::Vector3d torque_Nm;
  std::vector<Commutation> commutations; // one per orientation
};

struct ActuatorResult {
  std::string method; // "charge_model" or "fe"
  std::vector<std::string> coil_names;
  Eigen::VectorXd resistance_ohm;
  std::vector<Orientation> orientations;
  std::vector<TorqueConstants> gamma; // one per orientation, 3 x coils
  std::vector<ActuatorDemand> demands;
  int n_field_solves = 0; // FE solves, or 1 charge model
  double gamma_seconds = 0;
  std::vector<std::string> notes;
};

struct Verification {
  std::string demand; // ActuatorDemand::name
  Orientation orientation;
  Eigen::Vector3d demanded_Nm = Eigen::Vector3d::Zero();
  Eigen::Vector3d produced_Nm = Eigen::Vector3d::Zero(); // FE Lorentz torque on all coils
  bool ok = false;                                       // false: ill-conditioned, not solved
  // The estimated error of |produced_Nm|, N m, from the adaptive passes (NaN without them: a
  // Lorentz torque has no one-mesh estimate yet), and the passes.
  double produced_error_Nm = std::numeric_limits<double>::quiet_NaN();
  PositionAdapt adapt;
};

// The --verify solves (see above); options.mesh_scale, options.order and options.adapt apply. Under
// mpirun (options.world) every process calls this; rank 0 gets the verifications, the others none.
std::vector<Verification> verify_commutation(const CaseSpec& spec, const ActuatorOptions& options,
                                             const ActuatorResult& result);

// Checks the case against the options (exit-2 InputError: unknown rotor group, coils on the
// rotor or inside its swept sphere, stator parts inside it, no coils).
void check_actuator_case(const CaseSpec& spec, const std::string& rotor);

// The rotor's B (tesla) in its own frame by the charge model with spherical imaging; every
// magnet must be on the rotor (InputError naming the magnet otherwise). Approximations made
// go to `notes`. The model lives as long as the returned function.
FieldAtPoints analytic_rotor_field(const CaseSpec& spec, const std::string& rotor,
                                   std::vector<std::string>& notes);

// The rotor's B (tesla) in its own frame by one FE solve of the case's magnets and iron
// (coils, probes and forces left out: the coils enter only through the Lorentz torque, which
// needs the field without their currents). Only for a field that turns rigidly with the rotor
// (every magnetic part on the rotor, or a sphere about the origin); InputError naming the
// rotor otherwise. The returned function holds the run; `run`, if given, receives it too (for
// its size and timings). A point outside the meshed domain is an InputError naming `coils`.
FieldAtPoints fe_rotor_field(const CaseSpec& spec, const std::string& rotor,
                             const RunOverrides& overrides,
                             std::shared_ptr<const Run3D>* run = nullptr);

// Torque (N m, about the origin) on the rotor at each orientation from the case's own coil
// currents in the rotor's field b_rotor (its own frame: analytic_rotor_field, fe_rotor_field):
// minus the Lorentz torque on the coils, -sum_k Gamma_k i_k over the coils that carry current.
// No check that the rotor can turn (check_actuator_case): rotors that reach around the coils
// (seed 001's design B) are allowed.
std::vector<Eigen::Vector3d> rotor_torque(const CaseSpec& spec, const FieldAtPoints& b_rotor,
                                          const std::vector<Orientation>& orientations,
                                          const CoilRule& rule = {});
// rotor_torque in the charge model's field (analytic_rotor_field).
std::vector<Eigen::Vector3d> analytic_rotor_torque(const CaseSpec& spec, const std::string& rotor,
                                                   const std::vector<Orientation>& orientations,
                                                   const CoilRule& rule = {});

// The rotor torque about y (rotor_torque) against the inclination about y, from -max_deg to
// max_deg in steps of step_deg (seed 001's Fig. 4 curve).
struct InclinationTorque {
  std::vector<double> ry_deg, ty_Nm;
  double peak_Nm() const; // max |T_y|
};
InclinationTorque torque_about_y(const CaseSpec& spec, const FieldAtPoints& b_rotor, double max_deg,
                                 double step_deg);
// torque_about_y in the charge model's field.
InclinationTorque analytic_torque_about_y(const CaseSpec& spec, const std::string& rotor,
                                          double max_deg, double step_deg);

// Gamma at every orientation (analytic or FE) and the commutation of every demand.
ActuatorResult run_actuator(const CaseSpec& spec, const ActuatorOptions& options,
                            const std::vector<Orientation>& orientations);

// commutation.csv of one demand: rx_deg,ry_deg,rz_deg,i_<coil>_A..,P_W,i_peak_A,cond_Gamma
// (ill-conditioned rows keep cond_Gamma and leave the rest empty).
std::string commutation_csv(const ActuatorResult& result, const ActuatorDemand& demand);
// torque_constants.csv: rx_deg,ry_deg,rz_deg,coil,kx,ky,kz (N m/A).
std::string torque_constants_csv(const ActuatorResult& result);

// The command: reads, checks (before anything is written), runs and writes commutation.csv
// (or commutation_x/y/z.csv without --torque), torque_constants.csv, power_map.png and
// summary.json through one OutputStage. Returns the exit code.
int run_actuator_command(ActuatorOptions options);

} // namespace magfem
