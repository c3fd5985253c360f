#pragma once
// The elements around each vertex of a mesh of triangles or tetrahedra (CSR: two passes, count
// then fill), for patches (postproc/patch_recovery2d, patch_recovery3d) and rings of
// neighbours (postproc/probe_error3d).
#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace magfem {

template <std::size_t Corners> class VertexElements {
public:
  VertexElements(const std::vector<std::array<int, Corners>>& elements, std::size_t n_vertices)
      : first_(n_vertices + 1, 0) {
    for (const auto& k : elements)
      for (int v : k)
        ++first_[v + 1];
    for (std::size_t v = 0; v < n_vertices; ++v)
      first_[v + 1] += first_[v];
    elements_.resize(first_.back());
    std::vector<int> fill(first_.begin(), first_.end() - 1);
    for (std::size_t e = 0; e < elements.size(); ++e)
      for (int v : elements[e])
        elements_[fill[v]++] = static_cast<int>(e);
  }
  // The elements that have `vertex` as a corner, in increasing order.
  std::span<const int> of(int vertex) const {
    return {elements_.data() + first_[vertex], elements_.data() + first_[vertex + 1]};
  }

private:
  std::vector<int> first_, elements_;
};

} // namespace magfem
