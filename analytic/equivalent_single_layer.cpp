#include "analytic/equivalent_single_layer.hpp"

#include <cmath>

#include <boost/math/tools/minima.hpp>

#include "core/constants.hpp"
#include "analytic/coaxial_coil_field.hpp"
#include "analytic/radial_l1_difference.hpp"
#include "analytic/voice_coil_line_model.hpp"

namespace magfem {

CoaxialCoil EquivalentSingleLayer::as_sheet(const CoaxialCoil& original) const {
  return {radius, radius, original.z_min, original.z_max,
          sheet_current * (original.z_max - original.z_min)};
}

CoaxialCoil EquivalentMagnet::as_sheet() const {
  return {radius, radius, z_min, z_max, mu0_M / mu0 * (z_max - z_min)};
}

EquivalentSingleLayer esl_line_model_at(const CoaxialCoil& coil, double current, double radius) {
  return {radius, line_model_esl_sheet_current(coil, current, radius)};
}

EquivalentSingleLayer esl_line_model(const CoaxialCoil& coil, double current, double y_max) {
  return esl_line_model_at(coil, current, line_model_esl_radius(coil, y_max));
}

EquivalentSingleLayer esl_exact_at(const CoaxialCoil& coil, double current, double radius) {
  const double length = coil.z_max - coil.z_min;
  const double h = coaxial_coil_axial_H(coil, current, coil.z_max);
  return {radius, 2 * h * std::hypot(radius, length) / length};
}

EquivalentSingleLayer esl_exact(const CoaxialCoil& coil, double current, double y_max) {
  const CoaxialCoilField exact(coil, current);
  const double z = coil.z_max;
  auto error = [&](double a) {
    const EquivalentSingleLayer e = esl_exact_at(coil, current, a);
    const CoaxialCoilField sheet(e.as_sheet(coil), 1.0);
    return radial_l1_difference([&](double y) { return exact.Bz(y, z); },
                                [&](double y) { return sheet.Bz(y, z); },
                                {coil.r_inner, coil.r_outer, a}, y_max, 1e-3 * coil.r_outer)
        .difference;
  };
  // 20 bits: a_e to ~1e-6 relative, far below the differences the paper's table shows, and
  // each evaluation of the error is an integral of exact fields.
  const auto best = boost::math::tools::brent_find_minima(error, coil.r_inner, coil.r_outer, 20);
  return esl_exact_at(coil, current, best.first);
}

EquivalentMagnet equivalent_magnet(const CoaxialCoil& source, double current, double radius) {
  const double length = source.z_max - source.z_min;
  const double b = mu0 * coaxial_coil_axial_H(source, current, source.z_max);
  return {radius, source.z_min, source.z_max, 2 * std::sqrt(1 + std::pow(radius / length, 2)) * b};
}

} // namespace magfem
