#include "postproc/probe_rows2d.hpp"

#include <cmath>

#include "core/constants.hpp"

namespace magfem {
namespace {

// Angle of sample i of a circle probe (full turns exclude the end, arcs include it).
double circle_angle(const ProbeSpec& probe, int i) {
  const int n = probe.points;
  const double span = probe.angle_end - probe.angle_start;
  const bool full_turn = std::abs(span - 2 * pi) < 1e-12;
  const double step = n == 1 ? 0.0 : span / (full_turn ? n : n - 1);
  return probe.angle_start + i * step;
}

} // namespace

std::vector<Eigen::Vector2d> probe_points_2d(const ProbeSpec& probe) {
  std::vector<Eigen::Vector2d> points;
  const int n = probe.points;
  for (int i = 0; i < n; ++i) {
    if (probe.kind == ProbeSpec::Kind::line) {
      const double s = n == 1 ? 0.0 : static_cast<double>(i) / (n - 1);
      points.push_back((probe.start + s * (probe.end - probe.start)).head<2>());
    } else {
      const double a = circle_angle(probe, i);
      points.push_back(probe.center.head<2>() +
                       probe.radius * Eigen::Vector2d(std::cos(a), std::sin(a)));
    }
  }
  return points;
}

ProbeTable tabulate_probe_2d(const ProbeSpec& probe, const std::vector<Eigen::Vector2d>& points,
                             const std::vector<Eigen::Vector2d>& B, double length_unit, bool axi) {
  ProbeTable table;
  table.name = probe.name;
  if (probe.kind == ProbeSpec::Kind::line) {
    table.columns = axi ? std::vector<std::string>{"r", "z", "Br", "Bz"}
                        : std::vector<std::string>{"x", "y", "Bx", "By"};
    for (std::size_t i = 0; i < points.size(); ++i)
      table.rows.push_back(
          {points[i].x() / length_unit, points[i].y() / length_unit, B[i].x(), B[i].y()});
    return table;
  }
  table.columns =
      axi ? std::vector<std::string>{"angle_deg", "r", "z", "Br", "Bz", "Brho", "Btheta"}
          : std::vector<std::string>{"angle_deg", "x", "y", "Bx", "By", "Br", "Bt"};
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double a = circle_angle(probe, static_cast<int>(i));
    const Eigen::Vector2d e_r(std::cos(a), std::sin(a)), e_t(-std::sin(a), std::cos(a));
    const Eigen::Vector2d& b = B[i];
    table.rows.push_back({a * rad_to_deg, points[i].x() / length_unit, points[i].y() / length_unit,
                          b.x(), b.y(), b.dot(e_r), b.dot(e_t)});
  }
  return table;
}

} // namespace magfem
