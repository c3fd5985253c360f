// Two independent analytic models of the thesis's 32-magnet benchmark (Table 3.1, parallel
// magnetization, centred directions; paper_targets.md A): the spherical harmonic model and
// the magnetic charge model (with imaging for the bounded case). Table 3.2 reports 0.025 /
// 0.028 / 0.0017 % (eq. 3.117) unbounded and 1.6 % bounded, limited by the thesis's overflow
// at 149 / 122 harmonics; issue 5 asks 0.01 %. Here the stricter pointwise measure is
// asserted: rms over the patch of the pointwise difference per component, relative to the
// rms of the reference component, below 1e-4; the eq. 3.117 figure is printed beside it.
#include <chrono>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "core/constants.hpp"
#include "analytic/benchmark32.hpp"
#include "analytic/charge_model.hpp"
#include "analytic/harmonic_model.hpp"

namespace magfem {
namespace {

using Vec3 = Eigen::Vector3d;

struct Patch {
  std::vector<Vec3> x;
  std::vector<Vec3> e_rho, e_theta, e_phi;
};

// rho = const, theta and phi in 0..90 deg in `step_deg` steps (the thesis's r56 surface).
Patch patch(double rho, double step_deg) {
  Patch p;
  const int n = static_cast<int>(std::lround(90.0 / step_deg));
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      const double t = i * step_deg * deg_to_rad, f = j * step_deg * deg_to_rad;
      const Vec3 er(std::sin(t) * std::cos(f), std::sin(t) * std::sin(f), std::cos(t));
      p.x.push_back(rho * er);
      p.e_rho.push_back(er);
      p.e_theta.emplace_back(std::cos(t) * std::cos(f), std::cos(t) * std::sin(f), -std::sin(t));
      p.e_phi.emplace_back(-std::sin(f), std::cos(f), 0.0);
    }
  }
  return p;
}

struct Discrepancy {
  double pointwise; // rms(B - B_ref) / rms(B_ref)
  double eq3117;    // (rms(B_ref) - rms(B)) / rms(B_ref), thesis eq. 3.117
};

Discrepancy compare(const std::vector<double>& b, const std::vector<double>& ref) {
  double d2 = 0, r2 = 0, b2 = 0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    d2 += (b[i] - ref[i]) * (b[i] - ref[i]);
    r2 += ref[i] * ref[i];
    b2 += b[i] * b[i];
  }
  return {std::sqrt(d2 / r2), (std::sqrt(r2) - std::sqrt(b2)) / std::sqrt(r2)};
}

std::vector<double> component(const std::vector<Vec3>& b, const std::vector<Vec3>& e) {
  std::vector<double> c(b.size());
  for (std::size_t i = 0; i < b.size(); ++i) {
    c[i] = b[i].dot(e[i]);
  }
  return c;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

HarmonicOptions harmonic_options(int n_max, std::optional<double> r_s) {
  HarmonicOptions o;
  o.n_max = n_max;
  o.permeable_radius = r_s;
  return o;
}

constexpr double kAsked = 1e-4; // issue 5: 0.01 %

// Pointwise rms discrepancy per compared component for n_max = 300 and 600 on a 6-deg patch
// (256 points; the full 2-deg patch is the benchmark script's job). Returns [n][component].
std::vector<std::vector<double>> run(Benchmark32Magnetization kind, std::optional<double> r_s,
                                     int n_components) {
  const auto magnets = make_benchmark32(kind);
  const Patch p = patch(Benchmark32::r_observation, 6.0);
  ChargeModelOptions copt;
  copt.tolerance = 1e-8; // quadrature error ~1e-8 of the peak, far below the harmonic tail
  std::vector<PermeableSphere> spheres;
  if (r_s) {
    spheres.push_back(PermeableSphere{Vec3::Zero(), *r_s, true});
  }
  auto t0 = std::chrono::steady_clock::now();
  const std::vector<Vec3> ref = ChargeModel(magnets, spheres, copt).B(p.x);
  std::printf("%s %s: charge model %.2f s for %zu points\n", to_string(kind).c_str(),
              r_s ? "bounded" : "unbounded", seconds_since(t0), p.x.size());
  const char* names[] = {"B_rho", "B_theta", "B_phi"};
  const std::vector<Vec3>* axes[] = {&p.e_rho, &p.e_theta, &p.e_phi};
  std::vector<std::vector<double>> out;
  for (int n_max : {300, 600}) {
    t0 = std::chrono::steady_clock::now();
    const std::vector<Vec3> b = HarmonicModel(magnets, harmonic_options(n_max, r_s)).B(p.x);
    std::printf("  harmonic n_max %d: %.2f s\n", n_max, seconds_since(t0));
    out.emplace_back();
    for (int c = 0; c < n_components; ++c) {
      const Discrepancy d = compare(component(b, *axes[c]), component(ref, *axes[c]));
      std::printf("    %-8s pointwise rms %.2e %%, eq. 3.117 %.2e %%\n", names[c],
                  100 * d.pointwise, 100 * d.eq3117);
      out.back().push_back(d.pointwise);
    }
  }
  return out;
}

// The remaining difference must be the harmonic truncation (it shrinks with n_max, by about
// (55/56)^300 = 4e-3 times algebraic factors), not a disagreement between the models.
void check(const std::vector<std::vector<double>>& d) {
  for (std::size_t c = 0; c < d[1].size(); ++c) {
    EXPECT_LT(d[1][c], kAsked) << "component " << c;
    EXPECT_LT(d[1][c], 0.5 * d[0][c]) << "component " << c << " does not converge with n_max";
  }
}

TEST(HarmonicVsCharge, Benchmark32ParallelUnbounded) {
  check(run(Benchmark32Magnetization::parallel_centred, std::nullopt, 3));
}

// Bounded: R_s = 56 mm, B_rho compared on R_s itself (the thesis's Fig. 3.12).
TEST(HarmonicVsCharge, Benchmark32ParallelBounded) {
  check(run(Benchmark32Magnetization::parallel_centred, Benchmark32::r_observation, 1));
}

// Radial magnetization, which the thesis's harmonic model could not represent (sec. 3.6.1).
TEST(HarmonicVsCharge, Benchmark32RadialUnbounded) {
  check(run(Benchmark32Magnetization::radial, std::nullopt, 3));
}

// A hemispherical, uneven array (3 x 5 segments of 30 x 72 deg, theta 0..90 deg, the other
// hemisphere empty) with mixed parallel directions and one radial segment: no equatorial
// symmetry, so every quadrature path without mirror pairing is used. Compared outside
// (rho = 45 mm, terms ~ (40/45)^n) and in the cavity (rho = 20 mm, ~ (20/30)^n), where
// n_max = 250 leaves a truncation below 1e-11; the charge model's tolerance is 1e-8, so
// the pointwise rms must agree to 1e-6 of the reference rms.
TEST(HarmonicVsCharge, UnevenHemisphereArray) {
  std::vector<AnalyticMagnet> magnets;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 5; ++j) {
      AnalyticMagnet m;
      m.shape = SphericalSegment{0.030,
                                 0.040,
                                 i * pi / 6,
                                 (i + 1) * pi / 6,
                                 0.1 + j * 2 * pi / 5,
                                 0.1 + (j + 1) * 2 * pi / 5};
      m.B_r = 1.0 + 0.05 * j;
      if (i == 1 && j == 2) {
        m.magnetization.pattern = Magnetization::Pattern::radial;
      } else {
        m.magnetization.pattern = Magnetization::Pattern::parallel;
        m.magnetization.direction =
            Vec3(std::cos(1.3 * j + i), std::sin(0.7 * i + j), 0.5 - i).normalized();
      }
      m.magnetization.sign = (i + j) % 2 == 0 ? 1.0 : -1.0;
      m.name = "h";
      m.name.append(std::to_string(i)).append("_").append(std::to_string(j));
      magnets.push_back(m);
    }
  }
  std::vector<Vec3> x;
  for (double rho : {0.020, 0.045}) {
    for (int it = 0; it <= 18; ++it) {
      for (int ip = 0; ip < 36; ip += 3) {
        const double t = it * 10 * deg_to_rad, f = ip * 10 * deg_to_rad;
        x.push_back(rho * Vec3(std::sin(t) * std::cos(f), std::sin(t) * std::sin(f), std::cos(t)));
      }
    }
  }
  ChargeModelOptions copt;
  copt.tolerance = 1e-8;
  const std::vector<Vec3> ref = ChargeModel(magnets, {}, copt).B(x);
  const std::vector<Vec3> b = HarmonicModel(magnets, harmonic_options(250, {})).B(x);
  double d2 = 0, r2 = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    d2 += (b[i] - ref[i]).squaredNorm();
    r2 += ref[i].squaredNorm();
  }
  std::printf("uneven hemisphere: pointwise rms |B - B_ref| / rms |B_ref| = %.2e\n",
              std::sqrt(d2 / r2));
  EXPECT_LT(std::sqrt(d2 / r2), 1e-6);
}

} // namespace
} // namespace magfem
