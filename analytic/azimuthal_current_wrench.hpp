#pragma once
// Force and torque on an azimuthal current distribution placed anywhere in space: a coaxial
// coil's volume current, or a current sheet (a voice-coil ESL, or a cylinder magnet of mu_r 1
// magnetized along its axis, whose equivalent surface current K = M x n is the sheet M on its
// side and nothing on its end faces). The Lorentz force int J x B dV in a field B(x) of the
// other sources; the voice-coil paper's eq. 2 (002_5cbab31495bf2c6b.txt). SI units.
#include <functional>

#include <Eigen/Core>

#include "analytic/coaxial_coil_field.hpp"

namespace magfem {

// A coaxial coil at `origin` with its axis along the unit vector `axis` (its z_min, z_max
// measured along the axis from the origin); positive current circulates right-handed about
// the axis.
struct PlacedCoil {
  CoaxialCoil coil;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
};

// B (T) of `field` (built for placed.coil) at the global point x.
Eigen::Vector3d placed_coil_B(const PlacedCoil& placed, const CoaxialCoilField& field,
                              const Eigen::Vector3d& x);

struct Wrench {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();  // N
  Eigen::Vector3d torque = Eigen::Vector3d::Zero(); // N m, about the pivot
};

struct WrenchQuadrature {
  int n_phi = 96;       // trapezoid points in phi (spectral for the smooth periodic integrand)
  int gauss = 6;        // Gauss points per panel in z and rho
  double finest = 1e-4; // z panels halve towards both ends down to this length (m): the
                        // field varies on the scale of the gap to the nearest other source
  int rho_panels = 2;   // radial panels (thick coils)
};

// Force and torque about `pivot` on `target` carrying `current` per turn in the field B.
Wrench azimuthal_current_wrench(const PlacedCoil& target, double current,
                                const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& B,
                                const Eigen::Vector3d& pivot, const WrenchQuadrature& q = {});

} // namespace magfem
