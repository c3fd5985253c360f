#include "solver/distributed_system3d.hpp"

#include "solver/mpi_context.hpp"

namespace magfem {
namespace {
void sum_whole(Eigen::VectorXd& v) {
  sum_on_every_rank(v.data(), static_cast<std::size_t>(v.size()));
}
} // namespace

DistributedSystem3D::DistributedSystem3D(const Assembler3D& share, const DistributedRows* rows)
    : share_(share), rows_(rows) {
  // The residual at u = 0 is minus the whole external load (remanence and coils).
  Eigen::VectorXd r;
  evaluate(Eigen::VectorXd::Zero(share_.n_unknowns()), r, nullptr, TangentKind::newton);
  load_norm_ = r.norm();
}

void DistributedSystem3D::evaluate(const Eigen::VectorXd& u, Eigen::VectorXd& residual,
                                   Eigen::SparseMatrix<double>* matrix, TangentKind kind) const {
  share_.evaluate(u, residual, matrix, kind);
  keep_own_rows(residual.data(), residual.size(), 1);
  sum_whole(residual);
}

bool DistributedSystem3D::start_problem(Eigen::VectorXd& residual,
                                        Eigen::SparseMatrix<double>& matrix) const {
  if (!share_.start_problem(residual, matrix))
    return false;
  keep_own_rows(residual.data(), residual.size(), 1);
  sum_whole(residual);
  return true;
}

Eigen::VectorXd DistributedSystem3D::current_derivative(const Eigen::VectorXd& u, int coil) const {
  Eigen::VectorXd d = share_.current_derivative(u, coil);
  keep_own_rows(d.data(), d.size(), 1);
  sum_whole(d);
  return d;
}

Eigen::MatrixXd DistributedSystem3D::multiply_summed(const Eigen::SparseMatrix<double>& part,
                                                     const Eigen::MatrixXd& v) const {
  Eigen::MatrixXd kv = part.selfadjointView<Eigen::Lower>() * v;
  keep_own_rows(kv.data(), kv.rows(), kv.cols());
  sum_on_every_rank(kv.data(), static_cast<std::size_t>(kv.size()));
  return kv;
}

void DistributedSystem3D::keep_own_rows(double* v, Eigen::Index rows, Eigen::Index cols) const {
  if (!rows_)
    return;
  for (Eigen::Index i = 0; i < rows; ++i)
    if (!rows_->owns(static_cast<int>(i)))
      for (Eigen::Index c = 0; c < cols; ++c)
        v[c * rows + i] = 0;
}

} // namespace magfem
