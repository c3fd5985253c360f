#pragma once
// Whether two placed 3D parts share volume, for the paths that never mesh (the analytic
// models): the mesher finds intersections itself, but the charge model would silently add
// up two magnets occupying the same space.
#include <optional>

#include "mesh/geometry3d.hpp"

namespace magfem {

// A point inside both parts, found by sampling a on an n^3 grid of its own coordinates;
// nothing if none is found (an overlap thinner than about a grid step of a can be missed,
// so callers test both ways round).
std::optional<Vec3> overlap_point(const Part3D& a, const Part3D& b, int n = 20);

} // namespace magfem
