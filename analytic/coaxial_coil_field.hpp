#pragma once
// The exact field of a coaxial coil (coil_closed_forms.hpp's CoaxialCoil): the circular loops
// filling its cross-section, each by the elliptic-integral loop field (sources/loop_field.hpp).
// A thick coil goes through sources/axisymmetric_bundle (its tested quadratures and zonal
// expansions, not a second copy); a current sheet (r_inner == r_outer: the voice-coil paper's
// equivalent single layer, and a uniformly magnetized cylinder of mu_r 1 with sheet current
// M per metre) integrates the loop field over its length on panels graded towards the field
// point's height. SI units, H in A/m; mu0 H = B everywhere outside magnets.
#include <memory>

#include "sources/axisymmetric_bundle.hpp"
#include "analytic/coil_closed_forms.hpp"

namespace magfem {

class CoaxialCoilField {
public:
  // `current` per turn (A).
  CoaxialCoilField(const CoaxialCoil& coil, double current);

  // H (A/m) at meridian point (rho >= 0, z). On a sheet itself (rho = radius, inside its
  // length) H_z is the mean of the two sides.
  MeridianField H(double rho, double z) const;
  // mu0 H_z, the paper's B_z.
  double Bz(double rho, double z) const;

  const CoaxialCoil& coil() const { return coil_; }

private:
  MeridianField sheet_H(double rho, double z) const;
  CoaxialCoil coil_;
  double current_;
  std::shared_ptr<const AxisymmetricBundle> bundle_; // thick coils only
};

} // namespace magfem
