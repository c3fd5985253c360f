#pragma once
// The 3D solution as a VtuGrid: linear tets (VTK type 10) for order 1, quadratic tets (type
// 24, whose node order is the DOF order of tet_lagrange.hpp) for order 2. Point data: phi,
// recovered B, |B|; cell data (at the centroid): region_id, material_id (Int32), B, |B|, H,
// magnetization (M0 = B_r m_hat / mu0 in A/m), and the names (vtu_cell_names.hpp). The
// open-boundary shell is left out (its coordinates are not physical); the points only the
// shell uses stay in this grid and are dropped by write_vtu.
#include <string>
#include <vector>

#include "postproc/field3d.hpp"
#include "postproc/vtu_writer.hpp"

namespace magfem {

// material_of_part: index into material_names for every part; background air uses
// air_material; region_names: one per part. recovered_B: one value per DOF,
// RecoveredB3D::dof_average() (mixed across regions at their boundaries: point data can hold one
// value a point; the cell data do not mix).
VtuGrid make_vtu_3d(const Field3D& field, const std::vector<Eigen::Vector3d>& recovered_B,
                    const std::vector<int>& material_of_part, int air_material,
                    const std::vector<std::string>& material_names,
                    const std::vector<std::string>& region_names);

} // namespace magfem
