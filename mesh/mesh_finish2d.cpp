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

// Index k of the edge from u to v (either direction) in triangle t, -1 when absent.
int edge_index(const std::array<int, 3>& t, int u, int v) {
  for (int k = 0; k < 3; ++k)
    if (key(t[k], t[(k + 1) % 3]) == key(u, v))
      return k;
  return -1;
}

} // namespace

Neighbours2D neighbours(const Mesh2D& m) {
  std::vector<std::pair<std::uint64_t, int>> half; // (edge key, 3 * triangle + k)
  half.reserve(3 * m.triangles.size());
  for (int t = 0; t < int(m.triangles.size()); ++t)
    for (int k = 0; k < 3; ++k)
      half.emplace_back(key(m.triangles[t][k], m.triangles[t][(k + 1) % 3]), 3 * t + k);
  std::sort(half.begin(), half.end());
  Neighbours2D nb(m.triangles.size(), {-1, -1, -1});
  for (std::size_t i = 0; i + 1 < half.size(); ++i)
    if (half[i].first == half[i + 1].first) {
      const int p = half[i].second, q = half[i + 1].second;
      nb[p / 3][p % 3] = q / 3;
      nb[q / 3][q % 3] = p / 3;
      ++i;
    }
  return nb;
}

int remove_slivers(Mesh2D& m, Neighbours2D& nb) {
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
  // Points the neighbour of t across edge u-v (if any) from `from` to `to`.
  const auto repoint = [&](int t, int u, int v, int from, int to) {
    if (t < 0)
      return;
    const int k = edge_index(m.triangles[t], u, v);
    if (k >= 0 && nb[t][k] == from)
      nb[t][k] = to;
  };
  std::vector<char> dead(m.triangles.size(), 0);
  for (int s : slivers) {
    const auto v = m.triangles[s];
    if (!flat(v))
      continue; // rebuilt by a neighbouring sliver's split
    // Middle vertex c opposite the longest edge a-b: v = (c, a, b) rotated.
    int k = 0;
    double best = -1;
    for (int j = 0; j < 3; ++j) {
      const double l2 = (m.nodes[v[(j + 1) % 3]] - m.nodes[v[(j + 2) % 3]]).squaredNorm();
      if (l2 > best)
        best = l2, k = j;
    }
    const int c = v[k], a = v[(k + 1) % 3], b = v[(k + 2) % 3];
    const int t_ca = nb[s][k], n = nb[s][(k + 1) % 3], t_bc = nb[s][(k + 2) % 3];
    dead[s] = 1;
    if (n < 0) { // a-b is on the boundary: c already lies on it, b-c and c-a become boundary
      repoint(t_bc, b, c, s, -1);
      repoint(t_ca, c, a, s, -1);
      continue;
    }
    // Split the neighbour (b, a, y) at c into (b, c, y) and (c, a, y); orientation is kept.
    auto tn = m.triangles[n];
    auto nbn = nb[n];
    const int j = edge_index(tn, a, b);
    std::rotate(tn.begin(), tn.begin() + j, tn.end());
    std::rotate(nbn.begin(), nbn.begin() + j, nbn.end()); // nbn: across b-a, a-y, y-b
    const int y = tn[2], fresh = int(m.triangles.size());
    m.triangles[n] = {b, c, y};
    nb[n] = {t_bc, fresh, nbn[2]};
    m.triangles.push_back({c, a, y});
    nb.push_back({t_ca, nbn[1], n});
    m.triangle_part.push_back(m.triangle_part[n]);
    dead.push_back(0);
    repoint(t_bc, b, c, s, n);
    repoint(t_ca, c, a, s, fresh);
    repoint(nbn[1], a, y, n, fresh);
  }
  // Compact, renumbering the neighbours.
  std::vector<int> new_index(m.triangles.size(), -1);
  int w = 0;
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    if (!dead[t])
      new_index[t] = w++;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    if (dead[t])
      continue;
    const int i = new_index[t];
    m.triangles[i] = m.triangles[t];
    m.triangle_part[i] = m.triangle_part[t];
    for (int e = 0; e < 3; ++e)
      nb[i][e] = nb[t][e] < 0 ? -1 : new_index[nb[t][e]];
  }
  m.triangles.resize(w);
  m.triangle_part.resize(w);
  nb.resize(w);
  return int(slivers.size());
}

std::vector<std::array<int, 2>> boundary_edges(const Mesh2D& m, const Neighbours2D& nb) {
  std::vector<std::array<int, 2>> out;
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      if (nb[t][k] < 0)
        out.push_back({m.triangles[t][k], m.triangles[t][(k + 1) % 3]});
  return out;
}

std::vector<std::array<int, 2>> interface_edges(const Mesh2D& m, const Neighbours2D& nb,
                                                int region) {
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
