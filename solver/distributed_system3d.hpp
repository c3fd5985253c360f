#pragma once
// The 3D system as every process of a distributed solve sees it: its Assembler3D assembles
// the process's share of the tetrahedra (AssemblyOptions3D::share), and the residuals are
// summed over the processes, so that each holds the whole residual, bit for bit the same
// everywhere (sum_on_every_rank), and Newton takes the same decisions on every process. The
// tangent stays this process's part: DistributedLinearSolver adds the parts into one
// distributed matrix.
#include <Eigen/Core>

#include "solver/assembler3d.hpp"
#include "solver/nonlinear_system.hpp"

namespace magfem {

class DistributedSystem3D : public NonlinearSystem {
public:
  // Collective (the load norm is that of the summed load). `share` is used, not owned.
  explicit DistributedSystem3D(const Assembler3D& share);

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

private:
  const Assembler3D& share_;
  double load_norm_ = 0;
};

} // namespace magfem
