#pragma once
// Maxwell stress tensor force and torque from a solved 3D field on a sphere in air (the
// thesis's eq. 3.44 in the air gap around a body). The quadrature is
// postproc/maxwell_stress.hpp's (Gauss-Legendre in theta, trapezoid in phi); this file
// supplies B from the FE solution, locating every quadrature point with PointLocator3D.
//
// Sampling: FieldSampling::recovered (the default) interpolates, with the element's shape
// functions, the nodal average of B over the air tets around each node (air only: B jumps
// across magnet and iron surfaces, and an average across them would spoil the first layer of
// air elements); FieldSampling::element takes the FE B of the tet containing the point.
// Measured on two magnetized spheres (tests/postproc/test_force3d.cpp, DISABLED_SamplingStudy,
// order 2, 231k unknowns): both carry the same discretization error (force 0.1-0.45 %,
// torque 0.05-0.3 % at radii 11-13 mm), but the recovered field, being continuous, lets the
// quadrature converge: going from 96 x 192 to 192 x 384 points moves it by 1-6e-4 and the
// element result by up to 1.4e-3; from 48 x 96, 1.6e-3 vs 4e-3. Hence recovered sampling
// and 96 x 192 points by default (18k located points, ~0.1 s).
#include <vector>

#include <Eigen/Core>

#include "postproc/field3d.hpp"
#include "postproc/maxwell_stress.hpp"
#include "postproc/point_locator3d.hpp"

namespace magfem {

// B of a solved 3D field at any point of the physical domain. Holds references to the field
// and the locator (which must outlive it) and, for recovered sampling, the nodal B values.
class FieldSampler3D {
public:
  FieldSampler3D(const Field3D& field, const PointLocator3D& locator,
                 FieldSampling sampling = FieldSampling::recovered);

  FieldSampling sampling() const { return sampling_; }
  // B at x (tesla). Throws std::invalid_argument if x is outside the physical domain (or in
  // the open-boundary shell) or not in air (mu_r 1, no magnet): a stress surface through
  // matter does not measure the force on its inside.
  Eigen::Vector3d B(const Eigen::Vector3d& x) const;
  std::vector<Eigen::Vector3d> B(const std::vector<Eigen::Vector3d>& xs) const;

private:
  const Field3D& field_;
  const PointLocator3D& locator_;
  FieldSampling sampling_;
  std::vector<Eigen::Vector3d> recovered_; // per DOF, air only (recovered sampling)
};

// Sample counts; 0 means the default (n_theta 96, n_phi 2 n_theta).
struct StressOptions3D {
  int n_theta = 0;
  int n_phi = 0;
};

// Force (N) and torque (N m, about torque_point) on everything inside the sphere (centre,
// radius in metres), which must lie in air.
ForceTorque maxwell_stress_sphere_3d(const FieldSampler3D& B, const Eigen::Vector3d& center,
                                     double radius, const Eigen::Vector3d& torque_point,
                                     const StressOptions3D& options = {});

// The same on the surface of an axis-aligned box (centre, edge lengths in metres): for
// parts that are not round (a pole piece in a narrow gap). Gauss-Legendre on every face,
// n_long points along the longest edge and proportionally fewer on the shorter ones.
std::vector<SurfacePoint> box_quadrature(const Eigen::Vector3d& center, const Eigen::Vector3d& size,
                                         int n_long);
ForceTorque maxwell_stress_box_3d(const FieldSampler3D& B, const Eigen::Vector3d& center,
                                  const Eigen::Vector3d& size, const Eigen::Vector3d& torque_point,
                                  int n_long = 96);
// Consistency check: the sphere result at two radii, and their relative difference.
ForceComparison maxwell_stress_two_spheres_3d(const FieldSampler3D& B,
                                              const Eigen::Vector3d& center, double radius_a,
                                              double radius_b, const Eigen::Vector3d& torque_point,
                                              const StressOptions3D& options = {});

} // namespace magfem
