#pragma once
// What Newton (newton.hpp) and the coils' sensitivity solves ask of a linear solver: set up on
// a tangent matrix once, then solve for one or several right-hand sides. LinearSolver
// (linear_solver.hpp) does it on one process; DistributedLinearSolver
// (distributed_linear_solver.hpp) over the processes of an mpirun, each of which passes the
// part of the tangent its elements contributed.
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace magfem {

class TangentSolver {
public:
  virtual ~TangentSolver() = default;
  // `lower`: the symmetric matrix by its lower triangle (distributed: this process's part).
  virtual void factorize(const Eigen::SparseMatrix<double>& lower) = 0;
  virtual Eigen::VectorXd solve(const Eigen::VectorXd& rhs) = 0;
  // One solution per column, with one set-up.
  virtual Eigen::MatrixXd solve_many(const Eigen::MatrixXd& rhs) = 0;
  virtual void set_cg_tolerance(double tol) = 0;
  virtual std::string name() const = 0;           // cholmod | cg
  virtual std::string preconditioner() const = 0; // none | ichol | boomeramg | gamg | pmg | ...
  virtual int last_iterations() const = 0;
  virtual double setup_seconds() const = 0;
  virtual double solve_seconds() const = 0;
  virtual const std::vector<std::string>& notes() const = 0;
};

} // namespace magfem
