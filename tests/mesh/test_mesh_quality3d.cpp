// compute_quality_3d folds its tets in blocks on all cores and then the blocks' extremes
// (mesh/mesh_quality3d.cpp). The figures are checked against closed forms: a regular tet's
// dihedral angle acos(1/3) and radius-edge ratio sqrt(6)/4, and the corner tet (0, e_x, e_y,
// e_z), whose dihedral angles are 90 deg at the axis edges and acos(1/sqrt 3) at the others,
// with circumradius sqrt(3)/2 over a shortest edge of 1.
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "mesh/mesh_quality3d.hpp"

namespace magfem {
namespace {

constexpr double deg = 180 / std::numbers::pi;

struct TetSoup {
  std::vector<Eigen::Vector3d> nodes;
  std::vector<std::array<int, 4>> tets;
  void add(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
           const Eigen::Vector3d& d) {
    const int n = static_cast<int>(nodes.size());
    nodes.insert(nodes.end(), {a, b, c, d});
    tets.push_back({n, n + 1, n + 2, n + 3});
  }
};

TetSoup regular_tets(std::size_t count) {
  TetSoup soup;
  for (std::size_t i = 0; i < count; ++i) {
    const Eigen::Vector3d o(3.0 * static_cast<double>(i), 0, 0); // apart; shape is what counts
    soup.add(o + Eigen::Vector3d(1, 1, 1), o + Eigen::Vector3d(1, -1, -1),
             o + Eigen::Vector3d(-1, 1, -1), o + Eigen::Vector3d(-1, -1, 1));
  }
  return soup;
}

void add_corner_tet(TetSoup& soup) {
  soup.add({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1});
}

TEST(MeshQuality3D, RegularTetsGiveTheClosedForm) {
  const TetSoup soup = regular_tets(10);
  const MeshQuality3D q = compute_quality_3d(soup.nodes, soup.tets);
  EXPECT_NEAR(q.min_dihedral_deg, std::acos(1.0 / 3) * deg, 1e-9);
  EXPECT_NEAR(q.max_dihedral_deg, std::acos(1.0 / 3) * deg, 1e-9);
  EXPECT_NEAR(q.max_radius_edge, std::sqrt(6.0) / 4, 1e-12);
}

// The worst tet last, in a partial block after several full ones (the reduction's blocks are
// 16384 tets): a reduction that drops a block, or the last partial one, misses it. And first,
// for a reduction that starts from the second block.
TEST(MeshQuality3D, ExtremesAreFoundInEveryBlock) {
  for (const bool last : {true, false}) {
    TetSoup soup;
    if (!last)
      add_corner_tet(soup);
    const TetSoup regular = regular_tets(3 * 16384 + 5);
    for (const auto& t : regular.tets)
      soup.add(regular.nodes[t[0]], regular.nodes[t[1]], regular.nodes[t[2]], regular.nodes[t[3]]);
    if (last)
      add_corner_tet(soup);
    const MeshQuality3D q = compute_quality_3d(soup.nodes, soup.tets);
    EXPECT_NEAR(q.min_dihedral_deg, std::acos(1 / std::sqrt(3.0)) * deg, 1e-9) << last;
    EXPECT_NEAR(q.max_dihedral_deg, 90.0, 1e-9) << last;
    EXPECT_NEAR(q.max_radius_edge, std::sqrt(3.0) / 2, 1e-12) << last;
  }
}

} // namespace
} // namespace magfem
