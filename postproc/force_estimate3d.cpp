#include "postproc/force_estimate3d.hpp"

#include <stdexcept>

namespace magfem {

ForceTorque maxwell_stress_recovered_3d(const PatchRecovery3D& recovery,
                                        const PointLocator3D& locator,
                                        const std::vector<SurfacePoint>& points,
                                        const Eigen::Vector3d& torque_point) {
  const Problem3D& problem = recovery.field().problem();
  std::vector<Eigen::Vector3d> b(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto loc = locator.locate(points[i].x);
    if (!loc || problem.is_shell(loc->tet))
      throw std::invalid_argument("recovered Maxwell stress: a surface point is outside the "
                                  "physical domain");
    b[i] = loc->b_map * recovery.B(loc->tet, loc->bary);
  }
  return maxwell_stress_sum(points, b, torque_point);
}

} // namespace magfem
