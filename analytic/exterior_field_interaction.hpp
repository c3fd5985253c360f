#pragma once
// Force and torque on magnets of any shape (segment arrays, cylinders, boxes) in the field of
// concentric axisymmetric bodies that a sphere about the origin separates from them - the
// gravity-compensator prototype's cylinders around its hemisphere. Outside the sphere of
// radius a enclosing the bodies their potential is the exterior harmonic series
//   psi(x) = (1/4pi) sum_n q_n r^-(n+1) P_n(x.axis / r)
// with the closed-form moments q_n of axisymmetric_interaction.hpp, so
//   H = (1/4pi) sum_n q_n r^-(n+2) [ (n+1) P_n(u) x/r - P_n'(u) (axis - u x/r) ],  u = x.axis/r,
// O(n_max) per point instead of a quadrature over the bodies' faces. The charges of the other
// magnets (sigma = M.n on faces, rho_m = -div M in radial volumes) are integrated with tensor
// Gauss rules whose order follows from each box's distance to the sphere (the series is
// analytic outside it) and its angles (gauss_error.hpp); F = mu0 sum q H, T = sum (x-p) x dF.
//
// Accuracy printed: the truncation tail (rigorous from the moments' bounds at the smallest
// radius of the charges) plus the quadrature's a priori estimate (x10, as in
// pair_interaction.hpp).
#include <vector>

#include <Eigen/Core>

#include "postproc/maxwell_stress.hpp"
#include "analytic/analytic_magnet.hpp"

namespace magfem {

struct ExteriorFieldOptions {
  double tolerance = 1e-6; // relative: per box and for the series' tail
  int max_order = 8;       // Gauss points per direction per box
  int n_limit = 20000;     // refuse (std::domain_error) if more degrees would be needed
  int n_threads = 0;       // 0 = std::thread::hardware_concurrency()
};

struct ExteriorFieldInteraction {
  ForceTorque on;          // on the magnets `on`, torque about the torque point
  double force_error = 0;  // estimated |error| of the force, N
  double torque_error = 0; // estimated |error| of the torque, N m
  int n_max = 0;           // degrees summed
};

// Throws std::invalid_argument (saying why) if a magnet of `by` is not an axisymmetric body
// (axisymmetric_body) or a magnet of `on` reaches into the sphere enclosing `by`, and
// std::domain_error if the series would need more than n_limit degrees.
ExteriorFieldInteraction exterior_field_interaction(const std::vector<AnalyticMagnet>& on,
                                                    const std::vector<AnalyticMagnet>& by,
                                                    const Eigen::Vector3d& torque_point,
                                                    const ExteriorFieldOptions& options = {});

} // namespace magfem
