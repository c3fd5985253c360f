#include "solver/distributed_system3d.hpp"

#include "solver/mpi_context.hpp"

namespace magfem {
namespace {
void sum_whole(Eigen::VectorXd& v) {
  sum_on_every_rank(v.data(), static_cast<std::size_t>(v.size()));
}
} // namespace

DistributedSystem3D::DistributedSystem3D(const Assembler3D& share) : share_(share) {
  // The residual at u = 0 is minus the whole external load (remanence and coils).
  Eigen::VectorXd r;
  evaluate(Eigen::VectorXd::Zero(share_.n_unknowns()), r, nullptr, TangentKind::newton);
  load_norm_ = r.norm();
}

void DistributedSystem3D::evaluate(const Eigen::VectorXd& u, Eigen::VectorXd& residual,
                                   Eigen::SparseMatrix<double>* matrix, TangentKind kind) const {
  share_.evaluate(u, residual, matrix, kind);
  sum_whole(residual);
}

bool DistributedSystem3D::start_problem(Eigen::VectorXd& residual,
                                        Eigen::SparseMatrix<double>& matrix) const {
  if (!share_.start_problem(residual, matrix))
    return false;
  sum_whole(residual);
  return true;
}

Eigen::VectorXd DistributedSystem3D::current_derivative(const Eigen::VectorXd& u, int coil) const {
  Eigen::VectorXd d = share_.current_derivative(u, coil);
  sum_whole(d);
  return d;
}

} // namespace magfem
