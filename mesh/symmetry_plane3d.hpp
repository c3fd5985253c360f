#pragma once
// Symmetry planes of a 3D model (issue 36): the coordinate planes x = 0, y = 0, z = 0 of the
// case frame. The mesher keeps the side where the coordinate is >= 0 (the model's share); the
// field on the other side is the mirror image of the field on this one:
//   field: normal   (n x H = 0 on the plane, field lines cross it at right angles): the
//                   device is its own mirror image (currents and magnetizations mirrored as
//                   the pseudovectors they are), B(R x) = -R B(x);
//   field: parallel (B . n = 0 on the plane, field lines run along it): the mirror image
//                   carries the opposite sources, B(R x) = R B(x);
// R the reflection about the plane. The rule for sources follows (docs/case_format.md):
// a magnet magnetized along the plane's normal, and a coil whose current runs parallel to the
// plane (its axis along the normal), are their own images under `normal`; magnetized across
// the normal (in the plane) or with its current crossing the plane (axis in the plane), under
// `parallel`.
#include <vector>

#include "mesh/placement3d.hpp"

namespace magfem {

enum class SymmetryField { normal, parallel };

struct SymmetryPlane3D {
  int axis = 2; // 0: x = 0, 1: y = 0, 2: z = 0
  SymmetryField field = SymmetryField::normal;
};

// Reflection about the plane (diag with -1 at the axis).
Mat3 reflection(const SymmetryPlane3D& plane);

// How B at a point of the whole device follows from the model: B(x) = b_map * B(point),
// point the image of x on the kept side (x itself when it lies there).
struct FoldedPoint3D {
  Vec3 point;
  Mat3 b_map = Mat3::Identity();
};
FoldedPoint3D fold_point(const std::vector<SymmetryPlane3D>& planes, const Vec3& x);

// The whole device over the model's share: 2 per plane (energies, flux linkages of coils that
// are their own mirror images, inductances).
double symmetry_factor(const std::vector<SymmetryPlane3D>& planes);

const char* axis_name(int axis);             // "x", "y", "z"
const char* field_name(SymmetryField field); // "normal", "parallel"

} // namespace magfem
