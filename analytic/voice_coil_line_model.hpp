#pragma once
// The voice-coil paper's own two-dimensional model (002_5cbab31495bf2c6b.txt, eqs. 3-6): the
// meridian cross-section of a coil (r_inner <= y <= r_outer, |z| <= l/2, mirrored to y < 0) is
// filled with straight line currents along x, infinite in x, opposite on the two halves, each
// with the 2D field mu0 I / (2 pi rho). It is not the field of the coil (whose loops close:
// the exact field is thick_coil_field.hpp); the paper derives its equivalent single layer
// (ESL) and reports Table 1's errors with it. B_z in closed form, SI units, +z for positive
// current (the direction a coaxial coil with positive current gives on its axis).
#include "analytic/coil_closed_forms.hpp"

namespace magfem {

// B_z (T) at (y, z) of the cross-section of `coil` filled with the current density
// J = turns * current / ((r_outer - r_inner) * length) (eq. 4a integrated in closed form:
// the z integral of each line is a sum of arctangents, the y integral
// d atan(c / d) + (c / 2) ln(c^2 + d^2)). A sheet (r_inner == r_outer) is eq. 4b with the
// sheet current turns * current / length.
double line_model_Bz(const CoaxialCoil& coil, double current, double y, double z);

// Eq. 6 (condition II): the ESL sheet current (A/m) at radius a_e that gives the coil's B_z at
// the centre of its end face (y = 0, z = z_max): K_e acot(a_e / l) = J l [chi acot chi
// + ln sqrt(1 + chi^2)] between chi_i = r_inner / l and chi_o = r_outer / l.
double line_model_esl_sheet_current(const CoaxialCoil& coil, double current, double radius);

// Condition I (eq. 5): the ESL radius in (r_inner, r_outer) that minimizes
// int_0^y_max |B_z,ML - B_z,ESL| dy on the end face z = z_max, with the eq. 6 sheet current at
// every trial radius (the paper solves (5) and (6) together). y_max <= 0 means the whole end
// face (0 .. infinity). Golden-section search to 1e-9 of r_outer.
double line_model_esl_radius(const CoaxialCoil& coil, double y_max);

} // namespace magfem
