#include "mesh/mesh_finish2d.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include "core/constants.hpp"

namespace magfem {

namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

double signed_area(const Mesh2D& m, const std::array<int, 3>& t) {
  return 0.5 * cross(m.nodes[t[1]] - m.nodes[t[0]], m.nodes[t[2]] - m.nodes[t[0]]);
}

std::uint64_t key(int a, int b) {
  return (std::uint64_t(std::uint32_t(std::min(a, b))) << 32) | std::uint32_t(std::max(a, b));
}

// Neighbour of each triangle across each edge k (from vertex k to vertex k + 1), -1 on the
// boundary. Sorting the edge keys is cheaper than a hash map at these sizes.
std::vector<std::array<int, 3>> neighbours(const Mesh2D& m) {
  std::vector<std::pair<std::uint64_t, int>> half; // (edge key, 3 * triangle + k)
  half.reserve(3 * m.triangles.size());
  for (int t = 0; t < int(m.triangles.size()); ++t)
    for (int k = 0; k < 3; ++k)
      half.emplace_back(key(m.triangles[t][k], m.triangles[t][(k + 1) % 3]), 3 * t + k);
  std::sort(half.begin(), half.end());
  std::vector<std::array<int, 3>> nb(m.triangles.size(), {-1, -1, -1});
  for (std::size_t i = 0; i + 1 < half.size(); ++i)
    if (half[i].first == half[i + 1].first) {
      const int p = half[i].second, q = half[i + 1].second;
      nb[p / 3][p % 3] = q / 3;
      nb[q / 3][q % 3] = p / 3;
      ++i;
    }
  return nb;
}

// Index k of the edge from u to v (either direction) in triangle t, -1 when absent.
int edge_index(const std::array<int, 3>& t, int u, int v) {
  for (int k = 0; k < 3; ++k)
    if (key(t[k], t[(k + 1) % 3]) == key(u, v))
      return k;
  return -1;
}

} // namespace

int remove_slivers(Mesh2D& m) {
  const auto flat = [&m](const std::array<int, 3>& v) {
    double l2 = 0;
    for (int k = 0; k < 3; ++k)
      l2 = std::max(l2, (m.nodes[v[k]] - m.nodes[v[(k + 1) % 3]]).squaredNorm());
    return std::abs(signed_area(m, v)) <= sliver_area_ratio * l2;
  };
  std::vector<int> slivers;
  for (int t = 0; t < int(m.triangles.size()); ++t)
    if (flat(m.triangles[t]))
      slivers.push_back(t);
  if (slivers.empty())
    return 0;
  const auto nb = neighbours(m);
  const std::size_t n_original = m.triangles.size();
  std::vector<char> dead(n_original, 0);
  for (int s : slivers) {
    const auto v = m.triangles[s];
    if (!flat(v))
      continue; // rebuilt by a neighbouring sliver's split
    // Middle vertex c opposite the longest edge a-b.
    int k = 0;
    double best = -1;
    for (int j = 0; j < 3; ++j) {
      const double l2 = (m.nodes[v[(j + 1) % 3]] - m.nodes[v[(j + 2) % 3]]).squaredNorm();
      if (l2 > best)
        best = l2, k = j;
    }
    const int c = v[k], a = v[(k + 1) % 3], b = v[(k + 2) % 3];
    dead[s] = 1;
    // The neighbour across a-b; an earlier split may have moved that edge to an added triangle.
    int n = nb[s][(k + 1) % 3];
    if (n >= 0 && (dead[n] || edge_index(m.triangles[n], a, b) < 0)) {
      n = -1;
      for (std::size_t t = n_original; t < m.triangles.size(); ++t)
        if (!dead[t] && edge_index(m.triangles[t], a, b) >= 0)
          n = int(t);
    }
    if (n < 0)
      continue; // a-b is on the boundary: c already lies on it
    // Split the neighbour (b, a, y) at c into (b, c, y) and (c, a, y); orientation is kept.
    auto tn = m.triangles[n];
    std::rotate(tn.begin(), tn.begin() + edge_index(tn, a, b), tn.end());
    const int y = tn[2];
    m.triangles[n] = {b, c, y};
    m.triangles.push_back({c, a, y});
    m.triangle_part.push_back(m.triangle_part[n]);
    dead.push_back(0);
  }
  std::size_t w = 0;
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    if (!dead[t]) {
      m.triangles[w] = m.triangles[t];
      m.triangle_part[w++] = m.triangle_part[t];
    }
  m.triangles.resize(w);
  m.triangle_part.resize(w);
  return int(slivers.size());
}

std::vector<std::array<int, 2>> boundary_edges(const Mesh2D& m) {
  const auto nb = neighbours(m);
  std::vector<std::array<int, 2>> out;
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      if (nb[t][k] < 0)
        out.push_back({m.triangles[t][k], m.triangles[t][(k + 1) % 3]});
  return out;
}

std::vector<std::array<int, 2>> interface_edges(const Mesh2D& m, int region) {
  const auto nb = neighbours(m);
  std::vector<std::array<int, 2>> out;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    if (m.triangle_part[t] != region)
      continue;
    for (int k = 0; k < 3; ++k)
      if (nb[t][k] >= 0 && m.triangle_part[nb[t][k]] != region)
        out.push_back({m.triangles[t][k], m.triangles[t][(k + 1) % 3]});
  }
  return out;
}

MeshQuality2D measure_quality(const Mesh2D& m) {
  MeshQuality2D q;
  q.min_angle_deg = 180.0;
  q.min_area = std::numeric_limits<double>::infinity();
  for (const auto& t : m.triangles) {
    q.min_area = std::min(q.min_area, signed_area(m, t));
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2d u = m.nodes[t[(k + 1) % 3]] - m.nodes[t[k]];
      const Eigen::Vector2d w = m.nodes[t[(k + 2) % 3]] - m.nodes[t[k]];
      const double deg = std::atan2(std::abs(cross(u, w)), u.dot(w)) * rad_to_deg;
      q.min_angle_deg = std::min(q.min_angle_deg, deg);
      q.max_angle_deg = std::max(q.max_angle_deg, deg);
    }
  }
  return q;
}

} // namespace magfem
