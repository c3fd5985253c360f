#include "solver/p1_coarse_space.hpp"

#include <algorithm>

namespace magfem {

Eigen::SparseMatrix<double, Eigen::RowMajor> p1_prolongation(const DofMap3D& dofs,
                                                             const std::vector<int>& dof_to_eq) {
  Eigen::SparseMatrix<double, Eigen::RowMajor> p;
  if (dofs.order() != 2)
    return p;
  const int n_vertices = dofs.n_vertices();
  std::vector<int> coarse(n_vertices, -1);
  int n_coarse = 0, n_eqs = 0;
  for (int v = 0; v < n_vertices; ++v)
    if (dof_to_eq[v] >= 0)
      coarse[v] = n_coarse++;
  for (int e : dof_to_eq)
    n_eqs += e >= 0 ? 1 : 0;
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(n_eqs * 2);
  for (int v = 0; v < n_vertices; ++v)
    if (coarse[v] >= 0)
      entries.emplace_back(dof_to_eq[v], coarse[v], 1.0);
  for (int d = n_vertices; d < dofs.n_dofs(); ++d) {
    if (dof_to_eq[d] < 0)
      continue;
    for (int v : dofs.edge_ends(d))
      if (coarse[v] >= 0)
        entries.emplace_back(dof_to_eq[d], coarse[v], 0.5);
  }
  p.resize(n_eqs, n_coarse);
  p.setFromTriplets(entries.begin(), entries.end());
  return p;
}

std::vector<int> element_equations(const DofMap3D& dofs, const std::vector<int>& dof_to_eq,
                                   std::size_t n_tets,
                                   const std::function<bool(std::size_t)>& in_block) {
  std::vector<char> taken(dof_to_eq.size(), 0);
  const int k = dofs.dofs_per_element();
  for (std::size_t t = 0; t < n_tets; ++t)
    if (in_block(t))
      for (int i = 0; i < k; ++i)
        taken[static_cast<std::size_t>(dofs.element_dofs(t)[i])] = 1;
  std::vector<int> equations;
  for (std::size_t d = 0; d < taken.size(); ++d)
    if (taken[d] && dof_to_eq[d] >= 0)
      equations.push_back(dof_to_eq[d]);
  std::sort(equations.begin(), equations.end());
  return equations;
}

} // namespace magfem
