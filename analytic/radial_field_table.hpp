#pragma once
// The radial flux density of a rotor tabulated on spheres about the origin, in the rotor's own
// frame, for torque constants over many orientations and coil arrays (the coil-pitch study).
//
// Why only the radial component: a coil on a sphere about the origin carries its current
// tangentially (x . j = 0), so its Lorentz torque density x x (j x B) = j (x . B) - B (x . j)
// = j (x . B) sees only B_r. Rotations keep |x|, so the points of a coil's quadrature stay on
// the spheres of its radial Gauss nodes for every orientation: the table needs those radii only
// and interpolates in angle alone.
//
// Interpolation: 4 x 4 Lagrange (cubic) in (theta, phi) on an equal-angle grid, periodic in phi
// and continued over the poles by f(-theta, phi) = f(theta, phi + pi). The step is what the
// caller trades for accuracy (tests/studies/test_actuator_coil_pitch.cpp measures it).
#include <vector>

#include <Eigen/Core>

#include "analytic/torque_constants.hpp"

namespace magfem {

class RadialFieldTable {
public:
  // b_rotor: B in the rotor's frame (all table points in one call); radii in metres (each
  // > 0); step in radians (rounded down so that pi is a whole number of steps).
  RadialFieldTable(const FieldAtPoints& b_rotor, std::vector<double> radii, double step_rad);

  // B_r e_r (tesla) at points whose radius is one of the table's within 1e-9 relative; throws
  // std::invalid_argument for any other point. Usable as a FieldAtPoints for torque constants
  // of coils on spheres about the origin (see above; other coils would get a wrong torque).
  std::vector<Eigen::Vector3d> operator()(const std::vector<Eigen::Vector3d>& points) const;

  double step_rad() const { return step_; }
  std::size_t size() const { return values_.size(); }

private:
  double radial(std::size_t radius, double theta, double phi) const;
  double at(std::size_t radius, int i, int j) const; // i may leave [0, n_theta] (over a pole)

  std::vector<double> radii_;
  int n_theta_ = 0, n_phi_ = 0; // theta_i = i h (i = 0..n_theta), phi_j = j h (j < n_phi)
  double step_ = 0;
  std::vector<double> values_; // B_r, [radius][i][j]
};

// The sorted distinct radial Gauss nodes of the torque quadrature of coils (metres).
std::vector<double> quadrature_radii(const std::vector<CoilField>& coils, const CoilRule& rule);

} // namespace magfem
