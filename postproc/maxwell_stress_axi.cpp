#include "postproc/maxwell_stress_axi.hpp"

#include <stdexcept>

#include "core/constants.hpp"
#include "core/gauss_legendre.hpp"

namespace magfem {

std::vector<SurfacePoint> revolved_contour_quadrature(const std::vector<Eigen::Vector2d>& polyline,
                                                      int n_panels, int order) {
  if (polyline.size() < 2 || n_panels < 1 || order < 1)
    throw std::invalid_argument("revolved_contour_quadrature: need 2 vertices and counts >= 1");
  const QuadratureRule g = gauss_legendre(order, 0.0, 1.0);
  std::vector<SurfacePoint> out;
  const bool closed = polyline.front() != polyline.back() && polyline.front().x() > 0;
  const std::size_t n_segments = closed ? polyline.size() : polyline.size() - 1;
  for (std::size_t s = 0; s < n_segments; ++s) {
    const Eigen::Vector2d a = polyline[s], b = polyline[(s + 1) % polyline.size()];
    const double length = (b - a).norm();
    if (length == 0)
      continue;
    const Eigen::Vector2d t = (b - a) / length, n(t.y(), -t.x());
    const double panel = length / n_panels;
    for (int p = 0; p < n_panels; ++p)
      for (int k = 0; k < order; ++k) {
        const Eigen::Vector2d x = a + (p + g.x[k]) * panel * t;
        out.push_back({{x.x(), 0, x.y()}, {n.x(), 0, n.y()}, g.w[k] * panel * 2 * pi * x.x()});
      }
  }
  return out;
}

std::vector<Eigen::Vector2d> box_contour(double r_min, double r_max, double z_min, double z_max) {
  if (r_min <= 0)
    return {{0, z_min}, {r_max, z_min}, {r_max, z_max}, {0, z_max}};
  return {{r_min, z_min}, {r_max, z_min}, {r_max, z_max}, {r_min, z_max}};
}

double maxwell_stress_axial_force(const FieldFunction2D& B,
                                  const std::vector<Eigen::Vector2d>& polyline, int n_panels,
                                  int order) {
  const auto points = revolved_contour_quadrature(polyline, n_panels, order);
  std::vector<Eigen::Vector3d> b(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector2d v = B({points[i].x.x(), points[i].x.z()});
    b[i] = {v.x(), 0, v.y()};
  }
  return maxwell_stress_sum(points, b, Eigen::Vector3d::Zero()).force.z();
}

} // namespace magfem
