#include "analytic/coaxial_coil_field.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/constants.hpp"
#include "core/gauss_legendre.hpp"

namespace magfem {

CoaxialCoilField::CoaxialCoilField(const CoaxialCoil& coil, double current)
    : coil_(coil), current_(current) {
  if (!(coil.r_inner >= 0 && coil.r_outer >= coil.r_inner && coil.z_max > coil.z_min &&
        coil.r_outer > 0)) {
    throw std::invalid_argument("CoaxialCoilField: need 0 <= r_inner <= r_outer, r_outer > 0, "
                                "z_max > z_min");
  }
  if (coil.r_outer > coil.r_inner) {
    const Solenoid s{coil.r_inner, coil.r_outer, coil.z_max - coil.z_min};
    bundle_ = std::make_shared<AxisymmetricBundle>(s, coil.turns * current, CoilFieldOptions{});
  }
}

MeridianField CoaxialCoilField::H(double rho, double z) const {
  if (!bundle_) {
    return sheet_H(rho, z);
  }
  return bundle_->H(rho, z - 0.5 * (coil_.z_min + coil_.z_max));
}

double CoaxialCoilField::Bz(double rho, double z) const {
  return mu0 * H(rho, z).h_z;
}

// The loop field falls off as 1 / distance from its filament, so panels shrink geometrically
// (ratio 1/4) from the far ends towards the field point's height clamped to the sheet, down to
// a size well below the distance to the sheet; 10-point Gauss per panel.
MeridianField CoaxialCoilField::sheet_H(double rho, double z) const {
  const double a = coil_.r_inner, length = coil_.z_max - coil_.z_min;
  const double k = coil_.turns * current_ / length; // A/m
  const double zc = std::clamp(z, coil_.z_min, coil_.z_max);
  const double finest = std::max(1e-3 * std::abs(rho - a), 1e-12 * length);
  static const QuadratureRule g = gauss_legendre(10);
  MeridianField out;
  auto panel = [&](double lo, double hi) {
    const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
    for (std::size_t i = 0; i < g.x.size(); ++i) {
      const MeridianField f = loop_field(a, mid + half * g.x[i], k, rho, z);
      out.h_rho += half * g.w[i] * f.h_rho;
      out.h_z += half * g.w[i] * f.h_z;
    }
  };
  for (const double end : {coil_.z_min, coil_.z_max}) {
    double far = end;
    while (std::abs(far - zc) > finest) {
      const double cut = zc + 0.25 * (far - zc);
      panel(std::min(cut, far), std::max(cut, far));
      far = cut;
    }
    if (far != zc) {
      panel(std::min(zc, far), std::max(zc, far));
    }
  }
  return out;
}

} // namespace magfem
