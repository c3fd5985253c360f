#pragma once
// The tets around each vertex of a 3D mesh (CSR: two passes, count then fill), for patches
// (postproc/patch_recovery3d) and rings of neighbours (postproc/probe_error3d).
#include <span>
#include <vector>

#include "mesh/mesh3d.hpp"

namespace magfem {

class VertexTets3D {
public:
  explicit VertexTets3D(const Mesh3D& mesh) : first_(mesh.n_nodes() + 1, 0) {
    for (const auto& k : mesh.tets)
      for (int v : k)
        ++first_[v + 1];
    for (std::size_t v = 0; v < mesh.n_nodes(); ++v)
      first_[v + 1] += first_[v];
    tets_.resize(first_.back());
    std::vector<int> fill(first_.begin(), first_.end() - 1);
    for (std::size_t t = 0; t < mesh.n_tets(); ++t)
      for (int v : mesh.tets[t])
        tets_[fill[v]++] = static_cast<int>(t);
  }
  // The tets that have `vertex` as a corner, in increasing order.
  std::span<const int> of(int vertex) const {
    return {tets_.data() + first_[vertex], tets_.data() + first_[vertex + 1]};
  }

private:
  std::vector<int> first_, tets_;
};

} // namespace magfem
