#pragma once
// The coil-pitch study of the thesis's sec. 5.3 (Figs. 5.9-5.11, Table 5.4): the average copper
// loss of the circular-coil array as a function of the coil pitch tau_c, for one rotor (magnets
// and back-iron of the case), by the charge model.
//
// How the thesis builds the array for a pitch (sec. 5.3.2-5.3.3), as we read it:
// - Coil size, eqs. 5.5-5.7: outer coil radius G_w + C_w = sqrt(2) tau_c / 4 (half the
//   distance to a diagonal neighbour), "reduced by 10 %" for manufacturing tolerances, split as
//   G_w = C_w / 4: G_w = 0.2 a, C_w = 0.8 a with a = 0.9 sqrt(2) tau_c / 4.
// - Layout (Fig. 5.7a, as examples/3d/spherical_actuator_design.yaml reads it): two rows tau_c/2
//   apart in theta about the equator (theta = 90 -+ tau_c/4), coils tau_c apart in phi along a
//   row, the rows offset by tau_c/2 (upper row at phi = +-tau_c/2, +-3 tau_c/2, .., lower row at
//   0, +-tau_c, ..), each row taking its positions nearest the front (phi = 0, the magnets'
//   side); a row whose count leaves one of a +- pair puts that coil at the back (phi = 180).
// - Coil count: the thesis removes coils at the back "if an overlap occurs": 14 coils for
//   40 <= tau_c <= 51, 12 for 52..60, 10 for 61..70. That is min(7, floor(360 / tau_c)) per row
//   (7 x 51 < 360 < 7 x 52, 6 x 60 = 360, 5 x 70 < 360), which this rule uses.
// - The radial extent, turns, fill factor and resistivity come from the case's first coil
//   (circular_coil_on_sphere about the origin); the loss scales as 1 / fill_factor.
// - The loss of a pitch is the mean over the orientations (the thesis: 15 x 15 x 15 = 3375
//   rotations over the +-45 deg range of motion) of P_x, P_y, P_z (1 N m about x, y, z by
//   eq. 5.4; see analytic/commutation.hpp), and P_mean is their average (Table 5.4). Orientations
//   where Gamma is ill-conditioned are left out and counted.
//
// Speed: the rotor's B_r is tabulated once on the coils' radial Gauss spheres
// (analytic/radial_field_table.hpp); every pitch and orientation then only interpolates.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analytic/radial_field_table.hpp"
#include "mesh/coil3d.hpp"
#include "studies/actuator.hpp"

namespace magfem {

// The thesis's circular-coil array at a coil pitch (radians), from a template coil (see above).
std::vector<Coil3D> thesis_coil_array(const Coil3D& coil_template, double pitch_rad);

struct CoilPitchRow {
  double pitch_deg = 0;
  int n_coils = 0;
  double gap_deg = 0, width_deg = 0; // G_w, C_w
  double P_W[3] = {0, 0, 0};         // mean loss for |T_d| about x, y, z
  int n_ill[3] = {0, 0, 0};          // orientations left out (ill-conditioned Gamma)
  double mean_W() const { return (P_W[0] + P_W[1] + P_W[2]) / 3; }
};

struct CoilPitchStudy {
  std::vector<CoilPitchRow> rows;
  std::size_t n_orientations = 0;
  double table_step_deg = 0;
  std::size_t table_points = 0;
  double table_seconds = 0, study_seconds = 0;
  std::vector<std::string> notes;
  // Row of the least P_mean (rows must not be empty).
  const CoilPitchRow& minimum() const;
};

// Table step of the rotor's B_r (degrees). Largest torque-constant error against the charge
// model at every quadrature point, relative to the largest constant (12 coils at 52 deg, three
// orientations; tests/studies/test_actuator_coil_pitch.cpp): 2 deg 8e-4, 1 deg 7e-5, 0.5 deg 6e-6.
// 1 deg is well below the coil quadrature's own 1e-3 (analytic/torque_constants.hpp).
inline constexpr double coil_pitch_table_step_deg = 1.0;

// The study for the pitches (degrees) over the orientations; torque_Nm is |T_d| (the loss
// scales with its square). Needs the analytic path (every magnet on the rotor); the case's
// coils are replaced by the thesis's array at each pitch. Throws InputError (exit 2) for a
// case it cannot run.
CoilPitchStudy run_coil_pitch_study(const CaseSpec& spec, const ActuatorOptions& options,
                                    const std::vector<double>& pitches_deg,
                                    const std::vector<Orientation>& orientations,
                                    double torque_Nm = 1.0,
                                    double table_step_deg = coil_pitch_table_step_deg);

// coil_pitch.csv: coil_pitch_deg,n_coils,G_w_deg,C_w_deg,P_x_W,P_y_W,P_z_W,P_mean_W,n_ill
std::string coil_pitch_csv(const CoilPitchStudy& study);

// The pitches (degrees) of the --coil-pitch options, after the checks the command makes of
// them (the charge model, no --torque, no --verify, the pitch list): InputError naming the
// option (exit 2).
std::vector<double> coil_pitch_degrees(const ActuatorOptions& options);

// summary.json of the study but its wall time ("seconds", which the command adds): the case,
// the rotor, the table and the pitch of least mean loss.
nlohmann::ordered_json coil_pitch_summary(const ActuatorOptions& options,
                                          const CoilPitchStudy& study);

// The command's --coil-pitch branch: coil_pitch.csv, coil_pitch.png and summary.json in
// options.out_dir. Returns the exit code.
int run_coil_pitch_command(const ActuatorOptions& options);

} // namespace magfem
