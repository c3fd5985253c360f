#pragma once
// Flux linkage and inductance of 3D coils from the solved field, by reciprocity:
//   lambda_k = integral over all space of B . h_k,
// h_k being coil k's free-space field per ampere (curl h_k = j_k): since
// integral A . j_k = integral A . curl h_k = integral B . h_k (the surface term vanishes at
// infinity), this is the coil's flux linkage with the whole field (magnets, iron, all coils)
// without a vector potential. The open-boundary shell stands for the exterior, so the
// integral is over all space. The incremental inductance L_ij = d lambda_i / d I_j uses the
// field's small-signal response to a unit current in coil j (current_sensitivity3d.hpp):
// dB = D (dH), D the tangent permeability at the operating point.
#include <vector>

#include <Eigen/Core>

#include "postproc/field3d.hpp"

namespace magfem {

// lambda_k in Wb (turns included) for every coil of the field's problem.
std::vector<double> flux_linkages_3d(const Field3D& field);

// L_ij in H. dphi_full[j]: the full-DOF sensitivity du/dI_j.
Eigen::MatrixXd inductance_matrix_3d(const Field3D& field,
                                     const std::vector<Eigen::VectorXd>& dphi_full);

} // namespace magfem
