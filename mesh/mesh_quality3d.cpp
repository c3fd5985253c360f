#include "mesh/mesh_quality3d.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <Eigen/Geometry>

#include "core/parallel_blocks.hpp"
#include "core/thread_count.hpp"

namespace magfem {

double tet_volume(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                  const Eigen::Vector3d& d) {
  return (b - a).dot((c - a).cross(d - a)) / 6;
}

namespace {

// The dihedral angles and radius-edge ratio of one tet folded into q.
void add_tet_quality(const std::vector<Eigen::Vector3d>& nodes, const std::array<int, 4>& t,
                     MeshQuality3D& q) {
  using V = Eigen::Vector3d;
  // Face f is opposite vertex f; edge (i, j) is shared by the faces opposite the other two.
  constexpr int edges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  const V p[4] = {nodes[t[0]], nodes[t[1]], nodes[t[2]], nodes[t[3]]};
  V n[4];
  for (int f = 0; f < 4; ++f) {
    const V& a = p[(f + 1) % 4];
    const V& b = p[(f + 2) % 4];
    const V& c = p[(f + 3) % 4];
    n[f] = (b - a).cross(c - a).normalized();
    if (n[f].dot(p[f] - a) > 0)
      n[f] = -n[f]; // outward
  }
  double shortest = std::numeric_limits<double>::infinity();
  for (const auto& e : edges) {
    int other[2], k = 0;
    for (int v = 0; v < 4; ++v)
      if (v != e[0] && v != e[1])
        other[k++] = v;
    const double cosang = std::clamp(-n[other[0]].dot(n[other[1]]), -1.0, 1.0);
    const double ang = std::acos(cosang) * 180 / std::numbers::pi;
    q.min_dihedral_deg = std::min(q.min_dihedral_deg, ang);
    q.max_dihedral_deg = std::max(q.max_dihedral_deg, ang);
    shortest = std::min(shortest, (p[e[0]] - p[e[1]]).norm());
  }
  const V a = p[1] - p[0], b = p[2] - p[0], c = p[3] - p[0];
  const V num =
      a.squaredNorm() * b.cross(c) + b.squaredNorm() * c.cross(a) + c.squaredNorm() * a.cross(b);
  const double circumradius = num.norm() / (2 * std::abs(a.dot(b.cross(c))));
  q.max_radius_edge = std::max(q.max_radius_edge, circumradius / shortest);
}

} // namespace

// On all cores, per block of tets, then the blocks' extremes: minima and maxima are exact
// in any order, so the result is the serial one.
MeshQuality3D compute_quality_3d(const std::vector<Eigen::Vector3d>& nodes,
                                 const std::vector<std::array<int, 4>>& tets) {
  MeshQuality3D q;
  q.min_dihedral_deg = tets.empty() ? 0 : 180;
  q.max_dihedral_deg = 0;
  q.max_radius_edge = 0;
  const std::size_t block = 16384;
  std::vector<MeshQuality3D> part(block_count(tets.size(), block), q);
  parallel_blocks(tets.size(), block, element_loop_threads(tets.size()),
                  [&](std::size_t b, std::size_t lo, std::size_t hi) {
                    for (std::size_t t = lo; t < hi; ++t)
                      add_tet_quality(nodes, tets[t], part[b]);
                  });
  for (const MeshQuality3D& p : part) {
    q.min_dihedral_deg = std::min(q.min_dihedral_deg, p.min_dihedral_deg);
    q.max_dihedral_deg = std::max(q.max_dihedral_deg, p.max_dihedral_deg);
    q.max_radius_edge = std::max(q.max_radius_edge, p.max_radius_edge);
  }
  return q;
}

} // namespace magfem
