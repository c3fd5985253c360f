#include "postproc/lorentz3d.hpp"

#include "core/constants.hpp"
#include "solver/coil_source3d.hpp"

namespace magfem {

namespace {

// sum over the points of w J x (B - B_own), B from b_of(tet, bary): the one integral both
// fields share, so that their difference is the fields' alone.
template <class BOf>
ForceTorque lorentz_sum(const Field3D& field, const PointLocator3D& locator, int coil,
                        const std::vector<CoilVolumePoint>& points,
                        const Eigen::Vector3d& torque_point, const BOf& b_of) {
  const CoilSource3D* src = field.problem().source;
  if (!src || !src->active() || coil < 0 || coil >= src->field->n_coils())
    throw std::invalid_argument("lorentz_force_3d: no such coil");
  const SourceField3D& coils = *src->field;
  const double current = coils.current(coil);
  ForceTorque ft;
  for (const auto& p : points) {
    const auto loc = locator.locate(p.x);
    if (!loc || field.problem().is_shell(loc->tet))
      throw std::invalid_argument("the coil leaves the meshed domain");
    const Eigen::Vector3d b =
        loc->b_map * b_of(loc->tet, loc->bary) - mu0 * current * coils.H_per_ampere(coil, p.x);
    const Eigen::Vector3d f = p.weight * p.j.cross(b);
    ft.force += f;
    ft.torque += (p.x - torque_point).cross(f);
  }
  return ft;
}

} // namespace

ForceTorque lorentz_force_3d(const Field3D& field, const PointLocator3D& locator, int coil,
                             const std::vector<CoilVolumePoint>& points,
                             const Eigen::Vector3d& torque_point) {
  return lorentz_sum(
      field, locator, coil, points, torque_point,
      [&](std::size_t t, const std::array<double, 4>& bary) { return field.B(t, bary); });
}

ForceTorque lorentz_force_recovered_3d(const PatchRecovery3D& recovery,
                                       const PointLocator3D& locator, int coil,
                                       const std::vector<CoilVolumePoint>& points,
                                       const Eigen::Vector3d& torque_point) {
  return lorentz_sum(
      recovery.field(), locator, coil, points, torque_point,
      [&](std::size_t t, const std::array<double, 4>& bary) { return recovery.B(t, bary); });
}

} // namespace magfem
