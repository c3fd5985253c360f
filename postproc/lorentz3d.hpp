#pragma once
// Lorentz force and torque on a 3D coil: F = integral over the coil of J x B, torque about p
// = integral (x - p) x (J x B). The coil is not meshed, so the integral runs over the coil's
// own volume quadrature (sources/) with B from the FE field located at each point.
// The coil's own free-space field is subtracted from B before the product: it exerts no net
// force or torque on its own (rigid) currents, so removing it exactly takes away its
// quadrature noise; what remains is the field of everything else (other coils, magnets,
// iron, including the iron's response to this coil, which does pull on it).
#include <stdexcept>
#include <vector>

#include <Eigen/Core>

#include "postproc/field3d.hpp"
#include "postproc/maxwell_stress.hpp"
#include "postproc/patch_recovery3d.hpp"
#include "postproc/point_locator3d.hpp"

namespace magfem {

struct CoilVolumePoint {
  Eigen::Vector3d x;
  double weight = 0; // m^3
  Eigen::Vector3d j; // A/m^2 at the coil's current
};

// Throws std::invalid_argument if a point lies outside the meshed physical domain.
ForceTorque lorentz_force_3d(const Field3D& field, const PointLocator3D& locator, int coil,
                             const std::vector<CoilVolumePoint>& points,
                             const Eigen::Vector3d& torque_point);

// The same integral with the patch-recovered B* (patch_recovery3d.hpp) in place of the
// element field: their difference is the reported force's one-mesh error estimate
// (pipeline/coil_run3d.cpp). Throws std::invalid_argument as lorentz_force_3d.
ForceTorque lorentz_force_recovered_3d(const PatchRecovery3D& recovery,
                                       const PointLocator3D& locator, int coil,
                                       const std::vector<CoilVolumePoint>& points,
                                       const Eigen::Vector3d& torque_point);

} // namespace magfem
