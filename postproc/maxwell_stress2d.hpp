#pragma once
// Maxwell stress tensor force and torque from a solved 2D field (per metre of length, SI;
// force in the xy-plane, torque along z about a given point): on a circle in air, and
// averaged over an air-gap band (Arkkio). The quadrature is postproc/maxwell_stress.hpp's;
// this file supplies B from the FE solution.
//
// Sampling: FieldSampling::recovered (the default) interpolates, with the element's shape
// functions, the nodal average of B over the air triangles around each node (air only: B
// jumps across the surfaces of magnets, iron and coils, and an average across them would
// spoil the first layer of air elements); FieldSampling::element takes the FE B of the
// triangle containing the point. Measured (tests/postproc/test_force2d.cpp, order 2, magnet
// and conductors): both are equally accurate (circle torque rms error 0.010 % element vs
// 0.014 % recovered, band 0.0006 % vs 0.002 %, circles around a conductor 0.023 % vs 0.027 %;
// at twice the element size 0.038 % vs 0.043 %), but the recovered field is continuous, so
// the trapezoid rule converges on it (2048 vs 8192 points: 1e-9 relative, element field
// 5e-6, falling only like 1/n): the default point count is safe on any mesh.
#include <vector>

#include <Eigen/Core>

#include "postproc/field2d.hpp"
#include "postproc/maxwell_stress.hpp"
#include "postproc/point_locator2d.hpp"

namespace magfem {

// B of a solved 2D field at any point of the physical domain. Holds references to the field
// and the locator (which must outlive it) and, for recovered sampling, the nodal B values.
class FieldSampler2D {
public:
  FieldSampler2D(const Field2D& field, const PointLocator2D& locator,
                 FieldSampling sampling = FieldSampling::recovered);

  FieldSampling sampling() const { return sampling_; }
  // B at x (tesla). Throws std::invalid_argument if x is outside the meshed domain (or in the
  // open-boundary shell) or not in air (mu_r 1, no magnet, no current): a stress surface
  // through matter does not measure the force on its inside.
  Eigen::Vector2d B(const Eigen::Vector2d& x) const;

private:
  const Field2D& field_;
  const PointLocator2D& locator_;
  FieldSampling sampling_;
  std::vector<Eigen::Vector2d> recovered_; // per DOF, air only (recovered sampling)
};

// Sample counts; 0 means the default.
struct StressOptions2D {
  int n_points = 0; // per circle (default 2048)
  int n_radii = 0;  // band only (default 8)
};

// Force and torque on everything inside the circle (centre, radius in metres), per metre.
ForceTorque maxwell_stress_circle_2d(const FieldSampler2D& B, const Eigen::Vector2d& center,
                                     double radius, const Eigen::Vector2d& torque_point,
                                     const StressOptions2D& options = {});

// Arkkio's band average over r_inner..r_outer (all in air), computed as the mean of the
// circle results over n_radii Gauss-Legendre radii (maxwell_stress_on_band), not by element
// integration, so the band need not coincide with element layers.
ForceTorque maxwell_stress_band_2d(const FieldSampler2D& B, const Eigen::Vector2d& center,
                                   double r_inner, double r_outer,
                                   const Eigen::Vector2d& torque_point,
                                   const StressOptions2D& options = {});

// Consistency check: the circle result at two radii, and their relative difference.
ForceComparison maxwell_stress_two_circles_2d(const FieldSampler2D& B,
                                              const Eigen::Vector2d& center, double radius_a,
                                              double radius_b, const Eigen::Vector2d& torque_point,
                                              const StressOptions2D& options = {});

} // namespace magfem
