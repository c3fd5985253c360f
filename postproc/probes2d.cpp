#include "postproc/probes2d.hpp"

#include <cmath>
#include <stdexcept>

#include "core/constants.hpp"

namespace magfem {
namespace {

Eigen::Vector2d field_at(const Field2D& field, const PointLocator2D& locator,
                         const Eigen::Vector2d& x, const ProbeSpec& probe) {
  const auto loc = locator.locate(x);
  if (!loc) throw std::runtime_error("probe '" + probe.name + "': point outside the mesh");
  return field.B(loc->triangle, loc->bary);
}

} // namespace

ProbeTable sample_probe_2d(const Field2D& field, const PointLocator2D& locator,
                           const ProbeSpec& probe, double length_unit) {
  ProbeTable table;
  table.name = probe.name;
  const int n = probe.points;
  const bool axi = field.problem().axisymmetric();
  if (probe.kind == ProbeSpec::Kind::line) {
    table.columns = axi ? std::vector<std::string>{"r", "z", "Br", "Bz"}
                        : std::vector<std::string>{"x", "y", "Bx", "By"};
    for (int i = 0; i < n; ++i) {
      const double s = n == 1 ? 0.0 : static_cast<double>(i) / (n - 1);
      const Eigen::Vector2d x = (probe.start + s * (probe.end - probe.start)).head<2>();
      const Eigen::Vector2d b = field_at(field, locator, x, probe);
      table.rows.push_back({x.x() / length_unit, x.y() / length_unit, b.x(), b.y()});
    }
    return table;
  }
  table.columns =
      axi ? std::vector<std::string>{"angle_deg", "r", "z", "Br", "Bz", "Brho", "Btheta"}
          : std::vector<std::string>{"angle_deg", "x", "y", "Bx", "By", "Br", "Bt"};
  const double span = probe.angle_end - probe.angle_start;
  const bool full_turn = std::abs(span - 2 * pi) < 1e-12;
  const double step = n == 1 ? 0.0 : span / (full_turn ? n : n - 1);
  for (int i = 0; i < n; ++i) {
    const double a = probe.angle_start + i * step;
    const Eigen::Vector2d e_r(std::cos(a), std::sin(a)), e_t(-std::sin(a), std::cos(a));
    const Eigen::Vector2d x = probe.center.head<2>() + probe.radius * e_r;
    const Eigen::Vector2d b = field_at(field, locator, x, probe);
    table.rows.push_back({a * rad_to_deg, x.x() / length_unit, x.y() / length_unit, b.x(), b.y(),
                          b.dot(e_r), b.dot(e_t)});
  }
  return table;
}

} // namespace magfem
