#pragma once
// An axisymmetric solution revolved about the z axis into a 3D grid for ParaView: each
// triangle of the r-z mesh (its vertices; shell excluded) swept through n_phi steps of the
// full turn gives wedge cells (degenerate where a vertex lies on the axis). Point data A_phi,
// B = B_r r_hat + B_z z_hat (recovered), |B|; cell data region_id, material_id (Int32), |B|,
// and the names (vtu_cell_names.hpp).
#include <string>
#include <vector>

#include "postproc/field2d.hpp"
#include "postproc/vtu_writer.hpp"

namespace magfem {

// Throws std::invalid_argument for a planar field or n_phi < 3.
VtuGrid make_vtu_revolved(const Field2D& field, const std::vector<int>& material_of_part,
                          int air_material, const std::vector<std::string>& material_names,
                          const std::vector<std::string>& region_names, int n_phi = 36);

} // namespace magfem
