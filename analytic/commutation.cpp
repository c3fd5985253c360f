#include "analytic/commutation.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include <Eigen/Cholesky>
#include <Eigen/SVD>

namespace magfem {

Commutation commutate(const TorqueConstants& gamma, const Eigen::VectorXd& resistance_ohm,
                      const Eigen::Vector3d& torque_Nm) {
  if (resistance_ohm.size() != gamma.cols() || !(resistance_ohm.array() > 0).all() ||
      !resistance_ohm.allFinite())
    throw std::invalid_argument("commutate: one positive resistance per coil expected");
  Commutation c;
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(gamma);
  const auto& s = svd.singularValues();
  // Fewer than three coils leave Gamma Gamma^T singular.
  const double smin = s.size() < 3 ? 0.0 : s(s.size() - 1);
  c.condition = smin > 0 ? s(0) / smin : std::numeric_limits<double>::infinity();
  if (!(c.condition <= max_condition)) {
    char buf[160];
    std::snprintf(buf, sizeof buf,
                  "Gamma is ill-conditioned (cond %.3g > %.0e): some torque direction needs "
                  "unbounded currents here",
                  c.condition, max_condition);
    c.warning = buf;
    return c;
  }
  // Eq. 5.4 weighted by the resistances (Lagrange: 2 R i = Gamma^T lambda): Gamma R^-1
  // Gamma^T is 3 x 3 and symmetric positive definite here, and its condition
  // (cond(Gamma)^2 max(R) / min(R)) leaves several significant digits for any real winding.
  const Eigen::VectorXd conductance = resistance_ohm.cwiseInverse();
  const Eigen::Matrix3d g = gamma * conductance.asDiagonal() * gamma.transpose();
  const Eigen::Vector3d y = g.llt().solve(torque_Nm);
  c.currents = conductance.asDiagonal() * (gamma.transpose() * y);
  c.power_W = (resistance_ohm.array() * c.currents.array().square()).sum();
  c.peak_A = c.currents.cwiseAbs().maxCoeff();
  c.ok = true;
  return c;
}

} // namespace magfem
