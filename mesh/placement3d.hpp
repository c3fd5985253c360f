#pragma once
// Rigid placement of a 3D part or coil: local frame -> global frame. SI metres and radians.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace magfem {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

// x_global = rotation * x_local + translation.
struct Placement {
  Mat3 rotation = Mat3::Identity();
  Vec3 translation = Vec3::Zero();

  Vec3 to_global(const Vec3& x_local) const { return rotation * x_local + translation; }
  Vec3 to_local(const Vec3& x_global) const {
    return rotation.transpose() * (x_global - translation);
  }
  // Rigid rotation by `angle` (right-hand rule) about `axis` through `point`, applied after
  // this placement.
  Placement rotated(const Vec3& axis, double angle, const Vec3& point) const {
    const Mat3 r = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
    return {r * rotation, r * (translation - point) + point};
  }
};

} // namespace magfem
