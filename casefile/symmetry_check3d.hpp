#pragma once
// Whether a 3D case is what its symmetry planes say (mesh/symmetry_plane3d.hpp), checked
// before meshing: the model's share stands for the whole device only if, about every plane,
//   - every part's mirror image is a part of the same material (a part on the plane is its
//     own image; one beyond it is another part's),
//   - every magnet's remanence at a point is the mirror of the remanence at its image:
//     M(R x) = -R M(x) for `field: normal` (magnetized along the normal), R M(x) for
//     `field: parallel` (magnetized in the plane),
//   - the coils' current density likewise: J(R x) = R J(x) for `normal` (current parallel to
//     the plane: a coil with its axis along the normal), -R J(x) for `parallel` (current
//     crossing the plane: axis in the plane), and every coil is its own image (its flux
//     linkage is then twice that of its share).
// The parts and coils are sampled at interior points (a grid in their own coordinates), so a
// difference smaller than the sampling spacing (a sixth of a part) can pass unseen; the mesh
// is exact only for what it meshes.
#include "casefile/case_spec.hpp"

namespace magfem {

// InputError (exit 2) at the line of the first part or coil that breaks a plane's symmetry,
// naming it, the plane and the point. No-op without planes.
void check_symmetry_3d(const CaseSpec& spec);

// Per part: how many copies of its meshed share make the whole part (2 per plane cutting it;
// 1 for a part on one side, whose mirror image is another part beyond the plane).
std::vector<double> region_symmetry_factors(const CaseSpec& spec);

// Per part: -1 when the model keeps some of it (it is meshed), else the part in the model's
// share whose mirror image it is (through every plane it lies beyond), -1 if none (only in a
// case check_symmetry_3d refuses).
std::vector<int> share_images(const CaseSpec& spec);

} // namespace magfem
