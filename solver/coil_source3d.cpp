#include "solver/coil_source3d.hpp"

#include <algorithm>
#include <cmath>
#include <queue>

#include "core/gauss_legendre.hpp"

namespace magfem {
namespace {

bool is_soft(const Material& m) {
  return !m.is_magnet() && (m.is_nonlinear() || m.mu_r != 1.0);
}

// -integral_a^b H_s . dl per ampere for every coil: the source potential difference
// Phi_s(b) - Phi_s(a). Four Gauss points: H_s is smooth on the scale of an element edge in
// iron (the coils are outside), so the error is far below the FE error.
void potential_step(const SourceField3D& field, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                    const QuadratureRule& rule, std::vector<double>& out) {
  const int nc = field.n_coils();
  std::fill(out.begin(), out.end(), 0.0);
  const Eigen::Vector3d d = b - a;
  std::vector<Eigen::Vector3d> h(nc);
  for (std::size_t q = 0; q < rule.x.size(); ++q) {
    field.H_per_ampere_all(a + rule.x[q] * d, h.data());
    for (int k = 0; k < nc; ++k)
      out[k] -= rule.w[q] * h[k].dot(d);
  }
}

// DOF -> tets of the total regions, CSR.
void dof_to_tets(const DofMap3D& dofs, const std::vector<unsigned char>& total,
                 std::vector<int>& start, std::vector<int>& items) {
  const int per = dofs.dofs_per_element();
  start.assign(dofs.n_dofs() + 1, 0);
  for (std::size_t t = 0; t < total.size(); ++t)
    if (total[t])
      for (int i = 0; i < per; ++i)
        ++start[dofs.element_dofs(t)[i] + 1];
  for (int d = 0; d < dofs.n_dofs(); ++d)
    start[d + 1] += start[d];
  items.assign(start.back(), 0);
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (std::size_t t = 0; t < total.size(); ++t)
    if (total[t])
      for (int i = 0; i < per; ++i)
        items[fill[dofs.element_dofs(t)[i]]++] = static_cast<int>(t);
}

} // namespace

CoilSource3D make_coil_source_3d(const Problem3D& problem, const DofMap3D& dofs,
                                 const SourceField3D& field, ElementRange share,
                                 const std::vector<std::size_t>* tets) {
  CoilSource3D src;
  src.field = &field;
  const auto& mesh = *problem.mesh;
  const int nc = field.n_coils();
  const int per = dofs.dofs_per_element();
  src.total.assign(mesh.n_tets(), 0);
  for (std::size_t t = 0; t < mesh.n_tets(); ++t) {
    const int part = mesh.tet_part[t];
    src.total[t] = part >= 0 && is_soft(*problem.parts[part].material);
  }
  src.offset_per_ampere.assign(nc, Eigen::VectorXd::Zero(dofs.n_dofs()));
  src.offset = Eigen::VectorXd::Zero(dofs.n_dofs());
  if (nc == 0)
    return src;

  std::vector<int> start, items;
  dof_to_tets(dofs, src.total, start, items);
  const auto& x = dofs.dof_points();
  const QuadratureRule rule = gauss_legendre(4, 0.0, 1.0);
  std::vector<int> component(dofs.n_dofs(), -1);
  std::vector<double> step(nc);
  std::vector<std::vector<int>> members; // DOFs of each component
  // Breadth-first over the DOF graph of each component: Phi_s(j) = Phi_s(i) + step(i -> j).
  for (int seed = 0; seed < dofs.n_dofs(); ++seed) {
    if (component[seed] >= 0 || start[seed] == start[seed + 1])
      continue;
    const int c = static_cast<int>(members.size());
    members.emplace_back();
    std::queue<int> queue;
    component[seed] = c;
    queue.push(seed);
    while (!queue.empty()) {
      const int i = queue.front();
      queue.pop();
      members[c].push_back(i);
      for (int k = start[i]; k < start[i + 1]; ++k) {
        const int* ed = dofs.element_dofs(items[k]);
        for (int a = 0; a < per; ++a) {
          const int j = ed[a];
          if (component[j] >= 0)
            continue;
          component[j] = c;
          potential_step(field, x[i], x[j], rule, step);
          for (int q = 0; q < nc; ++q)
            src.offset_per_ampere[q][j] = src.offset_per_ampere[q][i] + step[q];
          queue.push(j);
        }
      }
    }
  }
  // Consistency: around every element the steps must close. A mismatch of the order of the
  // turns means the component links a coil current.
  std::vector<double> mismatch(members.size(), 0.0);
  for (std::size_t t = 0; t < mesh.n_tets(); ++t) {
    if (!src.total[t])
      continue;
    const int* ed = dofs.element_dofs(t);
    for (int a = 1; a < 4; ++a) {
      potential_step(field, x[ed[0]], x[ed[a]], rule, step);
      for (int q = 0; q < nc; ++q) {
        const double e =
            src.offset_per_ampere[q][ed[a]] - src.offset_per_ampere[q][ed[0]] - step[q];
        auto& m = mismatch[component[ed[0]]];
        m = std::max(m, std::abs(e) / std::max(field.turns(q), 1e-300));
      }
    }
  }
  for (std::size_t c = 0; c < members.size(); ++c) {
    if (mismatch[c] < 1e-3)
      continue;
    src.warnings.push_back("an iron component of " + std::to_string(members[c].size()) +
                           " nodes encircles a coil current; it is solved with the reduced "
                           "potential (expect the cancellation error in its field)");
    for (std::size_t t = 0; t < mesh.n_tets(); ++t)
      if (src.total[t] && component[dofs.element_dofs(t)[0]] == static_cast<int>(c))
        src.total[t] = 0;
    for (int d : members[c])
      for (int q = 0; q < nc; ++q)
        src.offset_per_ampere[q][d] = 0;
  }
  for (int q = 0; q < nc; ++q)
    src.offset += field.current(q) * src.offset_per_ampere[q];
  src.table = SourceFieldTable3D(problem, dofs, field, 0, share, tets);
  return src;
}

} // namespace magfem
