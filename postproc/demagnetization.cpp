#include "postproc/demagnetization.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

namespace magfem {

std::string DemagnetizationCheck::warning(double length_unit, const std::string& unit_name,
                                          int dimension) const {
  const Eigen::Vector3d p = at_m / length_unit;
  char where[120];
  if (dimension == 3)
    std::snprintf(where, sizeof where, "(%g, %g, %g)", p.x(), p.y(), p.z());
  else
    std::snprintf(where, sizeof where, "(%g, %g)", p.x(), p.y());
  char buf[400];
  std::snprintf(buf, sizeof buf,
                "magnet '%s' (%s at %g C) is past its knee: B along M reaches %.3f T at "
                "%s %s, below the knee %.3f T by %.3f T (irreversible "
                "demagnetization there)",
                region.c_str(), material.c_str(), temperature_C, min_B_along_M_T, where,
                unit_name.c_str(), knee_T.value_or(0.0), -margin_T.value_or(0.0));
  return buf;
}

DemagnetizationResult scan_demagnetization(const std::vector<MagnetRegion>& regions,
                                           const std::vector<int>& element_part, int n_vertices,
                                           const VertexField& vertex_field) {
  constexpr double none = std::numeric_limits<double>::quiet_NaN();
  constexpr double inf = std::numeric_limits<double>::infinity();
  DemagnetizationResult out;
  out.element_B_along_M.assign(element_part.size(), none);
  std::vector<double> lowest(regions.size(), inf);
  std::vector<Eigen::Vector3d> where(regions.size(), Eigen::Vector3d::Zero());
  for (std::size_t t = 0; t < element_part.size(); ++t) {
    const int part = element_part[t];
    if (part < 0 || !regions[static_cast<std::size_t>(part)].material)
      continue;
    const auto& region = regions[static_cast<std::size_t>(part)];
    double element_min = inf;
    for (int k = 0; k < n_vertices; ++k) {
      Eigen::Vector3d x, b;
      vertex_field(t, k, x, b);
      const Eigen::Vector3d m = region.magnetization.unit_at(x);
      if (m.squaredNorm() == 0)
        continue; // the centre of a radial pattern: no direction to project on
      const double b_m = b.dot(m);
      element_min = std::min(element_min, b_m);
      if (b_m < lowest[static_cast<std::size_t>(part)]) {
        lowest[static_cast<std::size_t>(part)] = b_m;
        where[static_cast<std::size_t>(part)] = x;
      }
    }
    if (element_min < inf)
      out.element_B_along_M[t] = element_min;
  }
  for (std::size_t i = 0; i < regions.size(); ++i) {
    if (!regions[i].material || lowest[i] == inf)
      continue; // not a magnet, or no element of it in this mesh
    const Material& mat = *regions[i].material;
    DemagnetizationCheck c;
    c.region = regions[i].name;
    c.material = mat.name;
    c.temperature_C = mat.temperature_C;
    c.min_B_along_M_T = lowest[i];
    c.at_m = where[i];
    c.knee_T = mat.knee_T();
    if (c.knee_T) {
      c.margin_T = c.min_B_along_M_T - *c.knee_T;
      c.at_risk = *c.margin_T < 0;
    }
    out.magnets.push_back(std::move(c));
  }
  return out;
}

} // namespace magfem
