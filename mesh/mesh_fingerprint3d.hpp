#pragma once
// A 64-bit fingerprint of a tetrahedral mesh: equal meshes (bit for bit: coordinates,
// connectivity, parts, outer faces) give equal fingerprints, and any difference almost surely
// changes it. Processes of a distributed run mesh the case each on their own and compare
// fingerprints before they share the elements out.
#include <cstdint>

#include "mesh/mesh3d.hpp"

namespace magfem {

std::uint64_t mesh_fingerprint(const Mesh3D& mesh);

} // namespace magfem
