#pragma once
// The coils of an axisymmetric case (regions with turns and current): flux linkage, the
// differential inductance matrix and the apparent inductance, for the whole device whether or
// not the model is cut at the symmetry plane z = 0 (mesh/symmetry_plane2d.hpp).
//
// Without a plane, or for a coil the plane cuts (its own mirror image), the share's field is
// the whole device's and the sensitivity of the solution to a coil's current gives a column of
// the matrix. A coil whose mirror image is another coil (a Helmholtz pair, the two coils of an
// actuator either side of z = 0) is meshed on one side only, and the share drives both: with
// the plane's sign s (+1 field: normal, -1 field: parallel) a current I in the meshed coil A
// (N_A turns) stands for I_B = t I in its image B, t = s N_A / N_B. So
//   - B's linkage is s (N_B / N_A) times A's (the potential at B is s times that at A's image
//     point); the energy, forces and torques come out as the whole device's as before;
//   - the share's sensitivity under the plane's own condition links psi_s = L_AA + t L_AB,
//     under the other condition (complementary_sensitivities_2d) psi_a = L_AA - t L_AB, so
//     L_AA = (psi_s + psi_a) / 2 and L_AB = (psi_s - psi_a) / (2 t): one extra solve per pair
//     on the same mesh, at the same operating point (valid with nonlinear iron: its tangent
//     at the symmetric operating point is itself symmetric).
// Entries between two coils of mirrored pairs are the ones that need the complementary solve;
// between a pair and a coil on the plane the antisymmetric part links nothing.
#include <vector>

#include <Eigen/Core>

namespace magfem {

struct Run2D;
class Assembler2D;

// Fills run.coil_results (spec order) and run.inductance_H (rows and columns in that order) from
// the converged free-DOF solution u of `assembler`. No-op for a planar case.
void compute_coil_results_axi(Run2D& run, const Assembler2D& assembler, const Eigen::VectorXd& u);

} // namespace magfem
