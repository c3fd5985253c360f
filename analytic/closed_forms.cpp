#include "analytic/closed_forms.hpp"

#include <cmath>

#include "core/constants.hpp"

namespace magfem {

namespace {

// B of a point dipole mu0 m at the origin, written with mu0 m = (4 pi / 3) a^3 mu0 M so that
// only the remanence and the radius enter.
Eigen::Vector3d dipole_B(const Eigen::Vector3d& d, double radius,
                         const Eigen::Vector3d& remanence) {
  const double r = d.norm();
  const Eigen::Vector3d e = d / r;
  const double scale = std::pow(radius / r, 3) / 3.0; // (mu0 / 4 pi) m / r^3 over mu0 M
  return scale * (3.0 * e.dot(remanence) * e - remanence);
}

} // namespace

Eigen::Vector3d uniform_sphere_B(const Eigen::Vector3d& x, const Eigen::Vector3d& center,
                                 double radius, const Eigen::Vector3d& remanence) {
  const Eigen::Vector3d d = x - center;
  if (d.norm() <= radius) {
    return (2.0 / 3.0) * remanence;
  }
  return dipole_B(d, radius, remanence);
}

Eigen::Vector3d uniform_shell_B(const Eigen::Vector3d& x, const Eigen::Vector3d& center,
                                double r_inner, double r_outer, const Eigen::Vector3d& remanence) {
  if (r_inner <= 0) {
    return uniform_sphere_B(x, center, r_outer, remanence);
  }
  return uniform_sphere_B(x, center, r_outer, remanence) -
         uniform_sphere_B(x, center, r_inner, remanence);
}

Eigen::Vector2d uniform_cylinder_B(const Eigen::Vector2d& x, const Eigen::Vector2d& center,
                                   double radius, const Eigen::Vector2d& remanence) {
  const Eigen::Vector2d d = x - center;
  const double r = d.norm();
  if (r <= radius) {
    return 0.5 * remanence;
  }
  // 2D dipole: B = (a/r)^2 / 2 [2 (e.Br) e - Br], i.e. B_r ~ cos, B_phi ~ sin of the angle
  // from M, both with amplitude (B_r / 2)(a/r)^2.
  const Eigen::Vector2d e = d / r;
  return 0.5 * (radius / r) * (radius / r) * (2.0 * e.dot(remanence) * e - remanence);
}

namespace {

// ln of (S + 2 R r s) with S = R^2 + r^2, in the form R^2 + r^2 + 2 R r s.
double log_distance2(double R, double r, double s) {
  return std::log(R * R + r * r + 2 * R * r * s);
}

} // namespace

double harwin_eq3_radial_B(const HarwinCylinder& c, double R, double phi) {
  const double r = c.magnet_radius;
  const double s = std::sin(phi);
  return mu0 * c.current_per_rad / (2 * pi * R) *
         (log_distance2(R, r, s) - log_distance2(R, r, -s));
}

double harwin_eq4_radial_B(const HarwinCylinder& c, double R, double phi) {
  const double r = c.magnet_radius;
  const double sp = std::sin(phi + c.band_half_width);
  const double sm = std::sin(phi - c.band_half_width);
  const double sum = log_distance2(R, r, sm) - log_distance2(R, r, -sp) + log_distance2(R, r, sp) -
                     log_distance2(R, r, -sm);
  return mu0 * c.current_per_rad / (4 * pi * R) * sum;
}

double harwin_eq4_as_printed_radial_B(const HarwinCylinder& c, double R, double phi) {
  const double r = c.magnet_radius;
  const double sp = std::sin(phi + c.band_half_width);
  const double sm = std::sin(phi - c.band_half_width);
  const double sum = log_distance2(R, r, -sp) - log_distance2(R, r, sm) + log_distance2(R, r, -sm) -
                     log_distance2(R, r, sp);
  return mu0 * c.current_per_rad / (2 * pi * R) * sum;
}

} // namespace magfem
