#include "materials/bh_curve.hpp"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <sstream>

#include "core/constants.hpp"

namespace magfem {

namespace {

// Slopes within this relative margin below mu0 are accepted: tables are printed to 4-5
// significant digits, so a saturated segment computed as mu0 * dH is often rounded just under.
constexpr double slope_rel_tol = 1e-3;
// No material's polarization J = B - mu0 H exceeds this (FeCo alloys saturate near 2.45 T).
// J rather than B: a table may run on into saturation, where B keeps growing as mu0 H.
constexpr double max_polarization_T = 3.0;
// The likely cause of an implausible table, appended to the messages.
const char* const units_hint = "B must be in T and H in A/m, as [H, B]";
// The inverse's bisection fallback stops when the update is this many ulps of the interval end.
constexpr double inverse_ulps = 4.0;
constexpr int inverse_max_iter = 200;
// A Newton step smaller than this fraction of the interval is the last one needed.
constexpr double newton_final_step = 1e-8;

std::string in_mu0(double slope) {
  std::ostringstream s;
  s.precision(4);
  s << slope / mu0 << " mu0";
  return s.str();
}

void check_sizes(const std::vector<double>& h, const std::vector<double>& b) {
  if (h.size() != b.size())
    throw BhTableError(std::min(h.size(), b.size()), "H has " + std::to_string(h.size()) +
                                                         " values but B has " +
                                                         std::to_string(b.size()));
  if (h.size() < 2)
    throw BhTableError(0, "a B-H table needs at least 2 points, got " + std::to_string(h.size()));
}

// Slope of the segment ending at row i; the first row's segment starts at the origin.
void check_slope(const std::vector<double>& h, const std::vector<double>& b, std::size_t i) {
  const double h0 = i == 0 ? 0.0 : h[i - 1];
  const double b0 = i == 0 ? 0.0 : b[i - 1];
  if (i == 0 && h[0] == 0.0)
    return; // the origin itself
  const double slope = (b[i] - b0) / (h[i] - h0);
  if (slope >= mu0 * (1.0 - slope_rel_tol))
    return;
  const bool first = i == 0 || (i == 1 && h[0] == 0.0);
  const std::string where = first               ? "initial slope B/H"
                            : i + 1 == h.size() ? "final slope dB/dH"
                                                : "slope dB/dH";
  throw BhTableError(i, where + " = " + in_mu0(slope) +
                            " is below mu0 (by more than the tolerance of 0.1 %): "
                            "non-physical, a ferromagnet has dB/dH >= mu0 (is the B column "
                            "the polarization J = B - mu0 H? " +
                            units_hint + ")");
}

// A polarization above any material's: mostly a table given as [B, H] (or B in gauss).
void check_polarization(const std::vector<double>& h, const std::vector<double>& b, std::size_t i) {
  const double j = b[i] - mu0 * h[i];
  if (j <= max_polarization_T)
    return;
  std::ostringstream s;
  s.precision(6);
  s << "B = " << b[i] << " T at H = " << h[i] << " A/m: the polarization B - mu0 H = " << j
    << " T is above " << max_polarization_T
    << " T, more than any magnetic material has (columns swapped? " << units_hint << ")";
  throw BhTableError(i, s.str());
}

void validate(const std::vector<double>& h, const std::vector<double>& b) {
  check_sizes(h, b);
  for (std::size_t i = 0; i < h.size(); ++i) {
    if (!std::isfinite(h[i]) || !std::isfinite(b[i]))
      throw BhTableError(i, "values must be finite numbers");
    if (h[i] < 0.0 || b[i] < 0.0)
      throw BhTableError(i, "negative values are not allowed (give the curve for H >= 0)");
    if (i == 0 && h[0] == 0.0 && b[0] != 0.0)
      throw BhTableError(0, "B must be 0 at H = 0 (a soft material has no remanence)");
    const double h_prev = i == 0 ? 0.0 : h[i - 1];
    const double b_prev = i == 0 ? 0.0 : b[i - 1];
    if (i > 0 || h[0] > 0.0) {
      if (!(h[i] > h_prev))
        throw BhTableError(i, std::string("H must increase strictly from row to row (rows out "
                                          "of order, or repeated? ") +
                                  units_hint + ")");
      if (!(b[i] > b_prev))
        throw BhTableError(i, std::string("B must increase strictly from row to row: the "
                                          "curve is not monotone (a branch of a hysteresis "
                                          "loop, or a typo? give the single-valued normal "
                                          "magnetization curve; ") +
                                  units_hint + ")");
    }
    check_slope(h, b, i);
  }
}

} // namespace

void check_bh_table_plausible(const std::vector<double>& h_Apm, const std::vector<double>& b_T) {
  for (std::size_t i = 0; i < std::min(h_Apm.size(), b_T.size()); ++i)
    check_polarization(h_Apm, b_T, i);
}

BhCurve::BhCurve(std::vector<double> h_Apm, std::vector<double> b_T) {
  validate(h_Apm, b_T);
  if (h_Apm.front() > 0.0) {
    h_Apm.insert(h_Apm.begin(), 0.0);
    b_T.insert(b_T.begin(), 0.0);
  }
  h_ = std::move(h_Apm);
  b_ = std::move(b_T);

  // Monotone cubic Hermite slopes (Fritsch-Carlson family, with the Fritsch-Butland weighted
  // harmonic mean at interior points): every m_k <= 3 min(neighbouring secants), which keeps
  // each cubic monotone, so there is no overshoot between table points.
  const std::size_t n = h_.size();
  std::vector<double> secant(n - 1);
  for (std::size_t k = 0; k + 1 < n; ++k)
    secant[k] = (b_[k + 1] - b_[k]) / (h_[k + 1] - h_[k]);
  slope_b_.assign(n, 0.0);
  for (std::size_t k = 1; k + 1 < n; ++k) {
    const double wl = 2 * (h_[k + 1] - h_[k]) + (h_[k] - h_[k - 1]);
    const double wr = (h_[k + 1] - h_[k]) + 2 * (h_[k] - h_[k - 1]);
    slope_b_[k] = (wl + wr) / (wl / secant[k - 1] + wr / secant[k]);
  }
  // The curve leaves the last point with slope mu0, as the extrapolation does: saturation
  // polarization is reached there, and the derivative (Newton's tangent) stays continuous.
  slope_b_[n - 1] = mu0;
  // First interval: B = m0 H + c H^3 (no H^2 term), i.e. the odd extension of the curve is
  // smooth through H = 0. That is what keeps d mu/d(H^2) and d nu/d(B^2) finite at 0.
  // It requires m0 = (3 secant_0 - m1) / 2; m1 is capped so that m0 >= mu0.
  if (n > 2)
    slope_b_[1] = std::min(slope_b_[1], 3 * secant[0] - 2 * mu0);
  slope_b_[0] = 0.5 * (3 * secant[0] - slope_b_[1]);
}

std::size_t BhCurve::interval_of_h(double h) const {
  const auto it = std::upper_bound(h_.begin(), h_.end(), h);
  return static_cast<std::size_t>(it - h_.begin()) - 1;
}

std::size_t BhCurve::interval_of_b(double b) const {
  const auto it = std::upper_bound(b_.begin(), b_.end(), b);
  return static_cast<std::size_t>(it - b_.begin()) - 1;
}

void BhCurve::hermite(std::size_t k, double h, double& b, double& dbdh) const {
  const double dh = h_[k + 1] - h_[k];
  const double t = (h - h_[k]) / dh;
  const double s = 1.0 - t;
  const double m0 = slope_b_[k] * dh, m1 = slope_b_[k + 1] * dh; // slopes per unit t
  b = (1 + 2 * t) * s * s * b_[k] + t * s * s * m0 + t * t * (3 - 2 * t) * b_[k + 1] -
      t * t * s * m1;
  const double db_dt =
      6 * t * s * (b_[k + 1] - b_[k]) + s * (1 - 3 * t) * m0 + t * (3 * t - 2) * m1;
  dbdh = db_dt / dh;
}

void BhCurve::evaluate(double h, double& b, double& dbdh) const {
  if (h >= h_.back()) {
    b = b_.back() + mu0 * (h - h_.back());
    dbdh = mu0;
    return;
  }
  hermite(interval_of_h(h), h, b, dbdh);
}

void BhCurve::invert(double b, double& h, double& dbdh) const {
  if (b >= b_.back()) {
    h = h_.back() + (b - b_.back()) / mu0;
    dbdh = mu0;
    return;
  }
  const std::size_t k = interval_of_b(b);
  double lo = h_[k], hi = h_[k + 1];
  // Start from the Hermite cubic of the inverse (slopes 1/m at the ends), which is usually
  // close; then Newton on the monotone forward cubic, falling back to bisection whenever a
  // step would leave the bracket, so it converges for any table.
  const double db = b_[k + 1] - b_[k];
  const double t = (b - b_[k]) / db, s = 1.0 - t;
  h = (1 + 2 * t) * s * s * lo + t * s * s * db / slope_b_[k] + t * t * (3 - 2 * t) * hi -
      t * t * s * db / slope_b_[k + 1];
  if (!(h > lo && h < hi))
    h = lo + t * (hi - lo);
  // Newton converges quadratically: once a step is below newton_final_step of the interval,
  // the next error is ~ (curvature factor) * step^2, far below round-off, so that step is the
  // last one. Bisection steps only stop at round-off.
  const double final_step = newton_final_step * (hi - lo);
  const double tol = inverse_ulps * DBL_EPSILON * hi;
  for (int it = 0; it < inverse_max_iter; ++it) {
    double bv = 0;
    hermite(k, h, bv, dbdh);
    const double f = bv - b;
    if (f == 0.0)
      return;
    (f > 0 ? hi : lo) = h;
    double next = h - f / dbdh;
    bool done = std::abs(next - h) <= final_step;
    if (!(next > lo && next < hi)) {
      next = 0.5 * (lo + hi);
      done = std::abs(next - h) <= tol;
    }
    h = next;
    if (done)
      break;
  }
  double bv = 0;
  hermite(k, h, bv, dbdh); // the slope at the H returned
}

void BhCurve::secant_permeability(double h, double b, double dbdh, double& mu,
                                  double& dmu_dh2) const {
  if (h < h_[1]) {
    // B = m0 H + c H^3 here, so mu = m0 + c H^2 exactly (no cancellation near H = 0).
    const double c = (slope_b_[1] - slope_b_[0]) / (3 * h_[1] * h_[1]);
    mu = slope_b_[0] + c * h * h;
    dmu_dh2 = c;
    return;
  }
  mu = b / h;
  dmu_dh2 = (dbdh * h - b) / (2 * h * h * h);
}

double BhCurve::b_of_h(double h) const {
  double b = 0, d = 0;
  evaluate(std::abs(h), b, d);
  return h < 0 ? -b : b;
}

double BhCurve::dbdh(double h) const {
  double b = 0, d = 0;
  evaluate(std::abs(h), b, d);
  return d;
}

double BhCurve::h_of_b(double b) const {
  double h = 0, d = 0;
  invert(std::abs(b), h, d);
  return b < 0 ? -h : h;
}

double BhCurve::dhdb(double b) const {
  double h = 0, d = 0;
  invert(std::abs(b), h, d);
  return 1.0 / d;
}

void BhCurve::mu_of_h2(double h2, double& mu, double& dmu_dh2) const {
  const double h = std::sqrt(std::max(h2, 0.0));
  double b = 0, d = 0;
  evaluate(h, b, d);
  secant_permeability(h, b, d, mu, dmu_dh2);
}

void BhCurve::nu_of_b2(double b2, double& nu, double& dnu_db2) const {
  // nu(b2) = 1 / mu(h2) with h = H(b); by the chain rule
  // d nu/d(b2) = -mu'(h2) nu^2 d(h2)/d(b2) and d(h2)/d(b2) = (h / b) dh/db = nu / (dB/dH).
  // Every factor is finite at b = 0, where nu = 1 / (initial slope).
  const double b = std::sqrt(std::max(b2, 0.0));
  double h = 0, d = 0, mu = 0, dmu = 0;
  invert(b, h, d);
  secant_permeability(h, b, d, mu, dmu);
  nu = 1.0 / mu;
  dnu_db2 = -dmu * nu * nu * nu / d;
}

double BhCurve::peak_permeability() const {
  double peak = initial_slope();
  for (std::size_t k = 1; k < h_.size(); ++k)
    peak = std::max(peak, b_[k] / h_[k]);
  return peak;
}

double BhCurve::energy_density(double b) const {
  static constexpr std::array<double, 8> x = {
      -0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
      0.1834346424956498,  0.5255324099163290,  0.7966664774136267,  0.9602898564975363};
  static constexpr std::array<double, 8> w = {
      0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
      0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
  const auto piece = [&](double lo, double hi) {
    double sum = 0;
    for (int i = 0; i < 8; ++i)
      sum += w[i] * h_of_b(lo + 0.5 * (hi - lo) * (x[i] + 1));
    return 0.5 * (hi - lo) * sum;
  };
  b = std::abs(b);
  double sum = 0, lo = 0;
  for (const double k : b_) {
    if (k <= lo)
      continue;
    if (k >= b)
      break;
    sum += piece(lo, k);
    lo = k;
  }
  return sum + piece(lo, b);
}

} // namespace magfem
