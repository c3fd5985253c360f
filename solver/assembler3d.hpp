#pragma once
// Weak form of the 3D magnetostatic problem in the total scalar potential phi:
//   H = -grad phi,   B(H) = mu(|H|^2) H + B_r m_hat   (magnets: linear recoil mu0 mu_r),
//   div B = 0  ->  find phi:  r_i(phi) = -integral B(H) . grad N_i = 0  for all N_i,
// i.e. integral mu grad phi . grad N_i = integral B_r m_hat . grad N_i. The remanence enters
// as a source (equivalent to the magnet's surface and volume charges); B . n = 0 is natural.
// Newton tangent: dr_i/dphi_j = integral grad N_i . (mu I + 2 mu' H H^T) grad N_j, symmetric
// positive definite for monotone B-H curves (Picard: mu I).
// In the open-boundary shell the air term carries the shell-transformation metric and the
// outer faces are infinity (phi = 0); `dirichlet` also sets phi = 0 there; `neumann`
// (B . n = 0 everywhere) fixes one gauge DOF instead.
// Unknowns are the free DOFs; constrained DOFs are eliminated.
#include <atomic>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "solver/dof_map3d.hpp"
#include "solver/element_range.hpp"
#include "solver/nonlinear_system.hpp"
#include "solver/problem3d.hpp"
#include "solver/shell_transform.hpp"
#include "solver/sparse_pattern.hpp"

namespace magfem {

struct AssemblyOptions3D {
  // Element loop threads; 0 = all cores (fewer for small meshes). The sums are the serial
  // ones bit for bit whatever the count (core/parallel_scatter.hpp).
  int threads = 0;
  // The tetrahedra whose contributions evaluate(), start_problem(), current_derivative() and
  // the load norm sum (default all): a process's share in a distributed solve, where the
  // residuals are then this share's part (DistributedSystem3D sums them over the processes).
  ElementRange share;
  // When given, the tetrahedra (ascending) summed in place of `share`, and the only ones the
  // sparsity pattern covers: a process's own-row assembly (distributed_rows.hpp).
  std::shared_ptr<const std::vector<std::size_t>> elements = nullptr;
};

class Assembler3D : public NonlinearSystem {
public:
  Assembler3D(const Problem3D& problem, const DofMap3D& dofs, AssemblyOptions3D options = {});

  int n_unknowns() const override { return n_eqs_; }
  bool is_linear() const override { return linear_; }
  void evaluate(const Eigen::VectorXd& u, Eigen::VectorXd& residual,
                Eigen::SparseMatrix<double>* matrix, TangentKind kind) const override;
  // |r(0)|: remembered from the first evaluate() at u = 0, else evaluated on first demand.
  double load_norm() const override;
  // Nonlinear problems: the residual at u = 0 and the matrix of the problem in which every
  // soft material has its start permeability (Material::start_permeability).
  bool start_problem(Eigen::VectorXd& residual, Eigen::SparseMatrix<double>& matrix) const override;
  int threads() const { return loop_threads(); } // of the element loops

  // Free-DOF vector -> all DOFs (constrained ones are zero) and back.
  Eigen::VectorXd expand(const Eigen::VectorXd& u) const;
  Eigen::VectorXd restrict_to_free(const Eigen::VectorXd& phi_full) const;
  const SparsePattern& pattern() const { return pattern_; }
  // d r / d I_coil at u: the load that a unit change of the coil's current adds (reduced
  // regions: the Biot-Savart field; total regions: the tangent applied to Phi_s per ampere).
  // The incremental (differential) inductance follows from K du = -this.
  Eigen::VectorXd current_derivative(const Eigen::VectorXd& u, int coil,
                                     TangentKind kind = TangentKind::newton) const;
  // Every coil's current_derivative at u as the columns of one n_unknowns x n_coils matrix,
  // from one element loop: each element's geometry, source-field values and (total regions)
  // tangent serve all coils. 12-coil actuator design, mesh scale 3: 0.5 s against 6.2 s for
  // twelve current_derivative calls, each of which recomputes every total element's tangent.
  Eigen::MatrixXd current_derivatives(const Eigen::VectorXd& u,
                                      TangentKind kind = TangentKind::newton) const;
  const std::vector<int>& dof_to_equation() const { return dof_to_eq_; }

  // Element residual re (n) and, if ke != nullptr, tangent ke (n x n, row major) of tet t at
  // the full DOF vector phi_full. Public for tests. `start_law`: soft materials take their
  // start permeability (a linear law) instead of their B-H curve.
  void element(std::size_t t, const Eigen::VectorXd& phi_full, double* re, double* ke,
               TangentKind kind, bool start_law = false) const;

private:
  void assemble(const Eigen::VectorXd& u, Eigen::VectorXd& residual,
                Eigen::SparseMatrix<double>* matrix, TangentKind kind, bool start_law) const;
  // -integral mu H_0 . grad N_i over the reduced elements (H_0 = coil field), per equation.
  Eigen::VectorXd source_load(int coil) const; // coil < 0: all coils at their currents
  // coil >= 0: the loads of coils coil .. coil + n_coils - 1 per ampere, n values each, one
  // after the other in re; coil < 0 (n_coils 1): all coils at their currents.
  void element_source(std::size_t t, int coil, int n_coils, double* re) const;
  // Columns first .. first + count - 1 of current_derivatives.
  Eigen::MatrixXd current_derivative_columns(const Eigen::VectorXd& u, int first, int count,
                                             TangentKind kind) const;
  int loop_threads() const; // threads for an element loop (few elements: one)
  // The share's first tetrahedron and count (AssemblyOptions3D::share, clamped to the mesh).
  std::size_t share_first() const;
  std::size_t share_count() const;
  // The e-th tetrahedron of the share, and its element index in the pattern.
  std::size_t share_tet(std::size_t e) const {
    return options_.elements ? (*options_.elements)[e] : share_first() + e;
  }
  std::size_t pattern_element(std::size_t e) const {
    return options_.elements ? e : share_first() + e;
  }

  const Problem3D& problem_;
  const DofMap3D& dofs_;
  AssemblyOptions3D options_;
  ShellTransform shell_;
  int n_eqs_ = 0; // declared before dof_to_eq_, whose initializer sets it
  std::vector<int> dof_to_eq_;
  std::vector<int> element_eqs_;
  bool linear_ = true;
  SparsePattern pattern_;
  Eigen::VectorXd source_load_; // empty without coils
  // Negative until known (load_norm()). Atomic: a const assembler may be shared by threads,
  // which would all store the same value.
  mutable std::atomic<double> load_norm_{-1};
};

} // namespace magfem
