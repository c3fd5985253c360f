#pragma once
// The equivalent single layer (ESL) of a multilayer voice coil (002_5cbab31495bf2c6b.txt,
// sec. II.A) and the equivalent permanent magnet (sec. II.B): a current sheet of the coil's
// length at an effective radius a_e with an effective sheet current (the paper's J_e d_w, A/m).
// Condition II fixes the sheet current so that the field at the centre of the end face is the
// coil's; condition I picks a_e to minimize the L1 difference of B_z over the end face.
//
// The paper applies both conditions in its 2D line model (voice_coil_line_model.hpp); they
// are given here also with the exact fields. The equivalent magnet of eq. 12,
// mu0 M_e = 2 sqrt(1 + (a_e / l)^2) B(0, 0, l / 2), is a cylinder of radius a_e magnetized along
// its axis; with mu_r = 1 its B is exactly that of the sheet K = M_e, so it is the ESL whose
// condition II is met by the exact 3D end-centre field (and, with B(0, 0, l / 2) taken from
// the ESL itself as the paper's "computed from (8)" says, M_e is the ESL's own sheet current).
// SI units; the coil's ampere-turns spread uniformly over its cross-section.
#include "analytic/coil_closed_forms.hpp"

namespace magfem {

struct EquivalentSingleLayer {
  double radius = 0;        // a_e, m
  double sheet_current = 0; // J_e d_w, A/m (for the coil's current)
  // The sheet as a coaxial coil of the original's length (turns: sheet_current * length per
  // ampere, so use it with current 1 A).
  CoaxialCoil as_sheet(const CoaxialCoil& original) const;
};

// The paper's ESL: eqs. 5 and 6 in its 2D line model. y_max as in line_model_esl_radius
// (<= 0: the whole end face).
EquivalentSingleLayer esl_line_model(const CoaxialCoil& coil, double current, double y_max);
// Eq. 6 at a given radius (the sheet current of Table 1 from its printed a_e).
EquivalentSingleLayer esl_line_model_at(const CoaxialCoil& coil, double current, double radius);

// Condition II with the exact field: K = 2 H_z(0, z_max) sqrt(a_e^2 + l^2) / l, H_z from the
// closed form of the on-axis field (coaxial_coil_axial_H).
EquivalentSingleLayer esl_exact_at(const CoaxialCoil& coil, double current, double radius);
// Conditions I and II with the exact fields (golden-section search over a_e in
// (r_inner, r_outer) to 1e-6 of r_outer; each trial integrates over the end face).
EquivalentSingleLayer esl_exact(const CoaxialCoil& coil, double current, double y_max);

struct EquivalentMagnet {
  double radius = 0, z_min = 0, z_max = 0;
  double mu0_M = 0; // T
  // The magnet's equivalent surface current as a sheet (turns = M l, for a current of 1 A).
  CoaxialCoil as_sheet() const;
};
// Eq. 12 with B(0, 0, l / 2) the on-axis field at the centre of the end face of `source` (the
// original coil, or the ESL sheet), exact.
EquivalentMagnet equivalent_magnet(const CoaxialCoil& source, double current, double radius);

} // namespace magfem
