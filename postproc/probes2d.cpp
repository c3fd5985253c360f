#include "postproc/probes2d.hpp"

#include <stdexcept>

#include "postproc/probe_rows2d.hpp"

namespace magfem {

ProbeTable sample_probe_2d(const Field2D& field, const PointLocator2D& locator,
                           const ProbeSpec& probe, double length_unit,
                           const PatchRecovery2D* recovery) {
  const auto points = probe_points_2d(probe);
  std::vector<Eigen::Vector2d> b;
  for (const auto& x : points) {
    const auto loc = locator.locate(x);
    if (!loc)
      throw std::runtime_error("probe '" + probe.name + "': point outside the mesh");
    b.push_back(loc->b_map * (recovery ? recovery->B(loc->triangle, loc->bary)
                                       : field.B(loc->triangle, loc->bary)));
  }
  return tabulate_probe_2d(probe, points, b, length_unit, field.problem().axisymmetric());
}

} // namespace magfem
