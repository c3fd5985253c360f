#include "solver/current_sensitivity2d.hpp"

namespace magfem {
namespace {

// du/dI of every entry as free-DOF vectors of `assembler`, with the tangent of `assembler`
// taken at a_full (all DOFs of `dofs`).
std::vector<Eigen::VectorXd> solve_sensitivities(const Problem2D& problem, const DofMap2D& dofs,
                                                 const Assembler2D& assembler,
                                                 const Eigen::VectorXd& a_full,
                                                 const std::vector<CurrentPerAmpere2D>& coils,
                                                 const LinearSolverOptions& options) {
  std::vector<Eigen::VectorXd> out;
  if (coils.empty())
    return out;
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> k;
  assembler.evaluate_full(a_full, r, &k, TangentKind::newton);
  LinearSolver solver(options);
  solver.factorize(k);
  // The load of one current alone: the residual at A = 0 of the problem with every region
  // air and only that current (at A = 0 the residual is minus the load, whatever the
  // materials; air drops the magnets' remanence). The equations are numbered alike: the
  // constraints depend on the mesh, the boundary and the planes' conditions only.
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

} // namespace

std::vector<Eigen::VectorXd> current_sensitivities_2d(const Problem2D& problem,
                                                      const DofMap2D& dofs,
                                                      const Assembler2D& assembler,
                                                      const Eigen::VectorXd& u,
                                                      const std::vector<CurrentPerAmpere2D>& coils,
                                                      const LinearSolverOptions& options) {
  return solve_sensitivities(problem, dofs, assembler, assembler.expand(u), coils, options);
}

std::vector<Eigen::VectorXd>
complementary_sensitivities_2d(const Problem2D& problem, const DofMap2D& dofs,
                               const Eigen::VectorXd& a_full, std::size_t plane,
                               const std::vector<CurrentPerAmpere2D>& coils,
                               const LinearSolverOptions& options) {
  // The same mesh and DOFs with the plane's other condition: only the constraints change.
  Mesh2D mesh = *problem.mesh;
  SymmetryField& field = mesh.symmetry.at(plane).field;
  field = field == SymmetryField::normal ? SymmetryField::parallel : SymmetryField::normal;
  Problem2D other = problem;
  other.mesh = &mesh;
  const Assembler2D assembler(other, dofs);
  std::vector<Eigen::VectorXd> out =
      solve_sensitivities(other, dofs, assembler, a_full, coils, options);
  for (Eigen::VectorXd& du : out)
    du = assembler.expand(du);
  return out;
}

} // namespace magfem
