#include "postproc/demagnetization2d.hpp"

namespace magfem {

DemagnetizationResult check_demagnetization_2d(const Field2D& field,
                                               const std::vector<std::string>& region_names) {
  const Problem2D& problem = field.problem();
  static const std::array<std::array<double, 3>, 3> vertex = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  return scan_demagnetization(magnet_regions(problem.parts, region_names),
                              problem.mesh->triangle_part, 3,
                              [&](std::size_t t, int k, Eigen::Vector3d& x, Eigen::Vector3d& b) {
                                const auto& bary = vertex[static_cast<std::size_t>(k)];
                                x << field.point(t, bary), 0.0;
                                b << field.B(t, bary), 0.0;
                              });
}

} // namespace magfem
