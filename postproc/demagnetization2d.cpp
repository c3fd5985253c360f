#include "postproc/demagnetization2d.hpp"

namespace magfem {

DemagnetizationResult check_demagnetization_2d(const Field2D& field,
                                               const std::vector<std::string>& region_names) {
  const Problem2D& problem = field.problem();
  std::vector<MagnetRegion> regions;
  for (std::size_t i = 0; i < problem.parts.size(); ++i) {
    const auto& phys = problem.parts[i];
    regions.push_back({region_names.at(i), phys.material->is_magnet() ? phys.material : nullptr,
                       phys.magnetization});
  }
  static const std::array<std::array<double, 3>, 3> vertex = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  return scan_demagnetization(regions, problem.mesh->triangle_part, 3,
                              [&](std::size_t t, int k, Eigen::Vector3d& x, Eigen::Vector3d& b) {
                                const auto& bary = vertex[static_cast<std::size_t>(k)];
                                x << field.point(t, bary), 0.0;
                                b << field.B(t, bary), 0.0;
                              });
}

} // namespace magfem
