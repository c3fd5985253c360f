#include "mesh/mesh_finish2d.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

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

// Triangle indices by undirected edge (at most two per edge in a conforming mesh).
std::unordered_map<std::uint64_t, std::array<int, 2>> edge_triangles(const Mesh2D& m) {
  std::unordered_map<std::uint64_t, std::array<int, 2>> map;
  map.reserve(m.triangles.size() * 2);
  for (int t = 0; t < int(m.triangles.size()); ++t)
    for (int k = 0; k < 3; ++k) {
      auto [it, fresh] = map.try_emplace(key(m.triangles[t][k], m.triangles[t][(k + 1) % 3]),
                                         std::array<int, 2>{t, -1});
      if (!fresh)
        it->second[1] = t;
    }
  return map;
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
  auto edges = edge_triangles(m);
  std::vector<char> dead(m.triangles.size(), 0);
  for (int s : slivers) {
    const auto v = m.triangles[s];
    if (!flat(v))
      continue; // a neighbouring sliver's split already rebuilt it
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
    const auto& pair = edges.at(key(a, b));
    const int n = pair[0] == s ? pair[1] : pair[0];
    const auto replace = [&](int p, int q, int from, int to) {
      auto& pair_pq = edges.at(key(p, q));
      (pair_pq[0] == from ? pair_pq[0] : pair_pq[1]) = to;
    };
    if (n < 0) { // a-b is on the boundary: c already lies on it, b-c and c-a become boundary
      replace(b, c, s, -1);
      replace(c, a, s, -1);
      edges.erase(key(a, b));
      continue;
    }
    // Split neighbour (b, a, y) at c into (b, c, y) and (c, a, y); orientation is kept.
    auto tn = m.triangles[n];
    while (!(tn[0] == b && tn[1] == a))
      std::rotate(tn.begin(), tn.begin() + 1, tn.end());
    const int y = tn[2], fresh = int(m.triangles.size());
    m.triangles[n] = {b, c, y};
    m.triangles.push_back({c, a, y});
    m.triangle_part.push_back(m.triangle_part[n]);
    dead.push_back(0);
    // Edge map: b-c and c-a now border n and fresh instead of the sliver, a-y borders fresh.
    replace(b, c, s, n);
    replace(c, a, s, fresh);
    replace(a, y, n, fresh);
    edges[key(c, y)] = {n, fresh};
    edges.erase(key(a, b));
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
  const auto edges = edge_triangles(m);
  std::vector<std::array<int, 2>> out;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k)
      if (edges.at(key(t[k], t[(k + 1) % 3]))[1] < 0)
        out.push_back({t[k], t[(k + 1) % 3]});
  return out;
}

std::vector<std::array<int, 2>> interface_edges(const Mesh2D& m, int region) {
  const auto edges = edge_triangles(m);
  std::vector<std::array<int, 2>> out;
  for (int t = 0; t < int(m.triangles.size()); ++t) {
    if (m.triangle_part[t] != region)
      continue;
    for (int k = 0; k < 3; ++k) {
      const auto& pair = edges.at(key(m.triangles[t][k], m.triangles[t][(k + 1) % 3]));
      const int n = pair[0] == t ? pair[1] : pair[0];
      if (n >= 0 && m.triangle_part[n] != region)
        out.push_back({m.triangles[t][k], m.triangles[t][(k + 1) % 3]});
    }
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
