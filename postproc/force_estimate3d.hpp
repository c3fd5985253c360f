#pragma once
// The Maxwell-stress force and torque of the superconvergent patch-recovered B*
// (patch_recovery3d.hpp) on given surface points: one of the fields whose disagreement on
// the reported surface is the force's error estimate (pipeline/force3d.cpp). Where B* is one
// order better than the nodal average (patches inside a region), F(B*) - F(B_avg)
// approximates the reported result's error; it is an estimate, not a bound.
#include <vector>

#include "postproc/maxwell_stress.hpp"
#include "postproc/patch_recovery3d.hpp"
#include "postproc/point_locator3d.hpp"

namespace magfem {

// Force (N) and torque (N m about torque_point) of sum_i w_i T(B*(x_i)).n_i over `points`
// (sphere_quadrature / box_quadrature). The points must lie in the physical domain (not in
// the shell); throws std::invalid_argument otherwise.
ForceTorque maxwell_stress_recovered_3d(const PatchRecovery3D& recovery,
                                        const PointLocator3D& locator,
                                        const std::vector<SurfacePoint>& points,
                                        const Eigen::Vector3d& torque_point);

} // namespace magfem
