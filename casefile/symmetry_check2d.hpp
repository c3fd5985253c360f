#pragma once
// Whether a planar or axisymmetric case is what its symmetry planes say
// (mesh/symmetry_plane2d.hpp), checked before meshing, as check_symmetry_3d does in 3D: the
// model's share stands for the whole device only if, about every plane,
//   - every part's mirror image is a part of the same material (a part on the plane is its
//     own image; one beyond it is another part's),
//   - every magnet's remanence at a point is the mirror of the remanence at its image:
//     M(R x) = -R M(x) for `field: normal`, R M(x) for `field: parallel`,
//   - the current density (J_z planar, J_phi axisymmetric: normal to the cross-section, so the
//     reflection leaves its direction alone) is J(R x) = J(x) for `normal` and -J(x) for
//     `parallel`: a pair carrying the same current sits on a `normal` plane, a go-and-return
//     (planar) or anti-Helmholtz (axisymmetric) pair on a `parallel` one; a uniform current
//     region cut by the plane is its own image under `normal` only,
//   - an axisymmetric coil (a region with turns, whose linkage and inductance are reported)
//     is its own image or another coil's (turns and current too): the share of a pair drives
//     both coils at once, and the pair's inductances need the second solve of
//     pipeline/coil_results_axi.hpp, which only a coil image has turns for.
// Parts are sampled at interior points (cell midpoints of a 12 x 12 grid over each part), so
// a difference smaller than a twelfth of a part can pass unseen.
#include <vector>

#include "casefile/case_spec.hpp"

namespace magfem {

// InputError (exit 2) at the line of the first region that breaks a plane's symmetry, naming
// it, the plane and the point. No-op without planes.
void check_symmetry_2d(const CaseSpec& spec);

// Per part: how many copies of its meshed share make the whole part (2 per plane cutting it;
// 1 for a part on one side, whose mirror image is another part).
std::vector<double> region_symmetry_factors_2d(const CaseSpec& spec);

// Per plane (Geometry2D::planes) and part: the part its mirror image is (itself for a part
// the plane cuts), -1 when the image lies in air (only in a case check_symmetry_2d refuses).
std::vector<std::vector<int>> mirror_parts_2d(const CaseSpec& spec);

// Per part: -1 when the model keeps some of it (it is meshed), else the part in the model's
// share whose mirror image it is (through every plane it lies beyond: a quarter model's part
// in the far quadrant is the image of the one in the kept quadrant), -1 if none (only in a
// case check_symmetry_2d refuses).
std::vector<int> share_images_2d(const CaseSpec& spec);

} // namespace magfem
