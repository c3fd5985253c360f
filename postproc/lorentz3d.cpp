#include "postproc/lorentz3d.hpp"

#include "core/constants.hpp"
#include "solver/coil_source3d.hpp"

namespace magfem {

ForceTorque lorentz_force_3d(const Field3D& field, const PointLocator3D& locator, int coil,
                             const std::vector<CoilVolumePoint>& points,
                             const Eigen::Vector3d& torque_point) {
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
        loc->b_map * field.B(loc->tet, loc->bary) - mu0 * current * coils.H_per_ampere(coil, p.x);
    const Eigen::Vector3d f = p.weight * p.j.cross(b);
    ft.force += f;
    ft.torque += (p.x - torque_point).cross(f);
  }
  return ft;
}

} // namespace magfem
