#pragma once
// Uniformly magnetized balls for the interaction tests: their fields are exact point dipoles
// outside, so every interaction method is checked against the dipole-dipole formulas.
#include <Eigen/Core>

#include "core/constants.hpp"
#include "analytic/analytic_magnet.hpp"

namespace magfem::test {

inline AnalyticMagnet ball(const Eigen::Vector3d& c, double a, const Eigen::Vector3d& dir,
                           double B_r) {
  AnalyticMagnet m;
  m.shape = SphericalSegment{0, a, 0, pi, 0, 2 * pi};
  m.placement.translation = c;
  m.magnetization.pattern = Magnetization::Pattern::parallel;
  m.magnetization.direction = dir.normalized();
  m.B_r = B_r;
  return m;
}

// Dipole moment (A m^2) of a ball of radius a and remanence B_r.
inline Eigen::Vector3d moment(double a, const Eigen::Vector3d& dir, double B_r) {
  return (4.0 / 3.0) * pi * a * a * a * (B_r / mu0) * dir.normalized();
}

} // namespace magfem::test
