#include "solver/dof_map2d.hpp"

#include <algorithm>
#include <stdexcept>

#include "solver/triangle_lagrange.hpp"

namespace magfem {
namespace {
long long edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<long long>(a) << 32) | static_cast<unsigned>(b);
}
} // namespace

DofMap2D::DofMap2D(const Mesh2D& mesh, int order) : order_(order) {
  if (order != 1 && order != 2) throw std::invalid_argument("element order must be 1 or 2");
  const int nv = static_cast<int>(mesh.n_nodes());
  points_ = mesh.nodes;
  n_dofs_ = nv;
  const int per = dofs_per_element();
  element_dofs_.resize(mesh.n_triangles() * per);
  if (order == 2) {
    // Number edges by sorting all element edge keys once: deterministic and cache friendly.
    std::vector<long long> keys;
    keys.reserve(mesh.n_triangles() * 3);
    for (const auto& tri : mesh.triangles)
      for (const auto& e : triangle_edges) keys.push_back(edge_key(tri[e[0]], tri[e[1]]));
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    edge_index_.reserve(keys.size());
    for (const long long k : keys) {
      const int a = static_cast<int>(k >> 32), b = static_cast<int>(k & 0xffffffffLL);
      edge_index_.emplace_back(k, n_dofs_++);
      points_.push_back(0.5 * (mesh.nodes[a] + mesh.nodes[b]));
    }
  }
  for (std::size_t t = 0; t < mesh.n_triangles(); ++t) {
    const auto& tri = mesh.triangles[t];
    int* d = &element_dofs_[t * per];
    for (int i = 0; i < 3; ++i) d[i] = tri[i];
    if (order == 2)
      for (int e = 0; e < 3; ++e) d[3 + e] = edge_dof(tri[triangle_edges[e][0]], tri[triangle_edges[e][1]]);
  }
}

int DofMap2D::edge_dof(int a, int b) const {
  const long long k = edge_key(a, b);
  auto it = std::lower_bound(edge_index_.begin(), edge_index_.end(), std::make_pair(k, -1));
  if (it == edge_index_.end() || it->first != k) throw std::logic_error("edge not in mesh");
  return it->second;
}

std::vector<int> DofMap2D::dofs_on_edges(const std::vector<std::array<int, 2>>& edges) const {
  std::vector<int> out;
  for (const auto& e : edges) {
    out.push_back(e[0]);
    out.push_back(e[1]);
    if (order_ == 2) out.push_back(edge_dof(e[0], e[1]));
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

} // namespace magfem
