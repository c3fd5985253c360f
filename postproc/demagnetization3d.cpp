#include "postproc/demagnetization3d.hpp"

namespace magfem {

DemagnetizationResult check_demagnetization_3d(const Field3D& field,
                                               const std::vector<std::string>& region_names) {
  const Problem3D& problem = field.problem();
  static const std::array<std::array<double, 4>, 4> vertex = {
      {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};
  return scan_demagnetization(magnet_regions(problem.parts, region_names), problem.mesh->tet_part,
                              4, [&](std::size_t t, int k, Eigen::Vector3d& x, Eigen::Vector3d& b) {
                                const auto& bary = vertex[static_cast<std::size_t>(k)];
                                x = field.point(t, bary);
                                b = field.B(t, bary);
                              });
}

} // namespace magfem
