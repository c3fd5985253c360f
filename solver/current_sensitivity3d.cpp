#include "solver/current_sensitivity3d.hpp"

namespace magfem {

std::vector<Eigen::VectorXd> current_sensitivities_3d(const Assembler3D& assembler,
                                                      const Eigen::VectorXd& u, int n_coils,
                                                      const LinearSolverOptions& options) {
  std::vector<Eigen::VectorXd> out;
  if (n_coils == 0)
    return out;
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> k;
  assembler.evaluate(u, r, &k, TangentKind::newton);
  LinearSolver solver(options);
  solver.factorize(k);
  for (int j = 0; j < n_coils; ++j)
    out.push_back(-solver.solve(assembler.current_derivative(u, j)));
  return out;
}

} // namespace magfem
