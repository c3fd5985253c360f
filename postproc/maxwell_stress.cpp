#include "postproc/maxwell_stress.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Geometry>

#include "core/constants.hpp"
#include "core/gauss_legendre.hpp"

namespace magfem {

namespace {

using Vec3 = Eigen::Vector3d;

void check_counts(int a, int b, const char* what) {
  if (a < 1 || b < 1)
    throw std::invalid_argument(std::string(what) + ": quadrature point counts must be >= 1");
}

std::vector<SurfacePoint> circle_quadrature(const Eigen::Vector2d& c, double r, int n) {
  std::vector<SurfacePoint> pts(static_cast<std::size_t>(n));
  for (int j = 0; j < n; ++j) {
    const double ph = 2 * pi * j / n;
    const Vec3 normal(std::cos(ph), std::sin(ph), 0);
    pts[j] = {Vec3(c.x(), c.y(), 0) + r * normal, normal, 2 * pi * r / n};
  }
  return pts;
}

} // namespace

std::vector<SurfacePoint> sphere_quadrature(const Vec3& center, double radius, int n_theta,
                                            int n_phi) {
  check_counts(n_theta, n_phi, "sphere_quadrature");
  const QuadratureRule g = gauss_legendre(n_theta);
  std::vector<SurfacePoint> pts;
  pts.reserve(static_cast<std::size_t>(n_theta) * n_phi);
  for (int i = 0; i < n_theta; ++i) {
    // theta = (pi/2)(1 + t): d theta = pi/2 dt, dS = r^2 sin(theta) dtheta dphi.
    const double th = 0.5 * pi * (1 + g.x[i]);
    const double wt = 0.5 * pi * g.w[i] * radius * radius * std::sin(th) * (2 * pi / n_phi);
    for (int j = 0; j < n_phi; ++j) {
      const double ph = 2 * pi * (j + 0.5) / n_phi;
      const Vec3 n(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
      pts.push_back({center + radius * n, n, wt});
    }
  }
  return pts;
}

ForceTorque maxwell_stress_sum(const std::vector<SurfacePoint>& pts, const std::vector<Vec3>& B,
                               const Vec3& torque_point) {
  if (B.size() != pts.size())
    throw std::invalid_argument("maxwell_stress_sum: one B value per point expected");
  ForceTorque ft;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Vec3& b = B[i];
    const Vec3 tn = (b * b.dot(pts[i].n) - 0.5 * b.squaredNorm() * pts[i].n) / mu0;
    ft.force += pts[i].w * tn;
    ft.torque += pts[i].w * (pts[i].x - torque_point).cross(tn);
  }
  return ft;
}

ForceTorque maxwell_stress_on_sphere(const FieldFunction& B, const Vec3& center, double radius,
                                     const Vec3& torque_point, int n_theta, int n_phi) {
  const std::vector<SurfacePoint> pts = sphere_quadrature(center, radius, n_theta, n_phi);
  std::vector<Vec3> b(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i)
    b[i] = B(pts[i].x);
  return maxwell_stress_sum(pts, b, torque_point);
}

ForceTorque maxwell_stress_on_sphere(const BatchFieldFunction& B, const Vec3& center, double radius,
                                     const Vec3& torque_point, int n_theta, int n_phi) {
  const std::vector<SurfacePoint> pts = sphere_quadrature(center, radius, n_theta, n_phi);
  std::vector<Vec3> xs(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i)
    xs[i] = pts[i].x;
  return maxwell_stress_sum(pts, B(xs), torque_point);
}

ForceTorque maxwell_stress_on_circle(const FieldFunction2D& B, const Eigen::Vector2d& center,
                                     double radius, const Eigen::Vector2d& torque_point,
                                     int n_points) {
  check_counts(n_points, 1, "maxwell_stress_on_circle");
  const std::vector<SurfacePoint> pts = circle_quadrature(center, radius, n_points);
  std::vector<Vec3> b(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Eigen::Vector2d v = B(pts[i].x.head<2>());
    b[i] = Vec3(v.x(), v.y(), 0);
  }
  return maxwell_stress_sum(pts, b, Vec3(torque_point.x(), torque_point.y(), 0));
}

ForceTorque maxwell_stress_on_band(const FieldFunction2D& B, const Eigen::Vector2d& center,
                                   double r_inner, double r_outer,
                                   const Eigen::Vector2d& torque_point, int n_radii, int n_points) {
  check_counts(n_radii, n_points, "maxwell_stress_on_band");
  if (!(r_inner > 0 && r_outer > r_inner))
    throw std::invalid_argument("maxwell_stress_on_band: need 0 < r_inner < r_outer");
  // Weights w_k / 2 sum to 1: the mean over r of the circle results.
  const QuadratureRule g = gauss_legendre(n_radii);
  ForceTorque sum;
  for (int k = 0; k < n_radii; ++k) {
    const double r = r_inner + 0.5 * (r_outer - r_inner) * (1 + g.x[k]);
    sum = sum + 0.5 * g.w[k] * maxwell_stress_on_circle(B, center, r, torque_point, n_points);
  }
  return sum;
}

ForceComparison compare_force_torque(const ForceTorque& a, const ForceTorque& b) {
  auto rel = [](const Vec3& x, const Vec3& y) {
    const double scale = std::max(x.norm(), y.norm());
    return scale > 0 ? (x - y).norm() / scale : 0.0;
  };
  return {a, b, rel(a.force, b.force), rel(a.torque, b.torque)};
}

} // namespace magfem
