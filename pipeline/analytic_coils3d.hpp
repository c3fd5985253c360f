#pragma once
// The coil results of `magfem analytic` in 3D (magnets of mu_r 1 and coils in air; no iron, no
// imaging), with the FE's summary.json and forces.csv keys:
//  - per coil: resistance and loss (sources/coil_field.hpp), and the Lorentz force and torque
//    about the origin in the field of the magnets (charge model) and of the other coils
//    (sources/, the FE's source fields). Solenoids by validation/azimuthal_current_wrench
//    (z panels graded towards the ends, where a magnet or coil across a gap makes the field
//    vary fastest), other coils by the actuator's coil rule (analytic/torque_constants.hpp);
//  - the case's force specs: `lorentz` on the named coils; a stress `sphere` or `box` as the
//    force and torque on the magnets and coils it encloses from everything outside it (charge
//    interaction between magnets; magnet-coil pairs by action = reaction);
//  - flux linkage of a coil and the coils' inductance matrix where the coaxial closed forms
//    apply: solenoids and axially magnetized cylinders on the coil's axis (mutual and self
//    inductance by Maxwell's formula, analytic/coil_closed_forms.hpp; a magnet of mu_r 1 is
//    its current sheets). Otherwise the linkage is not reported and a note says why.
#include "pipeline/run_analytic.hpp"
#include "analytic/charge_model.hpp"

namespace magfem {

// Fills run.coils, linkage_known, inductance_H, forces and appends to run.scene.notes.
void analytic_coils_3d(AnalyticRun& run, const ChargeModelOptions& field_options);

} // namespace magfem
