#pragma once
// The demagnetization check (demagnetization.hpp) of a planar or axisymmetric solve: B . m_hat
// at the triangles' vertices, in the (x, y) or (r, z) plane.
#include <string>
#include <vector>

#include "postproc/demagnetization.hpp"
#include "postproc/field2d.hpp"

namespace magfem {

// region_names: one per part of the problem (Geometry2D::parts order).
DemagnetizationResult check_demagnetization_2d(const Field2D& field,
                                               const std::vector<std::string>& region_names);

} // namespace magfem
