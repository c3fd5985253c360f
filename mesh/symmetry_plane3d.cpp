#include "mesh/symmetry_plane3d.hpp"

namespace magfem {

Mat3 reflection(const SymmetryPlane3D& plane) {
  Mat3 r = Mat3::Identity();
  r(plane.axis, plane.axis) = -1;
  return r;
}

FoldedPoint3D fold_point(const std::vector<SymmetryPlane3D>& planes, const Vec3& x) {
  FoldedPoint3D f{x};
  for (const SymmetryPlane3D& p : planes) {
    if (f.point[p.axis] >= 0)
      continue;
    f.point[p.axis] = -f.point[p.axis];
    // x = R x', B(x) = B(R x') = -R B(x') (normal) or R B(x') (parallel). The planes are
    // orthogonal coordinate planes, so the reflections commute and compose in any order.
    const Mat3 r = reflection(p);
    f.b_map = (p.field == SymmetryField::normal ? Mat3(-r) : r) * f.b_map;
  }
  return f;
}

double symmetry_factor(const std::vector<SymmetryPlane3D>& planes) {
  return static_cast<double>(1u << planes.size());
}

const char* axis_name(int axis) {
  static const char* names[] = {"x", "y", "z"};
  return names[axis];
}

const char* field_name(SymmetryField field) {
  return field == SymmetryField::normal ? "normal" : "parallel";
}

} // namespace magfem
