#include "solver/current_sensitivity2d.hpp"

namespace magfem {

std::vector<Eigen::VectorXd> current_sensitivities_2d(const Problem2D& problem,
                                                      const DofMap2D& dofs,
                                                      const Assembler2D& assembler,
                                                      const Eigen::VectorXd& u,
                                                      const std::vector<CurrentPerAmpere2D>& coils,
                                                      const LinearSolverOptions& options) {
  std::vector<Eigen::VectorXd> out;
  if (coils.empty())
    return out;
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> k;
  assembler.evaluate(u, r, &k, TangentKind::newton);
  LinearSolver solver(options);
  solver.factorize(k);
  // The load of one current alone: the residual at A = 0 of the problem with every region
  // air and only that current (at A = 0 the residual is minus the load, whatever the
  // materials; air drops the magnets' remanence). The equations are numbered alike: the
  // constraints depend on the mesh and the boundary only.
  Problem2D alone = problem;
  for (auto& p : alone.parts)
    p = RegionPhysics2D{alone.air.material, {}, 0.0};
  for (const auto& c : coils) {
    auto& p = alone.parts[static_cast<std::size_t>(c.part)];
    p.current_density = c.density_per_A;
    const Assembler2D load(alone, dofs);
    load.evaluate(Eigen::VectorXd::Zero(load.n_unknowns()), r, nullptr, TangentKind::newton);
    out.push_back(solver.solve(-r));
    p.current_density = 0;
  }
  return out;
}

} // namespace magfem
