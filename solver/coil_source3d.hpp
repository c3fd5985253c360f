#pragma once
// Coils in the 3D scalar-potential formulation: the two-potential method.
//
// Everywhere H = H_0 - grad u with one continuous unknown u:
//   - reduced regions (air, magnets, the coils themselves, the open-boundary shell):
//     H_0 = H_s, the coils' Biot-Savart field, so curl H = J holds exactly;
//   - total regions (soft iron, which carries no current): H_0 = -grad(I_h Phi_s), the
//     discrete gradient of the interpolated source potential Phi_s (H_s = -grad Phi_s there),
//     so that u + I_h Phi_s is the total potential psi and H = -grad psi.
// Why: with a plain reduced potential the field in iron is the small difference of two large
// ones (H_s - grad u) and its discretisation error is amplified by mu_r (the cancellation
// error). Here the iron sees no H_s at all; the only approximation is the interpolation of
// Phi_s on the iron surface, whose error (a small potential jump) is absorbed on the air side
// because highly permeable iron is nearly equipotential.
//
// Phi_s is integrated along mesh edges (line integrals of H_s) inside each connected iron
// component. A component whose loops link a coil current (a closed core around a coil) has
// no single-valued Phi_s; it stays reduced (with a warning), which is correct but carries the
// cancellation error.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "solver/dof_map3d.hpp"
#include "solver/problem3d.hpp"
#include "solver/source_field3d.hpp"
#include "solver/source_field_table3d.hpp"

namespace magfem {

struct CoilSource3D {
  const SourceField3D* field = nullptr;
  std::vector<unsigned char> total;               // per tet: 1 = total-potential region
  std::vector<Eigen::VectorXd> offset_per_ampere; // per coil: Phi_s at every DOF (A per A)
  Eigen::VectorXd offset;                         // sum of current * offset_per_ampere
  SourceFieldTable3D table;                       // H_s at the rule points of every tet
  std::vector<std::string> warnings;

  bool active() const { return field != nullptr && field->n_coils() > 0; }
  bool is_total(std::size_t tet) const { return !total.empty() && total[tet] != 0; }
};

// Soft (non-magnet, permeable) parts become total regions; their Phi_s is integrated per
// connected component.
// `share` (or `tets`, when given): the tets whose source-table entries this process computes
// (SourceFieldTable3D); the Phi_s of the total regions is computed whole on every process.
CoilSource3D make_coil_source_3d(const Problem3D& problem, const DofMap3D& dofs,
                                 const SourceField3D& field, ElementRange share = {},
                                 const std::vector<std::size_t>* tets = nullptr);

} // namespace magfem
