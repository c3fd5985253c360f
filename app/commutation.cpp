#include "app/commutation.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

#include <Eigen/Cholesky>
#include <Eigen/SVD>

namespace magfem {

Commutation commutate(const TorqueConstants& gamma, const Eigen::VectorXd& resistance_ohm,
                      const Eigen::Vector3d& torque_Nm) {
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
  // Eq. 5.4 as written: Gamma Gamma^T is 3 x 3 and symmetric positive definite here, and its
  // condition (cond(Gamma)^2 <= 1e12) leaves at least four significant digits.
  const Eigen::Matrix3d g = gamma * gamma.transpose();
  const Eigen::Vector3d y = g.llt().solve(torque_Nm);
  c.currents = gamma.transpose() * y;
  c.power_W = (resistance_ohm.array() * c.currents.array().square()).sum();
  c.peak_A = c.currents.cwiseAbs().maxCoeff();
  c.ok = true;
  return c;
}

} // namespace magfem
