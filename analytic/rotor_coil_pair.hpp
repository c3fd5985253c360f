#pragma once
// The magnet-coil pair of the voice-coil paper's Fig. 5 (002_5cbab31495bf2c6b.txt): it belongs
// to the paper's spherical motor (Table 4: rotor radius 37.5 mm, stator coils 19.05 x 9.53 x
// 25.4 mm of 1050 turns, air gap 0.5 mm), so the magnet sits on the rotor, its outer face on
// the rotor sphere, and turns with the rotor about the rotor centre (the origin) in the xz
// plane, while the coil stays on the stator, coaxial with the magnet at separation angle 0,
// its near face `gap` beyond the rotor sphere. SI units, angles in radians.
#include "analytic/azimuthal_current_wrench.hpp"

namespace magfem {

struct RotorCoilPair {
  double rotor_radius = 37.5e-3;
  double gap = 0.5e-3;
  double magnet_radius = 6.35e-3, magnet_length = 12.7e-3;
  double mu0_M = 1.27; // T, along the magnet's outward axis
  // The coil in its own frame: axis z, z_min = 0 at the face towards the rotor (placed at
  // rotor_radius + gap on the z axis).
  CoaxialCoil coil{4.76e-3, 9.5e-3, 0.0, 25.4e-3, 1050};
  double current = 4.0;
};

// The coil placed on the stator (axis +z).
PlacedCoil stator_coil(const RotorCoilPair& p, const CoaxialCoil& coil_or_model);
// The magnet's equivalent surface current (a sheet of M l ampere-turns, for 1 A) at
// separation angle theta: its axis (sin theta, 0, cos theta).
PlacedCoil rotor_magnet(const RotorCoilPair& p, double theta);

// Force and torque about the rotor centre on the magnet at separation angle theta, in the
// field of `coil_model` (the exact thick coil p.coil, or an ESL / equivalent-magnet sheet given
// in the coil's frame, with `model_current` per turn).
Wrench magnet_wrench(const RotorCoilPair& p, const CoaxialCoil& coil_model, double model_current,
                     double theta, const WrenchQuadrature& q = {});

} // namespace magfem
