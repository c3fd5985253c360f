// BhCurve: interpolation, derivatives, inverse, extrapolation and table validation.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "core/constants.hpp"
#include "materials/bh_curve.hpp"
#include "materials/material_library.hpp"

using magfem::BhCurve;
using magfem::BhTableError;
using magfem::mu0;

namespace {

// The soft-iron example of the case-file documentation (origin given explicitly).
BhCurve example_curve() {
  return BhCurve({0, 100, 300, 1000, 10000}, {0, 0.5, 1.2, 1.5, 1.9});
}

std::vector<BhCurve> all_curves() {
  std::vector<BhCurve> out{example_curve()};
  // A table without the origin, with a steep first segment and a 2-point table.
  out.emplace_back(std::vector<double>{50, 200, 2000, 50000},
                   std::vector<double>{0.4, 1.3, 1.7, 2.1});
  out.emplace_back(std::vector<double>{0, 1000}, std::vector<double>{0, 1.0});
  const auto& lib = magfem::MaterialLibrary::bundled();
  for (const auto& name : lib.names())
    if (lib.find(name)->curve)
      out.push_back(*lib.find(name)->curve);
  return out;
}

double central_difference(double (BhCurve::*f)(double) const, const BhCurve& c, double x,
                          double d) {
  return ((c.*f)(x + d) - (c.*f)(x - d)) / (2 * d);
}

// Index of the row a BhTableError names, or -1 if none was thrown.
long bad_row(const std::vector<double>& h, const std::vector<double>& b) {
  try {
    BhCurve c(h, b);
  } catch (const BhTableError& e) {
    return static_cast<long>(e.row());
  }
  return -1;
}

} // namespace

TEST(BhCurve, InterpolatesTheTablePointsAndInsertsTheOrigin) {
  const BhCurve c({100, 300}, {0.5, 1.2});
  ASSERT_EQ(c.h_table().size(), 3u);
  EXPECT_EQ(c.h_table()[0], 0.0);
  EXPECT_EQ(c.b_of_h(0.0), 0.0);
  EXPECT_NEAR(c.b_of_h(100), 0.5, 1e-15);
  EXPECT_NEAR(c.b_of_h(300), 1.2, 1e-15);
}

TEST(BhCurve, DerivativeMatchesCentralDifferences) {
  for (const auto& c : all_curves()) {
    const auto& h = c.h_table();
    const auto& b = c.b_table();
    for (std::size_t k = 0; k + 1 < h.size(); ++k) {
      const double dh = h[k + 1] - h[k];
      const double secant = (b[k + 1] - b[k]) / dh;
      const double d = 1e-4 * dh;
      // Central-difference error of a cubic: p''' d^2 / 6 with |p'''| <= 48 secant / dh^2
      // (all Hermite slopes are <= 3 secants), plus round-off eps |B| / d.
      const double tol = 8 * secant * (d / dh) * (d / dh) + 4 * DBL_EPSILON * b[k + 1] / d;
      for (double t : {0.2, 0.5, 0.8}) {
        const double x = h[k] + t * dh;
        EXPECT_NEAR(c.dbdh(x), central_difference(&BhCurve::b_of_h, c, x, d), tol)
            << "interval " << k << " t " << t;
      }
    }
  }
}

TEST(BhCurve, InverseDerivativeMatchesCentralDifferences) {
  for (const auto& c : all_curves()) {
    const auto& b = c.b_table();
    for (std::size_t k = 0; k + 1 < b.size(); ++k) {
      const double db = b[k + 1] - b[k];
      const double d = 1e-5 * db;
      for (double t : {0.2, 0.5, 0.8}) {
        const double x = b[k] + t * db;
        // H(B) is the inverse of a cubic: truncation (d/db)^2 = 1e-10 times its curvature
        // factor, which stays below 1e3 for these tables (slopes within an interval differ
        // by less than 30x); 1e-7 relative bounds it with room for round-off.
        const double fd = central_difference(&BhCurve::h_of_b, c, x, d);
        EXPECT_NEAR(c.dhdb(x), fd, 1e-7 * fd) << "interval " << k << " t " << t;
      }
    }
  }
}

TEST(BhCurve, IsMonotoneWithoutOvershootInBothDirections) {
  for (const auto& c : all_curves()) {
    const auto& h = c.h_table();
    const auto& b = c.b_table();
    for (std::size_t k = 0; k + 1 < h.size(); ++k) {
      double prev_b = b[k];
      double prev_h = h[k];
      for (int i = 1; i <= 400; ++i) {
        const double x = h[k] + (h[k + 1] - h[k]) * i / 400.0;
        const double y = c.b_of_h(x);
        EXPECT_GT(y, prev_b) << "B(H) not increasing in interval " << k;
        EXPECT_LE(y, b[k + 1] * (1 + 1e-15)) << "overshoot in interval " << k;
        EXPECT_GT(c.dbdh(x), 0.0);
        prev_b = y;
        const double bb = b[k] + (b[k + 1] - b[k]) * i / 400.0;
        const double hh = c.h_of_b(bb);
        EXPECT_GT(hh, prev_h) << "H(B) not increasing in interval " << k;
        EXPECT_LE(hh, h[k + 1] * (1 + 1e-15)) << "overshoot of H(B) in interval " << k;
        prev_h = hh;
      }
    }
  }
}

TEST(BhCurve, InverseRoundTrip) {
  for (const auto& c : all_curves()) {
    const double h_max = 3 * c.h_table().back();
    for (int i = 0; i <= 2000; ++i) {
      // Logarithmic sampling covers the initial region, the knee and the extrapolation.
      const double h = i == 0 ? 0.0 : h_max * std::pow(10.0, -6.0 * (2000 - i) / 2000.0);
      // The inverse is converged to round-off (its last Newton step is < 1e-8 of the
      // interval, leaving ~1e-16 * curvature); conditioning adds eps * B / (dB/dH), at most
      // ~30 eps * H for these tables. Measured: 1e-14; 1e-13 relative covers both.
      EXPECT_NEAR(c.h_of_b(c.b_of_h(h)), h, 1e-13 * c.h_table().back() + 1e-13 * h);
    }
  }
}

TEST(BhCurve, OddExtensionToNegativeArguments) {
  const auto c = example_curve();
  EXPECT_EQ(c.b_of_h(-250.0), -c.b_of_h(250.0));
  EXPECT_EQ(c.dbdh(-250.0), c.dbdh(250.0));
  EXPECT_EQ(c.h_of_b(-1.3), -c.h_of_b(1.3));
}

TEST(BhCurve, ExtrapolatesWithSlopeExactlyMu0) {
  for (const auto& c : all_curves()) {
    const double hl = c.h_table().back(), bl = c.b_table().back();
    for (double f : {1.0, 1.5, 10.0}) {
      const double h = f * hl;
      EXPECT_DOUBLE_EQ(c.b_of_h(h), bl + mu0 * (h - hl));
      EXPECT_EQ(c.dbdh(h), mu0);
      EXPECT_DOUBLE_EQ(c.dhdb(c.b_of_h(h)), 1.0 / mu0);
    }
    // The interpolant meets the extrapolation with the same slope (C1 for Newton): a step d
    // to the left changes the slope by at most |B''| d <= 24 secant d / dh (Hermite bound).
    const auto& h = c.h_table();
    const auto& b = c.b_table();
    const std::size_t n = h.size();
    const double dh = h[n - 1] - h[n - 2];
    const double secant = (b[n - 1] - b[n - 2]) / dh;
    const double d = 1e-9 * dh;
    EXPECT_NEAR(c.dbdh(hl - d), mu0, 24 * secant * d / dh);
  }
}

namespace {

// Sample points of a squared-magnitude form: inside the first interval, at the midpoint of
// every other interval and beyond the table, each with the width of the argument range it
// sits in (in squared units), the scale on which the derivative varies.
struct SquaredSample {
  double x;     // |H| or |B|
  double width; // of its interval, in x^2
};

std::vector<SquaredSample> squared_samples(const std::vector<double>& t) {
  std::vector<SquaredSample> out{{1e-3 * t[1], t[1] * t[1]}, {0.5 * t[1], t[1] * t[1]}};
  for (std::size_t k = 1; k + 1 < t.size(); ++k)
    out.push_back({0.5 * (t[k] + t[k + 1]), t[k + 1] * t[k + 1] - t[k] * t[k]});
  out.push_back({1.5 * t.back(), t.back() * t.back()});
  return out;
}

// Central difference of a squared form f(x2) with step d = 1e-4 of the sample's width (or of
// x2 near 0). The truncation error is (d / width)^2 / 6 = 1.7e-9 times a curvature factor
// (third derivative times width^2 over the derivative's natural scale |f| / width), which is
// below ~30 for a piecewise cubic whose slopes stay within a factor 30 in one interval;
// round-off adds 4 eps |f| / d. Measured: at most 1.5e-8 of the scale. The tolerance is
// 1e-7 of |f'| + |f| / width (the latter matters where f' changes sign).
template <class Form>
void expect_derivative_matches(const Form& form, const SquaredSample& s, const char* what) {
  const double x2 = s.x * s.x;
  const double d = 1e-4 * std::min(s.width, x2); // x2 - d stays positive
  double f = 0, df = 0, fp = 0, fm = 0, unused = 0;
  form(x2, f, df);
  form(x2 + d, fp, unused);
  form(x2 - d, fm, unused);
  const double scale = std::abs(df) + std::abs(f) / s.width;
  EXPECT_NEAR(df, (fp - fm) / (2 * d), 1e-7 * scale + 4 * DBL_EPSILON * std::abs(f) / d)
      << what << " at " << s.x;
}

} // namespace

TEST(BhCurve, PermeabilityFormDerivativeMatchesFiniteDifferences) {
  for (const auto& c : all_curves()) {
    for (const auto& s : squared_samples(c.h_table())) {
      double mu = 0, dmu = 0;
      c.mu_of_h2(s.x * s.x, mu, dmu);
      EXPECT_NEAR(mu, c.b_of_h(s.x) / s.x, 1e-14 * mu);
      expect_derivative_matches([&c](double h2, double& m, double& dm) { c.mu_of_h2(h2, m, dm); },
                                s, "mu(H^2)");
    }
  }
}

TEST(BhCurve, ReluctivityFormDerivativeMatchesFiniteDifferences) {
  for (const auto& c : all_curves()) {
    auto samples = squared_samples(c.b_table());
    samples.push_back({2.5, 2.5 * 2.5}); // deep saturation
    for (const auto& s : samples) {
      double nu = 0, dnu = 0;
      c.nu_of_b2(s.x * s.x, nu, dnu);
      EXPECT_NEAR(nu, c.h_of_b(s.x) / s.x, 1e-12 * nu);
      expect_derivative_matches([&c](double b2, double& n, double& dn) { c.nu_of_b2(b2, n, dn); },
                                s, "nu(B^2)");
    }
  }
}
TEST(BhCurve, SquaredFormsAreFiniteAndContinuousAtZero) {
  for (const auto& c : all_curves()) {
    double nu0v = 0, dnu0 = 0, nu1 = 0, dnu1 = 0;
    c.nu_of_b2(0.0, nu0v, dnu0);
    EXPECT_DOUBLE_EQ(nu0v, 1.0 / c.initial_slope());
    EXPECT_TRUE(std::isfinite(dnu0));
    // The curve is B = m0 H + c H^3 near 0, so nu(b2) is smooth in b2: a forward difference
    // with step 1e-8 T^2 has relative error ~ step / b1^2 < 1e-5 for first points >= 0.03 T.
    const double step = 1e-8;
    c.nu_of_b2(step, nu1, dnu1);
    EXPECT_NEAR(dnu0, (nu1 - nu0v) / step, 1e-5 * std::abs(dnu0) + 1e-3 * nu0v * step);
    EXPECT_NEAR(dnu1, dnu0, 1e-5 * std::abs(dnu0) + 1e-12);
    double mu = 0, dmu = 0;
    c.mu_of_h2(0.0, mu, dmu);
    EXPECT_DOUBLE_EQ(mu, c.initial_slope());
    EXPECT_GE(mu, mu0);
    EXPECT_TRUE(std::isfinite(dmu));
  }
}

TEST(BhCurve, RejectsBadTablesNamingTheRow) {
  EXPECT_EQ(bad_row({0, 100, 200}, {0, 1}), 2);                  // sizes differ
  EXPECT_EQ(bad_row({100}, {1.0}), 0);                           // < 2 points
  EXPECT_EQ(bad_row({0, 100, 100, 300}, {0, 0.5, 0.6, 1.0}), 2); // H not increasing
  EXPECT_EQ(bad_row({0, 100, 200, 300}, {0, 0.5, 1.0, 0.9}), 3); // B not increasing
  EXPECT_EQ(bad_row({0, -100, 200}, {0, 0.5, 1.0}), 1);          // negative H
  EXPECT_EQ(bad_row({10, 100, 200}, {-0.1, 0.5, 1.0}), 0);       // negative B
  EXPECT_EQ(bad_row({0, 100, 1e6}, {0, 1.0, 1.2}), 2);           // final slope < mu0
  EXPECT_EQ(bad_row({1000, 2000}, {1e-4, 1.0}), 0);              // initial B/H < mu0
  EXPECT_EQ(bad_row({0, 1000, 2000}, {0, 1e-4, 1.0}), 1);        // same, origin given
  EXPECT_EQ(bad_row({0, 100, 200}, {0.1, 0.5, 1.0}), 0);         // remanence at H = 0
  EXPECT_EQ(bad_row({0, 100, 300, 1000, 10000}, {0, 0.5, 1.2, 1.5, 1.9}), -1);
  EXPECT_THROW(BhCurve({0, 100}, {0, 1, 2}), std::invalid_argument);
}

TEST(BhCurve, MessageSaysWhatIsWrong) {
  try {
    BhCurve c({0, 100, 1e6}, {0, 1.0, 1.2});
    FAIL();
  } catch (const BhTableError& e) {
    EXPECT_NE(std::string(e.what()).find("row 2"), std::string::npos) << e.what();
    EXPECT_NE(e.reason().find("final slope"), std::string::npos) << e.reason();
    EXPECT_NE(e.reason().find("mu0"), std::string::npos) << e.reason();
  }
}

TEST(BhCurve, NewtonTangentOfTheSquaredFormsIsTheCurveSlope) {
  // The solver's tangent along B is nu + 2 b2 nu'(b2) = d|H|/d|B|, and along H
  // mu + 2 h2 mu'(h2) = d|B|/d|H|: both must equal the curve's own derivative. These are
  // identities, so only round-off separates them: a few ulps amplified by the ratio of
  // absolute to differential permeability (< 30 here); measured 5e-15, allowed 1e-13.
  for (const auto& c : all_curves()) {
    for (int i = 0; i <= 400; ++i) {
      const double b = 2.6 * i / 400.0;
      double nu = 0, dnu = 0;
      c.nu_of_b2(b * b, nu, dnu);
      EXPECT_NEAR(nu + 2 * b * b * dnu, c.dhdb(b), 1e-13 * c.dhdb(b)) << "B = " << b;
      const double h = c.h_of_b(b);
      double mu = 0, dmu = 0;
      c.mu_of_h2(h * h, mu, dmu);
      EXPECT_NEAR(mu + 2 * h * h * dmu, c.dbdh(h), 1e-13 * c.dbdh(h)) << "H = " << h;
      EXPECT_GT(nu + 2 * b * b * dnu, 0.0); // the Newton tangent stays positive definite
    }
  }
}

TEST(BhCurve, EnergyDensityIsTheIntegralOfHAcrossTableKnotsAndTheExtrapolation) {
  // integral_0^b h db' against a fine composite trapezoid rule (2e5 panels; its own error is
  // largest at the knee, measured difference 1.4e-7 at 1.9 T) through the table's knots and
  // past the last point, where one Gauss rule over the kinks was off by ~1e-3. Tolerance 1e-6.
  const auto& curve = *magfem::MaterialLibrary::bundled().find("steel_1010")->curve;
  for (const double b : {0.3, 1.2, 1.9, 2.2, 2.8}) {
    const int n = 200000;
    double sum = 0;
    for (int i = 0; i <= n; ++i)
      sum += (i == 0 || i == n ? 0.5 : 1.0) * curve.h_of_b(b * i / n);
    const double reference = sum * b / n;
    EXPECT_NEAR(curve.energy_density(b), reference, 1e-6 * reference) << "B " << b;
    EXPECT_DOUBLE_EQ(curve.energy_density(-b), curve.energy_density(b));
  }
}

namespace {

// The BhTableError a table from a user gives (the parsers' checks); fails the test when none
// is thrown.
BhTableError table_error(const std::vector<double>& h, const std::vector<double>& b) {
  try {
    magfem::check_bh_table_plausible(h, b);
    BhCurve c(h, b);
  } catch (const BhTableError& e) {
    return e;
  }
  ADD_FAILURE() << "table accepted";
  return BhTableError(0, "");
}

bool says(const BhTableError& e, const std::string& text) {
  return e.reason().find(text) != std::string::npos;
}

} // namespace

// The issue-36 table: a real curve given as [B, H] is monotone and steep, so only the
// polarization bound catches it.
TEST(BhCurve, SwappedColumnsAreRefusedWithTheLikelyCause) {
  const auto& steel = *magfem::MaterialLibrary::bundled().find("steel_1010")->curve;
  const auto e = table_error(steel.b_table(), steel.h_table());
  EXPECT_EQ(e.row(), 1u); // row 0 is the origin
  EXPECT_TRUE(says(e, "columns swapped? B must be in T and H in A/m, as [H, B]")) << e.reason();
  EXPECT_TRUE(says(e, "above 3 T")) << e.reason();
  // B in gauss likewise.
  EXPECT_TRUE(says(table_error({100, 1000}, {5000, 15000}), "columns swapped?"));
}

// B itself may pass 3 T far in saturation (B = J + mu0 H): the bound is on J = B - mu0 H.
TEST(BhCurve, SaturatedTablePastThreeTeslaIsAccepted) {
  const double j = 2.0;
  EXPECT_NO_THROW(
      magfem::check_bh_table_plausible({1000, 1e5, 2e6}, {1.5, j + mu0 * 1e5, j + mu0 * 2e6}));
  EXPECT_TRUE(says(table_error({1000, 1e5}, {1.5, 3.01 + mu0 * 1e5}), "above 3 T"));
}

TEST(BhCurve, NonMonotoneTableIsRefusedWithTheReason) {
  const auto e = table_error({0, 100, 200, 300}, {0, 0.5, 1.0, 0.9});
  EXPECT_EQ(e.row(), 3u);
  EXPECT_TRUE(says(e, "not monotone")) << e.reason();
  EXPECT_TRUE(says(e, "B must be in T and H in A/m, as [H, B]")) << e.reason();
}

// The stated tolerance: a final slope down to 0.1 % below mu0 is rounding in a printed table.
TEST(BhCurve, FinalSlopeBelowMu0BeyondTheToleranceIsRefused) {
  const auto table = [](double final_slope) {
    return std::pair<std::vector<double>, std::vector<double>>{{100, 1000, 101000},
                                                               {0.5, 1.5, 1.5 + final_slope * 1e5}};
  };
  auto [h, b] = table(0.9995 * mu0);
  EXPECT_NO_THROW(BhCurve(h, b));
  std::tie(h, b) = table(0.998 * mu0);
  const auto e = table_error(h, b);
  EXPECT_EQ(e.row(), 2u);
  EXPECT_TRUE(says(e, "final slope dB/dH")) << e.reason();
  EXPECT_TRUE(says(e, "0.1 %")) << e.reason();
  EXPECT_TRUE(says(e, "polarization J")) << e.reason();
}
