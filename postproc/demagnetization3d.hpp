#pragma once
// The demagnetization check (demagnetization.hpp) of a 3D solve: B . m_hat at the tets'
// vertices (of curved tets too: their vertices are on the curved surface).
#include <string>
#include <vector>

#include "postproc/demagnetization.hpp"
#include "postproc/field3d.hpp"

namespace magfem {

// region_names: one per part of the problem (Geometry3D::parts order).
DemagnetizationResult check_demagnetization_3d(const Field3D& field,
                                               const std::vector<std::string>& region_names);

} // namespace magfem
