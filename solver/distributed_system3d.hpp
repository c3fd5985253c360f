#pragma once
// The 3D system as every process of a distributed solve sees it: its Assembler3D assembles
// the process's share of the tetrahedra (AssemblyOptions3D::share), and the residuals are
// summed over the processes, so that each holds the whole residual, bit for bit the same
// everywhere (sum_on_every_rank), and Newton takes the same decisions on every process. The
// tangent stays this process's part: DistributedLinearSolver adds the parts into one
// distributed matrix.
//
// Own-row assembly (distributed_rows.hpp): the share is the tetrahedra touching the process's
// rows, some of them also another's; each process then keeps only the residual entries of
// the rows it owns before the sum, so that every entry comes whole from one process.
#include <Eigen/Core>

#include "solver/assembler3d.hpp"
#include "solver/distributed_rows.hpp"
#include "solver/nonlinear_system.hpp"

namespace magfem {

class DistributedSystem3D : public NonlinearSystem {
public:
  // Collective (the load norm is that of the summed load). `share` and `rows` (own-row
  // assembly; null: a share of the tetrahedra whose parts add up) are used, not owned.
  explicit DistributedSystem3D(const Assembler3D& share, const DistributedRows* rows = nullptr);

  int n_unknowns() const override { return share_.n_unknowns(); }
  bool is_linear() const override { return share_.is_linear(); }
  // Collective: the whole residual; `matrix` (if given) this process's part of the tangent.
  void evaluate(const Eigen::VectorXd& u, Eigen::VectorXd& residual,
                Eigen::SparseMatrix<double>* matrix, TangentKind kind) const override;
  double load_norm() const override { return load_norm_; }
  // Collective, as evaluate().
  bool start_problem(Eigen::VectorXd& residual, Eigen::SparseMatrix<double>& matrix) const override;
  // Collective: the whole d r / d I_coil at u (Assembler3D::current_derivative).
  Eigen::VectorXd current_derivative(const Eigen::VectorXd& u, int coil) const;
  // Collective: K v for this process's part of the tangent, whole on every process (the
  // products of the parts summed; own-row assembly: each process's own rows).
  Eigen::MatrixXd multiply_summed(const Eigen::SparseMatrix<double>& part,
                                  const Eigen::MatrixXd& v) const;

private:
  // Own-row assembly: zeroes the entries of rows other processes own (each column of `v`).
  void keep_own_rows(double* v, Eigen::Index rows, Eigen::Index cols) const;

  const Assembler3D& share_;
  const DistributedRows* rows_;
  double load_norm_ = 0;
};

} // namespace magfem
