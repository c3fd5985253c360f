#pragma once
// Error estimate of a Maxwell-stress force and torque from one mesh: the same surface
// quadrature evaluated with the superconvergent patch-recovered B* (patch_recovery3d.hpp)
// instead of the nodal-average B the reported result uses (maxwell_stress3d.hpp).
//
// Why this measures the error: the stress tensor is quadratic in B, so the force error is,
// to first order, the surface integral of dT(B; B - B_h). B* is one order more accurate
// than the averaged field (its error is O(h^(p+1)) against O(h^p) where the averages
// reproduce the element field's own node errors), so F(B*) - F(B_avg) approximates
// F(B) - F(B_avg): a recovery-based estimate of the reported quantity, in its unit, with the
// same (asymptotic, not guaranteed) reliability as the energy estimate. It is not a bound.
// The quadrature is the reported result's, so its own error cancels in the difference.
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
