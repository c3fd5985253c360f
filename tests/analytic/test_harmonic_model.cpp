// Spherical harmonic model (analytic/harmonic_model.hpp) against exact fields, and its
// behaviour at high degree.
#include <chrono>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "core/constants.hpp"
#include "analytic/benchmark32.hpp"
#include "analytic/closed_forms.hpp"
#include "analytic/harmonic_model.hpp"

namespace magfem {
namespace {

// n_theta x n_phi segments of one shell, all with the same parallel direction (or radial).
std::vector<AnalyticMagnet> segmented_shell(double r_in, double r_out, int n_theta, int n_phi,
                                            const Eigen::Vector3d& dir, double B_r,
                                            bool radial = false) {
  std::vector<AnalyticMagnet> out;
  for (int i = 0; i < n_theta; ++i) {
    for (int j = 0; j < n_phi; ++j) {
      AnalyticMagnet m;
      m.shape = SphericalSegment{r_in,
                                 r_out,
                                 pi * i / n_theta,
                                 pi * (i + 1) / n_theta,
                                 2 * pi * j / n_phi - 0.3,
                                 2 * pi * (j + 1) / n_phi - 0.3};
      m.B_r = B_r;
      m.magnetization.pattern =
          radial ? Magnetization::Pattern::radial : Magnetization::Pattern::parallel;
      m.magnetization.direction = dir.normalized();
      m.name = std::to_string(i);
      m.name.append("_").append(std::to_string(j));
      out.push_back(m);
    }
  }
  return out;
}

HarmonicOptions opts(int n_max, std::optional<double> r_s = {}, double quadrature_scale = 1.0) {
  HarmonicOptions o;
  o.n_max = n_max;
  o.permeable_radius = r_s;
  o.quadrature_scale = quadrature_scale;
  return o;
}

std::vector<Eigen::Vector3d> probe_points(const std::vector<double>& radii) {
  std::vector<Eigen::Vector3d> pts;
  for (double r : radii) {
    for (double t : {0.0, 0.3, 1.2, pi / 2, 2.5, pi}) {
      for (double p : {0.0, 0.7, 2.0, 4.4}) {
        pts.emplace_back(r * std::sin(t) * std::cos(p), r * std::sin(t) * std::sin(p),
                         r * std::cos(t));
      }
    }
  }
  return pts;
}

// A uniformly magnetized shell is exact in degree 1: the 4 x 8 segments' higher harmonics
// cancel to round-off, so the model must reproduce the sphere-minus-sphere field to ~1e-12
// (the issue asks 1e-6) in the cavity, in the magnet and outside, at any n_max.
TEST(HarmonicModel, UniformShellFromSegmentsIsExact) {
  const double r_in = 0.040, r_out = 0.055, B_r = 1.3;
  const Eigen::Vector3d dir = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
  for (auto [nt, np] : {std::pair{4, 8}, std::pair{1, 1}, std::pair{3, 5}}) {
    const HarmonicModel model(segmented_shell(r_in, r_out, nt, np, dir, B_r), opts(30));
    const auto pts = probe_points({0.0, 0.02, 0.045, 0.05, 0.056, 0.2});
    const auto B = model.B(pts);
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const Eigen::Vector3d ref =
          uniform_shell_B(pts[i], Eigen::Vector3d::Zero(), r_in, r_out, B_r * dir);
      EXPECT_LT((B[i] - ref).norm(), 1e-11 * B_r)
          << nt << "x" << np << " at " << pts[i].transpose();
    }
  }
}

TEST(HarmonicModel, UniformSolidSphereIsExact) {
  const double a = 0.03, B_r = 1.1;
  const Eigen::Vector3d dir = Eigen::Vector3d(1, 2, -2).normalized();
  const HarmonicModel model(segmented_shell(0.0, a, 2, 3, dir, B_r), opts(10));
  const auto pts = probe_points({0.01, 0.029, 0.031, 0.1});
  const auto B = model.B(pts);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Eigen::Vector3d ref = uniform_sphere_B(pts[i], Eigen::Vector3d::Zero(), a, B_r * dir);
    EXPECT_LT((B[i] - ref).norm(), 1e-11 * B_r) << pts[i].transpose();
  }
}

// Inside an infinitely permeable sphere R_s, the uniform shell's dipole psi = K cos/r^2 gets
// the image -K r cos / R_s^3: a uniform extra B = (B_r / 3)(R_o^3 - R_i^3)/R_s^3 along M,
// everywhere inside R_s. On R_s itself the tangential field vanishes.
TEST(HarmonicModel, UniformShellInPermeableSphereAddsUniformImageField) {
  const double r_in = 0.040, r_out = 0.055, r_s = 0.070, B_r = 1.3;
  const Eigen::Vector3d dir = Eigen::Vector3d(-0.2, 0.6, 0.5).normalized();
  const HarmonicModel model(segmented_shell(r_in, r_out, 4, 8, dir, B_r), opts(12, r_s));
  const Eigen::Vector3d image =
      B_r / 3 * (std::pow(r_out, 3) - std::pow(r_in, 3)) / std::pow(r_s, 3) * dir;
  const auto pts = probe_points({0.01, 0.045, 0.06, r_s});
  const auto B = model.B(pts);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Eigen::Vector3d ref =
        uniform_shell_B(pts[i], Eigen::Vector3d::Zero(), r_in, r_out, B_r * dir) + image;
    EXPECT_LT((B[i] - ref).norm(), 1e-11 * B_r) << pts[i].transpose();
    if (std::abs(pts[i].norm() - r_s) < 1e-12) {
      const Eigen::Vector3d e = pts[i].normalized();
      EXPECT_LT((B[i] - B[i].dot(e) * e).norm(), 1e-11 * B_r) << "tangential B on R_s";
    }
  }
  EXPECT_THROW(model.B(Eigen::Vector3d(0, 0, 1.01 * r_s)), std::domain_error);
  // In the magnet H is the exact field strength B_exact / mu0 - M (-M/3 of the big sphere,
  // the cavity's dipole and the image field), M the segment's own magnetization.
  const Eigen::Vector3d xm(0.0, 0.047, 0.0);
  const Eigen::Vector3d h_exact =
      (uniform_shell_B(xm, Eigen::Vector3d::Zero(), r_in, r_out, B_r * dir) + image) / mu0 -
      B_r / mu0 * dir;
  EXPECT_LT((model.H({xm}).front() - h_exact).norm(), 1e-11 * B_r / mu0);
  EXPECT_LT((model.magnetization(xm) - B_r / mu0 * dir).norm(), 1e-9);
}

// A closed shell magnetized radially with one sign has B = 0 everywhere (H = -M in the
// magnet, no field outside or in the cavity): checks the radial source terms and n = 0.
TEST(HarmonicModel, UniformRadialShellHasNoField) {
  const double B_r = 1.2;
  const HarmonicModel model(segmented_shell(0.04, 0.055, 4, 8, Eigen::Vector3d::UnitZ(), B_r, true),
                            opts(40));
  for (const Eigen::Vector3d& b : model.B(probe_points({0.02, 0.045, 0.05, 0.06}))) {
    EXPECT_LT(b.norm(), 1e-11 * B_r);
  }
}

// The benchmark array (thesis Table 3.1) at degrees far beyond the thesis's overflow at 149
// (122 bounded): all values finite; coefficients decaying like 1/n (M is piecewise constant
// with jumps along lines, whose spectrum falls as 1/n: n times the degree amplitude,
// averaged over 40 degrees, must stay within a factor 2 of its value near n = 5); and the
// field on rho = 56 mm converging geometrically: the degree-n terms there carry
// (R_o/rho)^n = (55/56)^n, so going from 300 to 600 must change B by much less than going
// from 150 to 300 (ratio about (55/56)^150 = 0.07 times algebraic factors; asserted < 0.2).
TEST(HarmonicModel, BenchmarkRunsToHighDegreeAndConverges) {
  const auto magnets = make_benchmark32(Benchmark32Magnetization::parallel_centred);
  std::vector<Eigen::Vector3d> pts;
  for (double t : {0.1, 0.5, 0.9, 1.3}) {
    for (double p : {0.2, 0.6, 1.0}) {
      pts.push_back(0.056 * Eigen::Vector3d(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p),
                                            std::cos(t)));
    }
  }
  for (std::optional<double> rs : {std::optional<double>{}, std::optional<double>{0.056}}) {
    std::vector<std::vector<Eigen::Vector3d>> fields;
    for (int n_max : {150, 300, 600}) {
      const HarmonicModel model(magnets, opts(n_max, rs));
      fields.push_back(model.B(pts));
      for (const auto& b : fields.back()) {
        ASSERT_TRUE(b.allFinite()) << "n_max " << n_max;
        ASSERT_LT(b.norm(), 5.0);
      }
      if (n_max == 600 && !rs) {
        const std::vector<double> amp = model.expansion().degree_amplitude();
        // Per-degree amplitudes oscillate; compare rms of n * amplitude over windows of 40
        // degrees (odd only: even degrees vanish by the array's symmetry).
        auto window = [&](int first) {
          double sum = 0;
          int count = 0;
          for (int n = first; n < first + 40; n += 2, ++count) {
            EXPECT_TRUE(std::isfinite(amp[n]));
            sum += n * n * amp[n] * amp[n];
          }
          return std::sqrt(sum / count);
        };
        const double ref = window(5);
        for (int first = 45; first + 40 <= 600; first += 40) {
          EXPECT_GT(window(first), 0.5 * ref) << first;
          EXPECT_LT(window(first), 2.0 * ref) << first;
        }
        for (int n : {5, 101, 401, 599}) {
          std::printf("degree amplitude n=%d: %.4g A/m, n * amplitude %.4g\n", n, amp[n],
                      n * amp[n]);
        }
      }
    }
    double d1 = 0, d2 = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      d1 = std::max(d1, (fields[1][i] - fields[0][i]).norm());
      d2 = std::max(d2, (fields[2][i] - fields[1][i]).norm());
    }
    std::printf("%s: max |B(300) - B(150)| = %.3e T, max |B(600) - B(300)| = %.3e T\n",
                rs ? "bounded" : "unbounded", d1, d2);
    EXPECT_LT(d2, 0.2 * d1);
  }
}

// The theta quadrature must not be the error source: doubling its nodes changes no
// coefficient by more than round-off relative to the largest.
TEST(HarmonicModel, CoefficientsAreConvergedInQuadrature) {
  const auto magnets = make_benchmark32(Benchmark32Magnetization::parallel_centred);
  const HarmonicModel a(magnets, opts(300));
  const HarmonicModel b(magnets, opts(300, {}, 2.0));
  const ShellExpansion& ea = a.expansion();
  const ShellExpansion& eb = b.expansion();
  double scale = 0, diff = 0;
  for (std::size_t k = 0; k < ea.index.size(); ++k) {
    for (auto [x, y] : {std::pair{ea.radial_cos[k], eb.radial_cos[k]},
                        std::pair{ea.radial_sin[k], eb.radial_sin[k]},
                        std::pair{ea.poloidal_cos[k], eb.poloidal_cos[k]},
                        std::pair{ea.poloidal_sin[k], eb.poloidal_sin[k]}}) {
      scale = std::max(scale, std::abs(y));
      diff = std::max(diff, std::abs(x - y));
    }
  }
  EXPECT_LT(diff, 1e-12 * scale) << diff << " of " << scale;
}

TEST(HarmonicModel, RejectsWhatItCannotRepresent) {
  const auto good = make_benchmark32(Benchmark32Magnetization::parallel_centred);
  auto expect_reject = [](std::vector<AnalyticMagnet> m, HarmonicOptions o, const char* what) {
    try {
      HarmonicModel model(m, o);
      ADD_FAILURE() << "accepted: " << what;
    } catch (const std::invalid_argument& e) {
      std::printf("rejected (%s): %s\n", what, e.what());
    }
  };
  auto m = good;
  m[3].shape = Cylinder{0, 0.01, 0.02};
  expect_reject(m, {}, "cylinder");
  m = good;
  std::get<SphericalSegment>(m[5].shape).r_outer = 0.06;
  expect_reject(m, {}, "two shells");
  m = good;
  m[0].placement.translation = Eigen::Vector3d(0, 0, 0.001);
  expect_reject(m, {}, "off-centre");
  m = good;
  m[0].placement = m[0].placement.rotated(Eigen::Vector3d::UnitX(), 0.1, Eigen::Vector3d::Zero());
  expect_reject(m, {}, "rotated");
  m = make_benchmark32(Benchmark32Magnetization::radial);
  m[2].magnetization.center = Eigen::Vector3d(0.01, 0, 0);
  expect_reject(m, {}, "radial about another centre");
  expect_reject(good, opts(0), "n_max 0");
  expect_reject(good, opts(10, 0.05), "R_s inside the magnets");
  expect_reject({}, {}, "empty");
  EXPECT_THROW(HarmonicModel(good, {PermeableSphere{Eigen::Vector3d::Zero(), 0.06, false}}, {}),
               std::invalid_argument);
}

// Issue 5 speed figure: time per harmonic order on the benchmark's r56 patch (2116 points,
// expansion included). Printed; asserted only loosely (shared 2-core machine): 5 ms target.
TEST(HarmonicModel, TimePerOrderOnBenchmark) {
  const auto magnets = make_benchmark32(Benchmark32Magnetization::parallel_centred);
  std::vector<Eigen::Vector3d> pts;
  for (int it = 0; it <= 45; ++it) {
    for (int ip = 0; ip <= 45; ++ip) {
      const double t = 2.0 * it * deg_to_rad, p = 2.0 * ip * deg_to_rad;
      pts.push_back(0.056 * Eigen::Vector3d(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p),
                                            std::cos(t)));
    }
  }
  for (int n_max : {150, 400}) {
    const auto t0 = std::chrono::steady_clock::now();
    const HarmonicModel model(magnets, opts(n_max));
    const auto B = model.B(pts);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("n_max %d: expansion %.3f s, total %.3f s for %zu points = %.2f ms per order\n",
                n_max, model.setup_seconds(), s, pts.size(), 1e3 * s / n_max);
    EXPECT_LT(1e3 * s / n_max, 50.0);
  }
}

} // namespace
} // namespace magfem
