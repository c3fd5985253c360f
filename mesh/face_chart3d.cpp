#include "mesh/face_chart3d.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace magfem {
namespace {

constexpr double half_pi = std::numbers::pi / 2;

double unwrap(double angle, double mid) {
  return mid + std::remainder(angle - mid, 2 * std::numbers::pi);
}

// Grid coordinates of a point of the face from its local position (only the free coordinates
// matter to the callers).
Vec3 grid_coordinates(const GridFrame3D& f, const Vec3& l) {
  switch (f.kind) {
  case GridKind3D::spherical: {
    const double r = l.norm();
    const double theta = r > 0 ? std::acos(std::clamp(l.z() / r, -1.0, 1.0)) : 0;
    return {r, theta, std::atan2(l.y(), l.x())};
  }
  case GridKind3D::cylindrical:
    return {l.head<2>().norm(), std::atan2(l.y(), l.x()), l.z()};
  case GridKind3D::cartesian:
    return l;
  }
  return l;
}

} // namespace

FaceChart3D::FaceChart3D(const GridFrame3D& frame, const GridFace3D& face) : frame_(&frame) {
  const double v = frame.breaks[face.axis][face.index];
  const int b1 = face.free_axis(0), b2 = face.free_axis(1);
  const double mid1 = 0.5 * (frame.lo(b1, face.cells[0]) + frame.hi(b1, face.cells[0]));
  const double mid2 = 0.5 * (frame.lo(b2, face.cells[1]) + frame.hi(b2, face.cells[1]));
  if (frame.kind == GridKind3D::spherical) {
    if (face.axis == 0) {
      radius_ = v;
      type_ = mid1 < half_pi ? Type::stereo_north : Type::stereo_south; // b1 is theta
    } else if (face.axis == 1) {
      if (std::abs(v - half_pi) < 1e-9) {
        type_ = Type::plane; // equatorial plane: default x, y axes
      } else {
        type_ = Type::cone;
        cone_angle_ = v;
        mid_angle_ = mid1; // b1 is phi
      }
    } else {
      e1_ = Vec3(std::cos(v), std::sin(v), 0);
      e2_ = Vec3::UnitZ();
    }
  } else if (frame.kind == GridKind3D::cylindrical) {
    if (face.axis == 0) {
      type_ = Type::cylinder;
      radius_ = v;
      mid_angle_ = mid1; // b1 is alpha
    } else if (face.axis == 1) {
      e1_ = Vec3(std::cos(v), std::sin(v), 0);
      e2_ = Vec3::UnitZ();
    } else {
      origin_ = Vec3(0, 0, v);
    }
  } else {
    origin_ = v * Vec3::Unit(face.axis);
    e1_ = Vec3::Unit(b1);
    e2_ = Vec3::Unit(b2);
  }
  (void)mid2;
}

Eigen::Vector2d FaceChart3D::to_2d(const Vec3& x_global) const {
  const Vec3 l = frame_->placement.to_local(x_global);
  switch (type_) {
  case Type::plane:
    return {(l - origin_).dot(e1_), (l - origin_).dot(e2_)};
  case Type::stereo_north:
    return 2 * radius_ * l.head<2>() / (radius_ + l.z());
  case Type::stereo_south:
    return 2 * radius_ * l.head<2>() / (radius_ - l.z());
  case Type::cone: {
    const double r = l.norm();
    const double a =
        (unwrap(std::atan2(l.y(), l.x()), mid_angle_) - mid_angle_) * std::sin(cone_angle_);
    return {r * std::cos(a), r * std::sin(a)};
  }
  case Type::cylinder:
    return {radius_ * (unwrap(std::atan2(l.y(), l.x()), mid_angle_) - mid_angle_), l.z()};
  }
  return {0, 0};
}

Vec3 FaceChart3D::to_3d(const Eigen::Vector2d& uv) const {
  Vec3 l = Vec3::Zero();
  switch (type_) {
  case Type::plane:
    l = origin_ + uv.x() * e1_ + uv.y() * e2_;
    break;
  case Type::stereo_north:
  case Type::stereo_south: {
    const Eigen::Vector2d w = uv / (2 * radius_);
    const double s2 = w.squaredNorm();
    const double z = (type_ == Type::stereo_north ? 1 : -1) * (1 - s2);
    l = radius_ * Vec3(2 * w.x(), 2 * w.y(), z) / (1 + s2);
    break;
  }
  case Type::cone: {
    const double r = uv.norm();
    const double phi = mid_angle_ + std::atan2(uv.y(), uv.x()) / std::sin(cone_angle_);
    l = r * Vec3(std::sin(cone_angle_) * std::cos(phi), std::sin(cone_angle_) * std::sin(phi),
                 std::cos(cone_angle_));
    break;
  }
  case Type::cylinder: {
    const double a = mid_angle_ + uv.x() / radius_;
    l = Vec3(radius_ * std::cos(a), radius_ * std::sin(a), uv.y());
    break;
  }
  }
  return frame_->placement.to_global(l);
}

double FaceChart3D::curvature_radius(const Vec3& x_global) const {
  switch (type_) {
  case Type::plane:
    return std::numeric_limits<double>::infinity();
  case Type::stereo_north:
  case Type::stereo_south:
  case Type::cylinder:
    return radius_;
  case Type::cone: {
    // Normal curvature radius across the cone at distance r from the apex.
    const double r = frame_->placement.to_local(x_global).norm();
    return r * std::sin(cone_angle_) / std::abs(std::cos(cone_angle_));
  }
  }
  return std::numeric_limits<double>::infinity();
}

FaceSamples3D sample_face(const GridFrame3D& f, const GridFace3D& face, double spacing) {
  const int b[2] = {face.free_axis(0), face.free_axis(1)};
  const double lo[2] = {f.lo(b[0], face.cells[0]), f.lo(b[1], face.cells[1])};
  const double hi[2] = {f.hi(b[0], face.cells[0]), f.hi(b[1], face.cells[1])};
  Vec3 q;
  q[face.axis] = f.breaks[face.axis][face.index];
  // Longest coordinate line of each free axis (checked at the ends and middle of the other).
  int n[2];
  for (int d = 0; d < 2; ++d) {
    double longest = 0;
    for (double s : {0.0, 0.5, 1.0}) {
      q[b[1 - d]] = lo[1 - d] + s * (hi[1 - d] - lo[1 - d]);
      double len = 0;
      constexpr int steps = 16;
      for (int k = 0; k < steps; ++k) {
        q[b[d]] = lo[d] + (hi[d] - lo[d]) * k / steps;
        const Vec3 a = f.point(q);
        q[b[d]] = lo[d] + (hi[d] - lo[d]) * (k + 1) / steps;
        len += (f.point(q) - a).norm();
      }
      longest = std::max(longest, len);
    }
    n[d] = static_cast<int>(std::ceil(longest / spacing)) + 1;
  }
  FaceSamples3D s;
  s.n1 = n[0];
  s.n2 = n[1];
  s.points.reserve(static_cast<std::size_t>(n[0]) * n[1]);
  for (int i = 0; i < n[0]; ++i)
    for (int j = 0; j < n[1]; ++j) {
      q[b[0]] = lo[0] + (hi[0] - lo[0]) * i / (n[0] - 1);
      q[b[1]] = lo[1] + (hi[1] - lo[1]) * j / (n[1] - 1);
      s.points.push_back(f.point(q));
    }
  return s;
}

bool face_contains(const GridFrame3D& f, const GridFace3D& face, const Vec3& x_global, double tol) {
  const Vec3 l = f.placement.to_local(x_global);
  const Vec3 q = grid_coordinates(f, l);
  // Tolerances per axis in coordinate units (angles scale with the distance to their axis).
  const double r_axis = f.kind == GridKind3D::spherical ? l.norm() : l.head<2>().norm();
  auto coord_tol = [&](int a) {
    const bool angular =
        (f.kind == GridKind3D::spherical && a > 0) || (f.kind == GridKind3D::cylindrical && a == 1);
    if (!angular)
      return tol;
    const double r = (f.kind == GridKind3D::spherical && a == 2) ? l.head<2>().norm() : r_axis;
    return r > tol ? tol / r : 4.0; // on the axis every angle matches
  };
  auto within = [&](int a, double lo, double hi) {
    const double t = coord_tol(a);
    if (!f.periodic[a])
      return q[a] >= lo - t && q[a] <= hi + t;
    const double mid = 0.5 * (lo + hi);
    return std::abs(std::remainder(q[a] - mid, 2 * std::numbers::pi)) <= 0.5 * (hi - lo) + t;
  };
  const double v = f.breaks[face.axis][face.index];
  if (!within(face.axis, v, v))
    return false;
  for (int n = 0; n < 2; ++n) {
    const int b = face.free_axis(n);
    if (!within(b, f.lo(b, face.cells[n]), f.hi(b, face.cells[n])))
      return false;
  }
  return true;
}

Vec3 face_normal(const GridFrame3D& f, const GridFace3D& face, const Vec3& x_global) {
  Vec3 q = grid_coordinates(f, f.placement.to_local(x_global));
  q[face.axis] = f.breaks[face.axis][face.index];
  return f.axis_direction(face.axis, q);
}

} // namespace magfem
