#include "postproc/coil_linkage3d.hpp"

#include <algorithm>

#include "core/constants.hpp"
#include "core/parallel_blocks.hpp"
#include "core/thread_count.hpp"
#include "solver/coil_source3d.hpp"
#include "solver/shell_transform.hpp"
#include "solver/tet_quadrature.hpp"

namespace magfem {
namespace {

// Sum over tets of body(t, partial), threaded. The tets are summed in fixed blocks, each into
// its own partial, and the partials added in block order: the result is the same bit for bit
// whatever the thread count or schedule (one partial per thread made it depend on the count).
template <class Body>
Eigen::MatrixXd sum_over_tets(std::size_t n_tets, Eigen::Index rows, Eigen::Index cols,
                              const Body& body) {
  constexpr std::size_t block = 2048;
  const int n_threads =
      static_cast<int>(std::min<std::size_t>(available_threads(), 1 + n_tets / 5000));
  std::vector<Eigen::MatrixXd> partial(block_count(n_tets, block),
                                       Eigen::MatrixXd::Zero(rows, cols));
  parallel_blocks(n_tets, block, n_threads, [&](std::size_t b, std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t)
      body(t, partial[b]);
  });
  Eigen::MatrixXd total = Eigen::MatrixXd::Zero(rows, cols);
  for (const auto& p : partial)
    total += p;
  return total;
}

// Tangent permeability D = dB/dH at H (magnets and linear media: mu I).
Eigen::Matrix3d tangent(const Material& m, const Eigen::Vector3d& h) {
  double mu = 0, dmu = 0;
  m.permeability(h.squaredNorm(), mu, dmu);
  return mu * Eigen::Matrix3d::Identity() + 2 * dmu * h * h.transpose();
}

} // namespace

std::vector<double> flux_linkages_3d(const Field3D& field) {
  const auto& problem = field.problem();
  const CoilSource3D* src = problem.source;
  if (!src || !src->active())
    return {};
  const SourceField3D& coils = *src->field;
  const int nc = coils.n_coils();
  const auto& mesh = *problem.mesh;
  const ShellTransform shell{mesh.shell_inner_radius, mesh.shell_outer_radius};
  const Eigen::MatrixXd sum =
      sum_over_tets(mesh.n_tets(), nc, 1, [&](std::size_t t, Eigen::MatrixXd& acc) {
        const bool in_shell = problem.is_shell(t);
        std::vector<Eigen::Vector3d> h(nc);
        const auto& rule = tet_rule(SourceFieldTable3D::rule_degree);
        for (int qi = 0; qi < static_cast<int>(rule.size()); ++qi) {
          const TetQuadPoint& q = rule[qi];
          const double dv = q.weight * field.volume_density(t, q.bary);
          src->table.H_per_ampere(t, qi, h.data()); // at the mapped point in the shell
          Eigen::Vector3d b;
          double jac = 1;
          if (in_shell) {
            // Physical B at the mapped point: mu0 (H_s + J^-1 (-grad phi)), volume times |det J|.
            const Eigen::Vector3d x = field.point(t, q.bary);
            b = mu0 * (src->table.H(t, qi) + shell.inverse_jacobian(x) * field.H_at(t, qi));
            jac = shell.det_jacobian(x);
          } else {
            b = field.B_at(t, qi);
          }
          for (int k = 0; k < nc; ++k)
            acc(k, 0) += dv * jac * b.dot(h[k]);
        }
      });
  return {sum.col(0).data(), sum.col(0).data() + nc};
}

Eigen::MatrixXd inductance_matrix_3d(const Field3D& field,
                                     const std::vector<Eigen::VectorXd>& dphi_full) {
  const auto& problem = field.problem();
  const CoilSource3D& src = *problem.source;
  const SourceField3D& coils = *src.field;
  const int nc = coils.n_coils();
  const auto& mesh = *problem.mesh;
  const auto& dofs = field.dofs();
  const ShellTransform shell{mesh.shell_inner_radius, mesh.shell_outer_radius};
  Eigen::MatrixXd l =
      sum_over_tets(mesh.n_tets(), nc, nc, [&](std::size_t t, Eigen::MatrixXd& acc) {
        const bool in_shell = problem.is_shell(t);
        const bool total = src.is_total(t);
        const Material& mat = *problem.physics(mesh.tet_part[t]).material;
        const int* dof = dofs.element_dofs(t);
        std::array<Eigen::Vector3d, 10> grad;
        std::vector<Eigen::Vector3d> h(nc);
        const auto& rule = tet_rule(SourceFieldTable3D::rule_degree);
        for (int qi = 0; qi < static_cast<int>(rule.size()); ++qi) {
          const TetQuadPoint& q = rule[qi];
          Eigen::Vector3d x;
          const int n = field.shape_gradients(t, q.bary, grad, x);
          const double dv = q.weight * field.volume_density(t, q.bary);
          const double jac = in_shell ? shell.det_jacobian(x) : 1.0;
          src.table.H_per_ampere(t, qi, h.data()); // at the mapped point in the shell
          const Eigen::Matrix3d d = in_shell ? Eigen::Matrix3d(mu0 * Eigen::Matrix3d::Identity())
                                             : tangent(mat, field.H_at(t, qi));
          for (int j = 0; j < nc; ++j) {
            Eigen::Vector3d g = Eigen::Vector3d::Zero();
            for (int i = 0; i < n; ++i)
              g += (dphi_full[j][dof[i]] + (total ? src.offset_per_ampere[j][dof[i]] : 0.0)) *
                   grad[i];
            Eigen::Vector3d dh =
                in_shell ? Eigen::Vector3d(h[j] - shell.inverse_jacobian(x) * g)
                         : Eigen::Vector3d(total ? Eigen::Vector3d(-g) : Eigen::Vector3d(h[j] - g));
            const Eigen::Vector3d db = d * dh;
            for (int i = 0; i < nc; ++i)
              acc(i, j) += dv * jac * db.dot(h[i]);
          }
        }
      });
  return l;
}

} // namespace magfem
