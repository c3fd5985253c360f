#pragma once
// Points of a VtuGrid that no cell uses (the nodes of the open boundary's shell, whose cells
// are left out of the VTU) removed, the connectivity and the point data renumbered to match.
#include "postproc/vtu_writer.hpp"

namespace magfem {

// Keeps the used points in their order (old point i becomes the number of used points before
// it), so a grid whose points are all used is unchanged. Returns the number removed.
std::size_t drop_unused_points(VtuGrid& grid);

} // namespace magfem
