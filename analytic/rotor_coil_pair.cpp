#include "analytic/rotor_coil_pair.hpp"

#include <cmath>

#include "core/constants.hpp"

namespace magfem {

PlacedCoil stator_coil(const RotorCoilPair& p, const CoaxialCoil& coil_or_model) {
  return {coil_or_model, Eigen::Vector3d(0, 0, p.rotor_radius + p.gap), Eigen::Vector3d::UnitZ()};
}

PlacedCoil rotor_magnet(const RotorCoilPair& p, double theta) {
  const Eigen::Vector3d axis(std::sin(theta), 0, std::cos(theta));
  const double half = 0.5 * p.magnet_length;
  const CoaxialCoil sheet{p.magnet_radius, p.magnet_radius, -half, half,
                          p.mu0_M / mu0 * p.magnet_length};
  return {sheet, (p.rotor_radius - half) * axis, axis};
}

Wrench magnet_wrench(const RotorCoilPair& p, const CoaxialCoil& coil_model, double model_current,
                     double theta, const WrenchQuadrature& q) {
  const PlacedCoil coil = stator_coil(p, coil_model);
  const CoaxialCoilField field(coil_model, model_current);
  return azimuthal_current_wrench(
      rotor_magnet(p, theta), 1.0,
      [&](const Eigen::Vector3d& x) { return placed_coil_B(coil, field, x); },
      Eigen::Vector3d::Zero(), q);
}

} // namespace magfem
