#pragma once
// Vector spherical harmonic expansion of a shell magnetization that does not depend on the
// radius (the segments of a spherical-shell array):
//   M(theta, phi) = sum_nm  Mr_nm Y_nm e_rho  +  Mp_nm r grad Y_nm  +  (toroidal part),
// with the real harmonics Y_nm = Pbar_nm(cos theta) {cos m phi, sin m phi} (legendre.hpp).
// Only the radial (Mr) and poloidal (Mp) parts carry magnetic charge, so only they produce a
// field; the toroidal part is tangential and divergence-free and is not computed.
//
// The coefficients are the projections of M onto these harmonics: the phi integrals of each
// segment are done in closed form (products of cos/sin m phi with 1, cos phi, sin phi), the
// theta integrals by Gauss-Legendre per band of equal theta range with enough nodes for the
// highest degree (the integrand is a trigonometric polynomial of degree n_max + 2 in theta).
#include <vector>

#include <Eigen/Core>

#include "analytic/legendre.hpp"

namespace magfem {

// One segment of the shell: theta_min..theta_max, phi_min..phi_max (radians), with either a
// uniform magnetization vector (A/m, global Cartesian) or a radial one (A/m along e_rho).
struct ShellSegmentSource {
  double theta_min = 0, theta_max = 0;
  double phi_min = 0, phi_max = 0;
  Eigen::Vector3d parallel = Eigen::Vector3d::Zero(); // A/m
  double radial = 0;                                  // A/m
};

struct ShellExpansion {
  TriangularIndex index;
  // Per (n, m) in index order, A/m: coefficients of Pbar cos(m phi) and Pbar sin(m phi).
  std::vector<double> radial_cos, radial_sin;
  std::vector<double> poloidal_cos, poloidal_sin; // zero for n = 0

  // L2 norm over the unit sphere of the degree-n radial plus poloidal part of M (A/m):
  // sqrt(sum_m N_m (Mr^2 + n(n+1) Mp^2)), N_m = 1 for m = 0, 1/2 otherwise.
  std::vector<double> degree_amplitude() const;
};

// quadrature_scale multiplies the number of theta nodes per band (1 is converged to round-off
// for degrees up to n_max; larger values are for checking that claim). n_threads >= 1.
ShellExpansion expand_shell_magnetization(const std::vector<ShellSegmentSource>& segments,
                                          int n_max, double quadrature_scale, int n_threads);

} // namespace magfem
