#pragma once
// Quality figures of a tetrahedral mesh: dihedral angles and radius-edge ratios.
#include <array>
#include <vector>

#include <Eigen/Core>

#include "mesh/mesh3d.hpp"

namespace magfem {

// Signed volume of the tetrahedron (a, b, c, d); positive when (b-a, c-a, d-a) is right-handed.
double tet_volume(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                  const Eigen::Vector3d& d);

// Minimum and maximum dihedral angle (degrees) and maximum circumradius / shortest edge over
// all tets.
MeshQuality3D compute_quality_3d(const std::vector<Eigen::Vector3d>& nodes,
                                 const std::vector<std::array<int, 4>>& tets);

} // namespace magfem
