#pragma once
// The 2D solution as a VtuGrid: quadratic triangles for order 2. Point data: A_z, recovered
// B, |B|; cell data (at the centroid): region_id, material_id (Int32), B, |B|, H, and the
// names (vtu_cell_names.hpp). The open-boundary shell is left out (its coordinates are not
// physical); write_vtu drops its nodes.
#include <string>
#include <vector>

#include "postproc/field2d.hpp"
#include "postproc/vtu_writer.hpp"

namespace magfem {

// material_of_part: index into material_names for every part; background air uses
// air_material. region_names: one per part.
VtuGrid make_vtu_2d(const Field2D& field, const std::vector<int>& material_of_part,
                    int air_material, const std::vector<std::string>& material_names,
                    const std::vector<std::string>& region_names);

} // namespace magfem
