#pragma once
// `magfem analytic` on an axisymmetric case (dimension: axi), exact for what it accepts:
//  - coils (rectangles with turns and current): thick coils, the loops filling the winding by
//    elliptic integrals (analytic/coaxial_coil_field.hpp);
//  - axially magnetized magnets of mu_r 1 (rectangles: cylinders and rings): the equivalent
//    current sheets, M on the outer side and -M on the inner side (K = M x n; the end faces
//    carry none), which give B exactly everywhere, inside the magnet too.
// F_z on every part by the mutual-inductance gradient of each pair of sources
// (analytic/coil_closed_forms.hpp; the Lorentz force of the sheets in the other sources'
// field where two sources touch), flux linkages and the coils' inductance matrix by mutual and
// self inductances (Maxwell's formula over the cross-sections).
// Refused with exit 2 naming the region: iron (a region other than a magnet with mu_r != 1 or
// a nonlinear material), magnets not magnetized along the axis, sources that are not unrotated
// rectangles or that later parts partly cover, and a boundary other than open.
#include "pipeline/run_analytic.hpp"

namespace magfem {

// Fills run.probes, forces, coils, inductance_H, sources, n_points and scene.notes.
void run_axi_analytic(AnalyticRun& run);

} // namespace magfem
