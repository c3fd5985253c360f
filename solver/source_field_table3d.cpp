#include "solver/source_field_table3d.hpp"

#include <algorithm>
#include <array>

#include "core/parallel_blocks.hpp"
#include "core/thread_count.hpp"
#include "solver/mpi_context.hpp"
#include "solver/shell_transform.hpp"
#include "solver/tet_lagrange.hpp"
#include "solver/tet_quadrature.hpp"

namespace magfem {
namespace {

// The rule's points in tet t, as the assembler and Field3D place them (isoparametric for
// curved tets).
void rule_points(const Mesh3D& mesh, const DofMap3D& dofs, std::size_t t,
                 std::vector<Eigen::Vector3d>& x) {
  const auto& rule = tet_rule(SourceFieldTable3D::rule_degree);
  x.resize(rule.size());
  if (dofs.is_curved(t)) {
    std::array<Eigen::Vector3d, 10> xn, grad;
    for (int i = 0; i < 10; ++i)
      xn[i] = dofs.dof_points()[dofs.element_dofs(t)[i]];
    for (std::size_t q = 0; q < rule.size(); ++q)
      tet_iso_gradients(xn, rule[q].bary, grad.data(), x[q]);
    return;
  }
  const auto& tet = mesh.tets[t];
  const auto& p = mesh.nodes;
  for (std::size_t q = 0; q < rule.size(); ++q) {
    const auto& b = rule[q].bary;
    x[q] = b[0] * p[tet[0]] + b[1] * p[tet[1]] + b[2] * p[tet[2]] + b[3] * p[tet[3]];
  }
}

// Tets (or DOF points) per block handed to a thread.
constexpr std::size_t block = 256;

} // namespace

SourceFieldTable3D::SourceFieldTable3D(const Problem3D& problem, const DofMap3D& dofs,
                                       const SourceField3D& field, int threads, ElementRange share,
                                       const std::vector<std::size_t>* tets)
    : field_(&field), n_coils_(field.n_coils()),
      n_points_(static_cast<int>(tet_rule(rule_degree).size())) {
  const Mesh3D& mesh = *problem.mesh;
  const std::size_t n_tets = mesh.n_tets();
  values_.resize(n_tets * n_points_ * n_coils_ * 3);
  const ShellTransform shell{mesh.shell_inner_radius, mesh.shell_outer_radius};
  const std::size_t first = std::min(share.first, n_tets);
  const std::size_t last = std::min(share.last, n_tets);
  // The e-th tet this process computes, of `count`.
  const std::size_t count = tets ? tets->size() : last - first;
  const auto tet_of = [&](std::size_t e) { return tets ? (*tets)[e] : first + e; };
  std::vector<unsigned char> computed(n_tets, 0);
  for (std::size_t e = 0; e < count; ++e)
    computed[tet_of(e)] = 1;
  const int n_threads = static_cast<int>(
      std::min<std::size_t>(threads > 0 ? threads : available_threads(), 1 + count / 2000));
  auto fill = [&](std::size_t begin, std::size_t end) {
    std::vector<Eigen::Vector3d> x, h(n_coils_);
    for (std::size_t e = begin; e < end; ++e) {
      const std::size_t t = tet_of(e);
      rule_points(mesh, dofs, t, x);
      const bool in_shell = problem.is_shell(t);
      for (int q = 0; q < n_points_; ++q) {
        field.H_per_ampere_all_once(in_shell ? shell.map(x[q]) : x[q], h.data());
        float* out = &values_[index(t, q, 0)];
        for (int k = 0; k < n_coils_; ++k)
          for (int c = 0; c < 3; ++c)
            *out++ = static_cast<float>(h[k][c]);
      }
    }
  };
  parallel_blocks(count, block, n_threads,
                  [&](std::size_t, std::size_t begin, std::size_t end) { fill(begin, end); });

  // DOF points of the tets outside the shell: B adds H_s at those of reduced tets, and the
  // VTU shows H_s at all of them. Each is computed by the share of its first such tet.
  std::vector<int> points;
  {
    std::vector<unsigned char> seen(dofs.n_dofs(), 0), needed(dofs.n_dofs(), 0);
    for (std::size_t t = 0; t < n_tets; ++t)
      if (!problem.is_shell(t))
        for (int i = 0; i < dofs.dofs_per_element(); ++i) {
          const int d = dofs.element_dofs(t)[i];
          if (!seen[d])
            needed[d] = computed[t];
          seen[d] = 1;
        }
    for (int d = 0; d < dofs.n_dofs(); ++d)
      if (needed[d])
        points.push_back(d);
  }
  at_dofs_.assign(static_cast<std::size_t>(dofs.n_dofs()) * n_coils_ * 3, 0.0f);
  parallel_blocks(points.size(), block, n_threads,
                  [&](std::size_t, std::size_t begin, std::size_t end) {
                    std::vector<Eigen::Vector3d> h(n_coils_);
                    for (std::size_t i = begin; i < end; ++i) {
                      const int d = points[i];
                      field.H_per_ampere_all_once(dofs.dof_points()[d], h.data());
                      float* out = &at_dofs_[static_cast<std::size_t>(d) * n_coils_ * 3];
                      for (int k = 0; k < n_coils_; ++k)
                        for (int c = 0; c < 3; ++c)
                          *out++ = static_cast<float>(h[k][c]);
                    }
                  });
}

void SourceFieldTable3D::gather_to_root() {
  union_to_root(values_.data(), values_.size());
  union_to_root(at_dofs_.data(), at_dofs_.size());
}

Eigen::Vector3d SourceFieldTable3D::H_at_dof(int d) const {
  const float* v = &at_dofs_[static_cast<std::size_t>(d) * n_coils_ * 3];
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int k = 0; k < n_coils_; ++k, v += 3)
    sum += field_->current(k) * Eigen::Vector3d(v[0], v[1], v[2]);
  return sum;
}

void SourceFieldTable3D::H_per_ampere(std::size_t t, int q, Eigen::Vector3d* out) const {
  const float* v = &values_[index(t, q, 0)];
  for (int k = 0; k < n_coils_; ++k, v += 3)
    out[k] = Eigen::Vector3d(v[0], v[1], v[2]);
}

Eigen::Vector3d SourceFieldTable3D::H_per_ampere(std::size_t t, int q, int coil) const {
  const float* v = &values_[index(t, q, coil)];
  return {v[0], v[1], v[2]};
}

Eigen::Vector3d SourceFieldTable3D::H(std::size_t t, int q) const {
  const float* v = &values_[index(t, q, 0)];
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int k = 0; k < n_coils_; ++k, v += 3)
    sum += field_->current(k) * Eigen::Vector3d(v[0], v[1], v[2]);
  return sum;
}

double SourceFieldTable3D::bytes_per_tet_and_coil() {
  return static_cast<double>(tet_rule(rule_degree).size() * 3 * sizeof(float));
}

} // namespace magfem
