#include "solver/dof_map3d.hpp"

#include <algorithm>
#include <stdexcept>

#include "solver/tet_lagrange.hpp"

namespace magfem {
namespace {
long long edge_key(int a, int b) {
  if (a > b)
    std::swap(a, b);
  return (static_cast<long long>(a) << 32) | static_cast<unsigned>(b);
}
} // namespace

DofMap3D::DofMap3D(const Mesh3D& mesh, int order) : order_(order) {
  if (order != 1 && order != 2)
    throw std::invalid_argument("element order must be 1 or 2");
  n_vertices_ = static_cast<int>(mesh.n_nodes());
  points_ = mesh.nodes;
  n_dofs_ = n_vertices_;
  const int per = dofs_per_element();
  const std::size_t n_tets = mesh.n_tets();
  element_dofs_.resize(n_tets * per);
  for (std::size_t t = 0; t < n_tets; ++t)
    for (int i = 0; i < 4; ++i)
      element_dofs_[t * per + i] = mesh.tets[t][i];
  if (order == 1)
    return;

  // Sort (edge key, slot) pairs once: numbers the edges deterministically and fills the
  // element tables without a search per element edge.
  std::vector<std::pair<long long, std::size_t>> slots;
  slots.reserve(n_tets * 6);
  for (std::size_t t = 0; t < n_tets; ++t)
    for (int e = 0; e < 6; ++e)
      slots.emplace_back(edge_key(mesh.tets[t][tet_edges[e][0]], mesh.tets[t][tet_edges[e][1]]),
                         t * per + 4 + e);
  std::sort(slots.begin(), slots.end());
  for (std::size_t k = 0; k < slots.size(); ++k) {
    if (k == 0 || slots[k].first != slots[k - 1].first) {
      const long long key = slots[k].first;
      edge_keys_.push_back(key);
      const int a = static_cast<int>(key >> 32), b = static_cast<int>(key & 0xffffffffLL);
      points_.push_back(0.5 * (mesh.nodes[a] + mesh.nodes[b]));
      ++n_dofs_;
    }
    element_dofs_[slots[k].second] = n_dofs_ - 1;
  }
}

int DofMap3D::edge_dof(int a, int b) const {
  const long long k = edge_key(a, b);
  auto it = std::lower_bound(edge_keys_.begin(), edge_keys_.end(), k);
  if (it == edge_keys_.end() || *it != k)
    throw std::logic_error("edge not in mesh");
  return n_vertices_ + static_cast<int>(it - edge_keys_.begin());
}

std::vector<int> DofMap3D::dofs_on_faces(const std::vector<std::array<int, 3>>& faces) const {
  std::vector<int> out;
  out.reserve(faces.size() * (order_ == 1 ? 3 : 6));
  for (const auto& f : faces) {
    out.insert(out.end(), f.begin(), f.end());
    if (order_ == 2)
      for (int k = 0; k < 3; ++k)
        out.push_back(edge_dof(f[k], f[(k + 1) % 3]));
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

} // namespace magfem
