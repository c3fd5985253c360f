#pragma once
// Force and torque from the Maxwell stress tensor on a closed surface in air, as pure
// quadrature on a field callback (no FE types): the FE wrappers (maxwell_stress2d.hpp,
// maxwell_stress3d.hpp) and the analytic references (analytic/analytic_force.hpp) share it.
//
//   T_ij = (1/mu0) (B_i B_j - delta_ij |B|^2 / 2),   T.n = (1/mu0) (B (B.n) - n |B|^2 / 2),
//   F = oint T.n dS,   torque about p = oint (x - p) x (T.n) dS   (thesis eqs. 3.41-3.44).
//
// The surface must lie in air (mu_r = 1, no current): then the result is the total force on
// everything inside it and, for the exact field, does not depend on the surface. 2D results
// are per metre of length (multiply by the stack length).
#include <functional>
#include <vector>

#include <Eigen/Core>

namespace magfem {

struct ForceTorque {
  // N (2D: N per metre of length, z component 0).
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  // N m about the given point (2D: N m per metre of length, x and y components 0).
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();
};

inline ForceTorque operator+(const ForceTorque& a, const ForceTorque& b) {
  return {a.force + b.force, a.torque + b.torque};
}
inline ForceTorque operator-(const ForceTorque& a, const ForceTorque& b) {
  return {a.force - b.force, a.torque - b.torque};
}
// Scaling, e.g. a 2D result per metre times the stack length.
inline ForceTorque operator*(double s, const ForceTorque& a) {
  return {s * a.force, s * a.torque};
}

// B in tesla at a point in metres.
using FieldFunction = std::function<Eigen::Vector3d(const Eigen::Vector3d&)>;
// Evaluates B at many points at once (e.g. a threaded ChargeModel).
using BatchFieldFunction =
    std::function<std::vector<Eigen::Vector3d>(const std::vector<Eigen::Vector3d>&)>;
// 2D: (B_x, B_y) in tesla at (x, y) in metres.
using FieldFunction2D = std::function<Eigen::Vector2d(const Eigen::Vector2d&)>;

// How the FE wrappers sample B: the element field itself (discontinuous across elements) or
// the nodal recovery interpolated with the element's shape functions (continuous).
enum class FieldSampling { element, recovered };

// Force and torque on everything inside the sphere (centre, radius in metres). n_theta
// Gauss-Legendre points in theta, n_phi midpoint (trapezoid) points in phi, which is
// spectrally accurate for smooth periodic data.
ForceTorque maxwell_stress_on_sphere(const FieldFunction& B, const Eigen::Vector3d& center,
                                     double radius, const Eigen::Vector3d& torque_point,
                                     int n_theta, int n_phi);
ForceTorque maxwell_stress_on_sphere(const BatchFieldFunction& B, const Eigen::Vector3d& center,
                                     double radius, const Eigen::Vector3d& torque_point,
                                     int n_theta, int n_phi);

// The sphere's quadrature points (row-major: theta outer, phi inner), for callers that
// evaluate B themselves; integrate with maxwell_stress_sum.
struct SurfacePoint {
  Eigen::Vector3d x; // metres
  Eigen::Vector3d n; // outward unit normal
  double w;          // area weight, m^2 (2D: length weight, m)
};
std::vector<SurfacePoint> sphere_quadrature(const Eigen::Vector3d& center, double radius,
                                            int n_theta, int n_phi);
// sum_i w_i T(B_i).n_i and its moment about torque_point; B[i] belongs to points[i].
ForceTorque maxwell_stress_sum(const std::vector<SurfacePoint>& points,
                               const std::vector<Eigen::Vector3d>& B,
                               const Eigen::Vector3d& torque_point);

// 2D, per metre of length: the circle (centre, radius) sampled at n_points equally spaced
// angles (trapezoid rule, spectrally accurate for smooth periodic data).
ForceTorque maxwell_stress_on_circle(const FieldFunction2D& B, const Eigen::Vector2d& center,
                                     double radius, const Eigen::Vector2d& torque_point,
                                     int n_points);

// 2D band average (Arkkio): the circle result averaged over the radii r_inner..r_outer,
//   F = 1/(r_outer - r_inner) int_band T.e_r dA,  T_z = 1/(mu0 (r_outer - r_inner)) int_band
//   r B_r B_theta dA (about the centre),
// i.e. the band integral evaluated as n_radii Gauss-Legendre circles of n_points each. For
// the exact field every circle gives the same answer; for an FE field the average smooths
// the element-to-element noise a single circle picks up.
ForceTorque maxwell_stress_on_band(const FieldFunction2D& B, const Eigen::Vector2d& center,
                                   double r_inner, double r_outer,
                                   const Eigen::Vector2d& torque_point, int n_radii, int n_points);

// The same force and torque from two computations (two radii, two methods), with their
// relative differences |a - b| / max(|a|, |b|) (0 when both vanish).
struct ForceComparison {
  ForceTorque a, b;
  double force_rel_diff = 0;
  double torque_rel_diff = 0;
};
ForceComparison compare_force_torque(const ForceTorque& a, const ForceTorque& b);

} // namespace magfem
