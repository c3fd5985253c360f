// Fully normalized associated Legendre functions (analytic/legendre.hpp): agreement with the
// standard library's spherical Legendre functions, the addition theorem at any degree (where
// unscaled recurrences underflow), derivatives, orthonormality, and Gauss-Legendre rules.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "analytic/legendre.hpp"

namespace magfem {
namespace {

constexpr double kPi = std::numbers::pi;

// std::sph_legendre(l, m, t) = (-1)^m sqrt((2l+1)/(4 pi) (l-m)!/(l+m)!) P_l^m(cos t) with
// P_l^m free of the Condon-Shortley phase (C++17 [sf.cmath]), i.e. (-1)^m Pbar_lm. Round-off
// of both recurrences over 100 degrees (libstdc++ uses its own recurrence): 1e-11.
TEST(HarmonicLegendre, MatchesStdSphLegendreUpToDegree100) {
  const int n_max = 100;
  const NormalizedLegendre legendre(n_max);
  for (double theta : {0.0, 0.013, 0.4, 1.1, kPi / 2, 2.3, kPi - 1e-3, kPi}) {
    const LegendreValues v = legendre.evaluate(theta);
    for (int n = 0; n <= n_max; ++n) {
      for (int m = 0; m <= n; ++m) {
        const double ref =
            (m % 2 == 0 ? 1.0 : -1.0) *
            std::sph_legendre(static_cast<unsigned>(n), static_cast<unsigned>(m), theta);
        ASSERT_NEAR(v.p[legendre.index()(n, m)], ref, 1e-11 * std::max(1.0, std::abs(ref)))
            << "n=" << n << " m=" << m << " theta=" << theta;
      }
    }
  }
}

// Addition theorem: sum_m |Y_nm|^2 = (2n+1)/(4 pi) at every angle, and
// sum_m |grad_s Y_nm|^2 = n(n+1)(2n+1)/(4 pi). At n = 2700 the sectoral terms near the poles
// are far below 1e-308, where a plain recurrence fails; the sums must still hold. Round-off:
// at the poles the recurrence has a double characteristic root (x = +-1), so rounding errors
// add up like n^2 eps there (observed 1.7e-10 at n = 1000); tolerance 1e-15 (n+1)^2, at
// least 1e-12.
TEST(HarmonicLegendre, AdditionTheoremHoldsAtHighDegree) {
  const int n_max = 2700;
  const NormalizedLegendre legendre(n_max);
  LegendreValues v;
  for (double theta : {0.0, 1e-6, 0.01, 0.3, kPi / 2, 2.9, kPi}) {
    legendre.evaluate(theta, v);
    for (int n : {0, 1, 2, 149, 150, 400, 1000, 2700}) {
      double sum_p = 0, sum_g = 0;
      for (int m = 0; m <= n; ++m) {
        const std::size_t k = legendre.index()(n, m);
        const double w = m == 0 ? 1.0 : 2.0;
        sum_p += w * v.p[k] * v.p[k];
        sum_g += w * (v.dp[k] * v.dp[k] + m * m * v.p_over_sin[k] * v.p_over_sin[k]);
        ASSERT_TRUE(std::isfinite(v.p[k]) && std::isfinite(v.dp[k]) &&
                    std::isfinite(v.p_over_sin[k]));
      }
      const double tol = std::max(1e-12, 1e-15 * (n + 1.0) * (n + 1.0));
      const double ref_p = (2.0 * n + 1) / (4 * kPi);
      EXPECT_NEAR(sum_p, ref_p, tol * ref_p) << "n=" << n << " theta=" << theta;
      const double ref_g = n * (n + 1.0) * ref_p;
      EXPECT_NEAR(sum_g, ref_g, tol * std::max(ref_g, 1.0)) << "n=" << n << " theta=" << theta;
    }
  }
}

// dPbar/dtheta against a central difference (h = 1e-5: truncation ~h^2 n^3 ~ 1e-7 of the
// scale sqrt(n) at n = 60), and p = sin(theta) p_over_sin.
TEST(HarmonicLegendre, DerivativeMatchesFiniteDifference) {
  const int n_max = 60;
  const NormalizedLegendre legendre(n_max);
  const double h = 1e-5;
  for (double theta : {0.2, 0.9, 1.7, 2.8}) {
    const LegendreValues v = legendre.evaluate(theta);
    const LegendreValues vp = legendre.evaluate(theta + h);
    const LegendreValues vm = legendre.evaluate(theta - h);
    for (int n = 0; n <= n_max; ++n) {
      for (int m = 0; m <= n; ++m) {
        const std::size_t k = legendre.index()(n, m);
        const double fd = (vp.p[k] - vm.p[k]) / (2 * h);
        ASSERT_NEAR(v.dp[k], fd, 1e-6 * std::sqrt(n + 1.0)) << "n=" << n << " m=" << m;
        if (m >= 1) {
          ASSERT_NEAR(v.p[k], std::sin(theta) * v.p_over_sin[k], 1e-14 * (n + 1));
        }
      }
    }
  }
}

// integral_0^pi Pbar_nm Pbar_lm sin t dt = delta_nl / (2 pi); in x = cos t the product is a
// polynomial of degree <= 2 n_max, integrated exactly by n_max + 1 Gauss nodes.
TEST(HarmonicLegendre, ColumnsAreOrthonormal) {
  const int n_max = 60;
  const NormalizedLegendre legendre(n_max);
  const QuadratureRule rule = gauss_legendre(n_max + 1);
  std::vector<LegendreValues> at(rule.x.size());
  for (std::size_t i = 0; i < rule.x.size(); ++i) {
    at[i] = legendre.evaluate(std::acos(rule.x[i]));
  }
  for (int m : {0, 1, 7, 30}) {
    for (int n = m; n <= n_max; n += 3) {
      for (int l = m; l <= n_max; l += 5) {
        double s = 0;
        for (std::size_t i = 0; i < rule.x.size(); ++i) {
          s += rule.w[i] * at[i].p[legendre.index()(n, m)] * at[i].p[legendre.index()(l, m)];
        }
        EXPECT_NEAR(2 * kPi * s, n == l ? 1.0 : 0.0, 1e-12) << n << " " << l << " " << m;
      }
    }
  }
}

TEST(HarmonicLegendre, GaussRuleIntegratesPolynomialsExactly) {
  for (int q : {1, 2, 5, 40, 300}) {
    const QuadratureRule rule = gauss_legendre(q, 0.5, 2.0);
    for (int k = 0; k <= 2 * q - 1; k += std::max(1, q / 3)) {
      double s = 0;
      for (std::size_t i = 0; i < rule.x.size(); ++i) {
        s += rule.w[i] * std::pow(rule.x[i] / 2.0, k);
      }
      const double exact = 2.0 * (1.0 - std::pow(0.25, k + 1)) / (k + 1);
      EXPECT_NEAR(s, exact, 1e-13 * exact) << "q=" << q << " k=" << k;
    }
  }
}

} // namespace
} // namespace magfem
