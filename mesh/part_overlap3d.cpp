#include "mesh/part_overlap3d.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "mesh/grid_frame3d.hpp"

namespace magfem {
namespace {

// Cell centres of an n^3 grid in the shape's own coordinates (rho, theta, phi for segments;
// r, phi, z for cylinders; x, y, z for boxes), local frame: every sample lies inside the
// shape, and a thin wedge or shell is sampled as densely as a thick one.
Vec3 local_sample(const Shape3D& shape, const Vec3& t) {
  return std::visit(
      [&](const auto& s) -> Vec3 {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, SphericalSegment>) {
          const double rho = s.r_inner + t.x() * (s.r_outer - s.r_inner);
          const double theta = s.theta_min + t.y() * (s.theta_max - s.theta_min);
          const double phi = s.phi_min + t.z() * (s.phi_max - s.phi_min);
          return rho * Vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                            std::cos(theta));
        } else if constexpr (std::is_same_v<T, Cylinder>) {
          const double r = s.r_inner + t.x() * (s.r_outer - s.r_inner);
          const double phi = 2 * std::numbers::pi * t.y();
          return Vec3(r * std::cos(phi), r * std::sin(phi), t.z() * s.height);
        } else if constexpr (std::is_same_v<T, TriangleSurface>) {
          // Its bounding box: samples outside the surface fail part_contains(a) anyway.
          Eigen::AlignedBox3d box;
          for (const Vec3& x : s.points)
            box.extend(x);
          return box.min() + t.cwiseProduct(box.sizes());
        } else {
          return (t - Vec3::Constant(0.5)).cwiseProduct(s.size);
        }
      },
      shape);
}

double size_of(const Shape3D& shape) {
  return std::visit(
      [](const auto& s) -> double {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, SphericalSegment>)
          return s.r_outer;
        else if constexpr (std::is_same_v<T, Cylinder>)
          return std::hypot(s.r_outer, s.height);
        else if constexpr (std::is_same_v<T, TriangleSurface>) {
          Eigen::AlignedBox3d box;
          for (const Vec3& x : s.points)
            box.extend(x);
          return box.diagonal().norm();
        } else
          return s.size.norm();
      },
      shape);
}

} // namespace

std::optional<Vec3> overlap_point(const Part3D& a, const Part3D& b, int n) {
  // A millionth of the parts' size: touching faces, equal to round-off, are not overlaps.
  const double margin = 1e-6 * std::max(size_of(a.shape), size_of(b.shape));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const Vec3 t((i + 0.5) / n, (j + 0.5) / n, (k + 0.5) / n);
        const Vec3 x = a.placement.to_global(local_sample(a.shape, t));
        // A negative tolerance asks for the strict interior.
        if (part_contains(a, x, -margin) && part_contains(b, x, -margin))
          return x;
      }
  return std::nullopt;
}

} // namespace magfem
