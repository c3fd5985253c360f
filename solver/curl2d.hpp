#pragma once
// The one place where planar and axisymmetric 2D differ in the field: B from the potential,
// and the measure of the cross-section.
//   planar        A = A_z(x, y):  B = curl(A z_hat)   = (dA/dy, -dA/dx),        dV = dx dy
//   axisymmetric  A = A_phi(r, z) with x = r, y = z:
//                 B = curl(A phi_hat) = (-dA/dz, dA/dr + A/r),  dV = 2 pi r dr dz
// Axisymmetric unknown: A_phi itself, weighted by r, rather than the flux function
// psi = r A_phi weighted by 1/r. With A_phi = 0 on the axis, every integrand is bounded
// (A/r -> dA/dr), while (1/r) |grad psi|^2 of a piecewise-polynomial psi diverges
// logarithmically next to the axis. psi (the flux-line function) is formed for output only.
#include <Eigen/Core>

#include "core/constants.hpp"
#include "mesh/geometry2d.hpp"

namespace magfem {

// B at point x from the potential's value a and gradient there. On the axis (r = 0 exactly)
// A/r is replaced by its limit dA/dr, and B_r = -dA/dz by 0: A vanishes all along the axis
// (an element touching it at one vertex only would otherwise report its own slope there).
inline Eigen::Vector2d curl_2d(Symmetry2D s, double a, const Eigen::Vector2d& grad,
                               const Eigen::Vector2d& x) {
  if (s == Symmetry2D::planar)
    return {grad.y(), -grad.x()};
  if (x.x() > 0)
    return {-grad.y(), grad.x() + a / x.x()};
  return {0.0, 2 * grad.x()};
}

// Volume per unit cross-section area at x: 1 (per metre of length) or 2 pi r (whole turn).
inline double measure_2d(Symmetry2D s, const Eigen::Vector2d& x) {
  return s == Symmetry2D::planar ? 1.0 : 2.0 * pi * x.x();
}

} // namespace magfem
