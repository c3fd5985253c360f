#pragma once
// Commutation of a multi-coil actuator (thesis eq. 5.4): the coil currents that produce a
// demanded torque T_d with the least copper loss P = sum R_k i_k^2 (the thesis's criterion),
//   i = R^-1 Gamma^T (Gamma R^-1 Gamma^T)^-1 T_d,
// Gamma being the 3 x n matrix of torque constants (N m per ampere of each coil) and R the
// diagonal of coil resistances. With equal resistances R cancels and this is eq. 5.4 as the
// thesis writes it, i = Gamma^T (Gamma Gamma^T)^-1 T_d, the least two-norm solution; coils
// of different size or winding have different resistances, and then the least-norm currents
// cost more than the least loss.
#include <string>

#include <Eigen/Core>

namespace magfem {

using TorqueConstants = Eigen::Matrix<double, 3, Eigen::Dynamic>;

// Above this condition number (sigma_max / sigma_min of Gamma) the currents are not computed:
// the orientation cannot produce some torque direction with bounded currents, and currents
// from the inverse would be noise amplified by it. The thesis saw cond ~10 at its loss peaks
// and 2.5 elsewhere (sec. 5.3.3), so this only catches (near-)singular orientations.
inline constexpr double max_condition = 1e6;

struct Commutation {
  Eigen::VectorXd currents; // A per coil; empty if Gamma is ill-conditioned
  double power_W = 0;       // sum R_k i_k^2
  double peak_A = 0;        // max |i_k|
  double condition = 0;     // cond(Gamma) (2-norm); infinity if Gamma is rank-deficient
  bool ok = false;
  std::string warning; // why the currents are missing
};

// resistance_ohm: one per coil (Gamma's columns), each > 0; throws std::invalid_argument
// otherwise.
Commutation commutate(const TorqueConstants& gamma, const Eigen::VectorXd& resistance_ohm,
                      const Eigen::Vector3d& torque_Nm);

} // namespace magfem
