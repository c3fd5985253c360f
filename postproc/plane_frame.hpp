#pragma once
// A right-handed orthonormal frame (u, v, n) on a plane through `center`: n the unit normal,
// u the in-plane direction of a rectangle's first side (or of a plane probe's first grid
// index), v = n x u. Shared by sections and plane probes.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace magfem {

struct PlaneFrame {
  Eigen::Vector3d center = Eigen::Vector3d::Zero(); // metres
  Eigen::Vector3d u = Eigen::Vector3d::UnitX(), v = Eigen::Vector3d::UnitY(),
                  n = Eigen::Vector3d::UnitZ();

  // The point at in-plane coordinates (a, b) (metres along u and v).
  Eigen::Vector3d at(double a, double b) const { return center + a * u + b * v; }
};

// The default first in-plane direction for unit normal n: the coordinate axis least aligned
// with n (x before y before z on ties) projected onto the plane and normalised. Normal z
// gives u = x, v = y; normal x gives u = y, v = z; normal y gives u = x, v = -z.
inline Eigen::Vector3d default_plane_axis(const Eigen::Vector3d& n) {
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(n[i]) < std::abs(n[k]))
      k = i;
  const Eigen::Vector3d e = Eigen::Vector3d::Unit(k);
  return (e - e.dot(n) * n).normalized();
}

// The frame of unit normal n with first direction u (unit, orthogonal to n).
inline PlaneFrame make_plane_frame(const Eigen::Vector3d& center, const Eigen::Vector3d& n,
                                   const Eigen::Vector3d& u) {
  return {center, u, n.cross(u), n};
}

} // namespace magfem
