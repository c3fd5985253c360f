#include "mesh/symmetry_plane2d.hpp"

namespace magfem {

Eigen::Matrix2d reflection_2d(const SymmetryPlane2D& plane) {
  Eigen::Matrix2d r = Eigen::Matrix2d::Identity();
  r(plane.axis, plane.axis) = -1;
  return r;
}

FoldedPoint2D fold_point_2d(const std::vector<SymmetryPlane2D>& planes, const Eigen::Vector2d& x) {
  FoldedPoint2D f{x};
  for (const SymmetryPlane2D& p : planes) {
    if (f.point[p.axis] >= 0)
      continue;
    f.point[p.axis] = -f.point[p.axis];
    // The planes are orthogonal, so the reflections commute and compose in any order.
    const Eigen::Matrix2d r = reflection_2d(p);
    const bool normal = p.field == SymmetryField::normal;
    f.b_map = (normal ? Eigen::Matrix2d(-r) : r) * f.b_map;
    f.a_sign *= normal ? 1 : -1;
  }
  return f;
}

double symmetry_factor_2d(const std::vector<SymmetryPlane2D>& planes) {
  return static_cast<double>(1u << planes.size());
}

std::vector<Eigen::Vector2d> clip_to_share(const std::vector<Eigen::Vector2d>& loop,
                                           const std::vector<SymmetryPlane2D>& planes) {
  std::vector<Eigen::Vector2d> cur = loop, out;
  for (const SymmetryPlane2D& plane : planes) {
    const int a = plane.axis;
    out.clear();
    for (std::size_t i = 0, n = cur.size(); i < n; ++i) {
      const Eigen::Vector2d &p = cur[i], &q = cur[(i + 1) % n];
      if (p[a] >= 0)
        out.push_back(p);
      if ((p[a] < 0 && q[a] > 0) || (p[a] > 0 && q[a] < 0)) {
        Eigen::Vector2d x = p + p[a] / (p[a] - q[a]) * (q - p);
        x[a] = 0; // exactly on the plane, where the mesher's cut side lies
        out.push_back(x);
      }
    }
    cur.swap(out);
  }
  double twice_area = 0;
  for (std::size_t i = 0, n = cur.size(); i < n; ++i) {
    const Eigen::Vector2d &p = cur[i], &q = cur[(i + 1) % n];
    twice_area += p.x() * q.y() - p.y() * q.x();
  }
  if (cur.size() < 3 || twice_area == 0)
    cur.clear();
  return cur;
}

const char* plane_name_2d(const SymmetryPlane2D& plane, bool axisymmetric) {
  if (axisymmetric)
    return "z";
  return plane.axis == 0 ? "x" : "y";
}

} // namespace magfem
