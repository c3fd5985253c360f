#pragma once
// Weak form of the 2D magnetostatic problem (planar A_z or axisymmetric A_phi) on Lagrange
// triangles:
//   find A:  integral H(B) . curl N_i dV  =  integral J N_i dV    for all test functions N_i,
// with B and dV from curl2d.hpp and H = nu (B - B_r m_hat) (magnets enter through
// their remanence, which is equivalent to their surface and volume currents). In the
// open-boundary shell the air term carries the shell-transformation metric.
// Unknowns are the free DOFs: Dirichlet DOFs (A = 0 on the outer boundary and, axisymmetric,
// on the axis, or one gauge DOF for a pure planar Neumann problem) are eliminated.
#include <vector>

#include <Eigen/Core>

#include "solver/dof_map2d.hpp"
#include "solver/nonlinear_system.hpp"
#include "solver/problem2d.hpp"
#include "solver/shell_transform.hpp"
#include "solver/sparse_pattern.hpp"

namespace magfem {

class Assembler2D : public NonlinearSystem {
public:
  Assembler2D(const Problem2D& problem, const DofMap2D& dofs);

  int n_unknowns() const override { return n_eqs_; }
  bool is_linear() const override { return linear_; }
  void evaluate(const Eigen::VectorXd& u, Eigen::VectorXd& residual,
                Eigen::SparseMatrix<double>* matrix, TangentKind kind) const override;
  double load_norm() const override { return load_norm_; }
  // evaluate at a vector of all DOFs, constrained ones included: the tangent at an operating
  // point solved under other constraints (a symmetry plane's other condition,
  // current_sensitivity2d.hpp), whose values on the plane this assembler would drop.
  void evaluate_full(const Eigen::VectorXd& a_full, Eigen::VectorXd& residual,
                     Eigen::SparseMatrix<double>* matrix, TangentKind kind) const;

  // Free-DOF vector -> all DOFs (constrained ones are zero) and back.
  Eigen::VectorXd expand(const Eigen::VectorXd& u) const;
  const SparsePattern& pattern() const { return pattern_; }

private:
  void element(std::size_t t, const Eigen::VectorXd& a_full, double* re, double* ke,
               TangentKind kind, bool want_matrix) const;
  double compute_load_norm() const;
  // Shell metric acting on B (planar: from the metric on grad A_z).
  Eigen::Matrix2d shell_metric(const Eigen::Vector2d& x) const;

  const Problem2D& problem_;
  const DofMap2D& dofs_;
  ShellTransform shell_;
  int n_eqs_ = 0; // set by the initializer of dof_to_eq_, hence declared before it
  std::vector<int> dof_to_eq_;
  std::vector<int> element_eqs_;
  bool linear_ = true;
  SparsePattern pattern_;
  double load_norm_ = 0;
};

} // namespace magfem
