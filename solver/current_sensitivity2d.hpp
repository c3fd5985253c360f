#pragma once
// Sensitivity of the 2D (planar or axisymmetric) solution to one region's current at a
// converged operating point: K du = f, K the Newton tangent there and f the load of the
// region's current density per ampere (turns / area), so that du = dA / dI. For linear media
// du is the potential of that current alone (magnets and other currents do not enter); for
// nonlinear iron it is the small-signal response. The differential inductance of a coil is
// its linkage with du (coil_linkage_axi.hpp).
#include <vector>

#include <Eigen/Core>

#include "solver/assembler2d.hpp"
#include "solver/dof_map2d.hpp"
#include "solver/linear_solver.hpp"
#include "solver/problem2d.hpp"

namespace magfem {

struct CurrentPerAmpere2D {
  int part = 0;             // Problem2D::parts index
  double density_per_A = 0; // A/m^2 per ampere of the coil current (turns / meshed area)
};

// du/dI for every entry, as free-DOF vectors of `assembler` (built on `problem` and `dofs`).
// One factorization of the tangent serves all of them.
std::vector<Eigen::VectorXd> current_sensitivities_2d(const Problem2D& problem,
                                                      const DofMap2D& dofs,
                                                      const Assembler2D& assembler,
                                                      const Eigen::VectorXd& u,
                                                      const std::vector<CurrentPerAmpere2D>& coils,
                                                      const LinearSolverOptions& options);

// The same under the other condition on symmetry plane `plane` (Mesh2D::symmetry index;
// normal <-> parallel), linearised at a_full, the operating point as all DOFs of `dofs`
// (Assembler2D::expand of the solution). A model cut at a plane with its own condition drives
// a coil and its mirror image together with the currents the condition gives them; the other
// condition drives them the other way round, so the two sensitivities separate a mirrored
// pair's self and mutual inductance (pipeline/coil_results_axi.hpp). With nonlinear iron the
// tangent at the operating point is itself symmetric about the plane, so the response to the
// antisymmetric excitation is the share's under the other condition. Returns all-DOF vectors
// (constrained DOFs zero), one per entry.
std::vector<Eigen::VectorXd>
complementary_sensitivities_2d(const Problem2D& problem, const DofMap2D& dofs,
                               const Eigen::VectorXd& a_full, std::size_t plane,
                               const std::vector<CurrentPerAmpere2D>& coils,
                               const LinearSolverOptions& options);

} // namespace magfem
