#include "analytic/voice_coil_line_model.hpp"

#include <cmath>

#include <boost/math/tools/minima.hpp>
#include <stdexcept>

#include "core/constants.hpp"
#include "analytic/radial_l1_difference.hpp"

namespace magfem {

namespace {

// Primitive in d of atan(c / d) (the z integral of a line at horizontal offset d).
double atan_primitive(double d, double c) {
  if (c == 0) {
    return 0.0;
  }
  if (d == 0) {
    return 0.5 * c * std::log(c * c);
  }
  return d * std::atan(c / d) + 0.5 * c * std::log(c * c + d * d);
}

double acot(double x) {
  return std::atan2(1.0, x);
}

// chi acot(chi) + ln sqrt(1 + chi^2), the primitive of acot.
double acot_primitive(double chi) {
  return chi * acot(chi) + 0.5 * std::log1p(chi * chi);
}

} // namespace

// A line at (y', z') with current I along -x for y' > 0 (+x for y' < 0) gives
// B_z = mu0 I (y' - y) / (2 pi rho^2); its z' integral over [z_min, z_max] is
// atan((z_max - z) / d) + atan((z - z_min) / d), d = y' - y.
double line_model_Bz(const CoaxialCoil& coil, double current, double y, double z) {
  const double length = coil.z_max - coil.z_min;
  const double c1 = coil.z_max - z, c2 = z - coil.z_min;
  const double ni = coil.turns * current;
  if (coil.r_outer == coil.r_inner) {
    const double a = coil.r_inner;
    auto f = [&](double d) { return d == 0 ? 0.0 : std::atan(c1 / d) + std::atan(c2 / d); };
    return mu0 * ni / length / (2 * pi) * (f(a - y) + f(a + y));
  }
  const double j = ni / ((coil.r_outer - coil.r_inner) * length);
  double s = 0;
  for (double c : {c1, c2}) {
    s += atan_primitive(coil.r_outer - y, c) - atan_primitive(coil.r_inner - y, c);
    s += atan_primitive(coil.r_outer + y, c) - atan_primitive(coil.r_inner + y, c);
  }
  return mu0 * j / (2 * pi) * s;
}

double line_model_esl_sheet_current(const CoaxialCoil& coil, double current, double radius) {
  const double length = coil.z_max - coil.z_min;
  if (!(coil.r_outer > coil.r_inner && radius > 0 && length > 0)) {
    throw std::invalid_argument("line_model_esl_sheet_current: need a thick coil, radius > 0");
  }
  const double j = coil.turns * current / ((coil.r_outer - coil.r_inner) * length);
  const double f = acot_primitive(coil.r_outer / length) - acot_primitive(coil.r_inner / length);
  return j * length * f / acot(radius / length);
}

double line_model_esl_radius(const CoaxialCoil& coil, double y_max) {
  const double z = coil.z_max;
  auto error = [&](double a) {
    const double k = line_model_esl_sheet_current(coil, 1.0, a);
    const double length = coil.z_max - coil.z_min;
    const CoaxialCoil sheet{a, a, coil.z_min, coil.z_max, k * length};
    return radial_l1_difference([&](double y) { return line_model_Bz(coil, 1.0, y, z); },
                                [&](double y) { return line_model_Bz(sheet, 1.0, y, z); },
                                {coil.r_inner, coil.r_outer, a}, y_max, 1e-3 * coil.r_outer)
        .difference;
  };
  // The line model is cheap: locate a_e to Brent's limit for doubles (26 bits, ~1.5e-8).
  return boost::math::tools::brent_find_minima(error, coil.r_inner, coil.r_outer, 26).first;
}

} // namespace magfem
