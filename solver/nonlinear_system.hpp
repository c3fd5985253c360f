#pragma once
// A discretised (possibly nonlinear) magnetostatic problem as the Newton driver sees it:
// unknowns u (free DOFs), residual r(u) = internal(u) - external, and its tangent.
#include <Eigen/SparseCore>

namespace magfem {

enum class TangentKind {
  newton, // exact Jacobian dr/du (nu I + 2 nu' B B^T)
  picard  // secant matrix (nu I): fixed-point iteration
};

class NonlinearSystem {
public:
  virtual ~NonlinearSystem() = default;
  virtual int n_unknowns() const = 0;
  virtual bool is_linear() const = 0;
  // Residual at u; if `matrix` is non-null also the tangent (lower triangle).
  virtual void evaluate(const Eigen::VectorXd& u, Eigen::VectorXd& residual,
                        Eigen::SparseMatrix<double>* matrix, TangentKind kind) const = 0;
  // Norm of the external load, the scale for relative residuals.
  virtual double load_norm() const = 0;
  // A linear problem K u0 = -r whose solution is a better place for Newton to start than
  // u = 0: fills r and K (lower triangle) and returns true, or returns false (start at zero).
  virtual bool start_problem(Eigen::VectorXd& /*residual*/,
                             Eigen::SparseMatrix<double>& /*matrix*/) const {
    return false;
  }
};

} // namespace magfem
