#pragma once
// Structured tetrahedral meshes of a box for 3D solver tests that must not depend on TetGen:
// every cube is cut into 6 tets around its main diagonal (Kuhn), which conforms across cubes.
// Outer faces are all boundary faces, oriented outward.
#include <algorithm>
#include <array>
#include <map>

#include <Eigen/Dense>

#include "mesh/mesh3d.hpp"

namespace magfem::test {

inline Mesh3D structured_box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, int n) {
  Mesh3D m;
  auto id = [n](int i, int j, int k) { return (k * (n + 1) + j) * (n + 1) + i; };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
        m.nodes.push_back(lo + (hi - lo).cwiseProduct(Eigen::Vector3d(i, j, k) / n));
  // Kuhn: the 6 monotone paths from corner 000 to 111.
  static constexpr std::array<std::array<int, 3>, 6> perms = {
      {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (const auto& p : perms) {
          std::array<int, 3> c = {i, j, k};
          std::array<int, 4> tet;
          tet[0] = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[p[s]];
            tet[s + 1] = id(c[0], c[1], c[2]);
          }
          const auto& x = m.nodes;
          Eigen::Matrix3d jm;
          jm << x[tet[1]] - x[tet[0]], x[tet[2]] - x[tet[0]], x[tet[3]] - x[tet[0]];
          if (jm.determinant() < 0)
            std::swap(tet[2], tet[3]);
          m.tets.push_back(tet);
        }
  m.tet_part.assign(m.tets.size(), 0);
  // Boundary faces: those of exactly one tet, oriented away from the tet's fourth vertex.
  std::map<std::array<int, 3>, std::pair<int, std::array<int, 3>>> faces;
  for (const auto& t : m.tets)
    for (int f = 0; f < 4; ++f) {
      // Face opposite vertex f with outward orientation for a positive tet.
      static constexpr std::array<std::array<int, 3>, 4> local = {
          {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}}};
      std::array<int, 3> face = {t[local[f][0]], t[local[f][1]], t[local[f][2]]};
      std::array<int, 3> key = face;
      std::sort(key.begin(), key.end());
      auto& entry = faces[key];
      ++entry.first;
      entry.second = face;
    }
  for (const auto& [key, entry] : faces)
    if (entry.first == 1)
      m.outer_faces.push_back(entry.second);
  return m;
}

} // namespace magfem::test
