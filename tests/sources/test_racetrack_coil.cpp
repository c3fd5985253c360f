// Racetrack coils (straight and arc bundles): Ampere's law around every piece, through a
// straight side and a corner, and beside them; div H = 0 and curl H = J; brute-force volume
// Biot-Savart; the dipole far field; and the racetrack without straights against the solenoid
// with the same cross-section (the arc code against the loop code).
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <random>

#include <gtest/gtest.h>

#include "coil_test_helpers.hpp"
#include "core/constants.hpp"
#include "core/gauss_legendre.hpp"
#include "sources/coil_field.hpp"
#include "sources/straight_bundle.hpp"

namespace magfem {
namespace {

// TEAM-7-like coil: straights 100 x 50 mm, inner radius 25 mm, width 25 mm, height 100 mm.
Coil3D racetrack_coil() {
  Coil3D c;
  c.shape = Racetrack{0.1, 0.05, 0.025, 0.025, 0.1};
  c.turns = 2742;
  c.current = 1.0;
  return c;
}

// See test_axisymmetric_coils.cpp: default tolerance 1e-8, measured within a factor ~3.
constexpr double far_tol = 2e-7;
constexpr double near_tol = 2e-5;

// Biot-Savart line integral I / (4 pi) int t x (x - y) / |x - y|^3 ds along the filament, by
// 20-point Gauss on panels graded geometrically (ratio 5) away from the point's foot on the
// filament, so that the peak of width d is resolved: an independent reference to ~1e-14.
Vec3 filament_by_quadrature(const Vec3& start, const Vec3& t, double len, double current,
                            const Vec3& x) {
  const double foot = std::clamp((x - start).dot(t), 0.0, len);
  const double d = std::max((x - start - (x - start).dot(t) * t).norm(), 1e-12);
  std::vector<double> cuts = {0.0, foot, len};
  for (double step = d; step < len; step *= 5) {
    cuts.push_back(foot - step);
    cuts.push_back(foot + step);
  }
  std::sort(cuts.begin(), cuts.end());
  Vec3 h = Vec3::Zero();
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double a = std::max(cuts[k], 0.0), b = std::min(cuts[k + 1], len);
    if (b <= a) {
      continue;
    }
    const QuadratureRule g = gauss_legendre(20, a, b);
    for (std::size_t i = 0; i < g.x.size(); ++i) {
      const Vec3 r = x - (start + g.x[i] * t);
      h += g.w[i] * current / (4 * pi) * t.cross(r) / std::pow(r.norm(), 3);
    }
  }
  return h;
}

TEST(StraightFilament, MatchesTheLineIntegralAlsoBeyondItsEnds) {
  const Vec3 start(0.1, -0.2, 0.3), t = Vec3(1, 2, -2).normalized();
  const double len = 0.5, current = 3.0;
  const Vec3 n = t.unitOrthogonal();
  for (const double s : {-1.0, -1e-3, 0.0, 0.2, 0.5, 0.5001, 3.0}) {
    for (const double d : {1e-6, 1e-3, 0.1, 2.0}) {
      const Vec3 x = start + s * t + d * n;
      const Vec3 h = straight_filament_field(start, t, len, current, x);
      const Vec3 ref = filament_by_quadrature(start, t, len, current, x);
      // The point's offset d is represented to 1e-17 / d relative, which bounds the agreement.
      EXPECT_LT((h - ref).norm(), (1e-12 + 1e-16 / d) * ref.norm()) << s << " " << d;
    }
  }
}

TEST(Racetrack, AmperesLawAroundThroughAndBesideEachPiece) {
  const CoilField f(racetrack_coil());
  const auto& r = std::get<Racetrack>(f.coil().shape);
  const double ni = f.coil().turns * f.coil().current;
  const test::Field H = [&](const Vec3& x) { return f.H(x); };
  // Bottom straight side (current +x) in the plane x = 0.01: cross-section centre at
  // y = -(sy/2 + R + w/2), z = 0; circle oriented y -> z (right-handed about +x).
  const Vec3 c_side(0.01, -(0.5 * r.straight_y + r.inner_radius + 0.5 * r.width), 0.0);
  const Vec3 ey = Vec3::UnitY(), ez = Vec3::UnitZ();
  // The big circles pass 20 mm from the other pieces: far rules.
  EXPECT_NEAR(test::circulation(H, c_side, ey, ez, 0.09, 512), ni, far_tol * ni);
  EXPECT_NEAR(test::circulation(H, c_side, ey, ez, 0.01, 512),
              ni * pi * 0.01 * 0.01 / f.cross_section_area(), near_tol * ni);
  EXPECT_NEAR(test::circulation(H, c_side - Vec3(0, 0.04, 0), ey, ez, 0.01, 512), 0.0,
              far_tol * ni);
  // Corner (+x, -y) at mid-angle -45 degrees: radial direction e_r, current along e_phi,
  // circle oriented z -> e_r (right-handed about e_z x e_r = e_phi).
  const double phi = -0.25 * pi;
  const Vec3 er(std::cos(phi), std::sin(phi), 0);
  const Vec3 c_corner =
      Vec3(0.5 * r.straight_x, -0.5 * r.straight_y, 0) + (r.inner_radius + 0.5 * r.width) * er;
  EXPECT_NEAR(test::circulation(H, c_corner, ez, er, 0.09, 512), ni, far_tol * ni);
  EXPECT_NEAR(test::circulation(H, c_corner, ez, er, 0.01, 512),
              ni * pi * 0.01 * 0.01 / f.cross_section_area(), near_tol * ni);
  EXPECT_NEAR(test::circulation(H, c_corner + 0.04 * er, ez, er, 0.01, 512), 0.0, far_tol * ni);
  // A circle in the plane z = 0.2 above the coil links nothing.
  EXPECT_NEAR(test::circulation(H, Vec3(0, 0, 0.2), Vec3::UnitX(), ey, 0.1, 512), 0.0,
              far_tol * ni);
}

TEST(Racetrack, DivergenceFreeAndCurlIsTheCurrentDensity) {
  const CoilField f(racetrack_coil());
  const test::Field H = [&](const Vec3& x) { return f.H(x); };
  const double size = 0.025;
  // Inside a straight side, inside a corner, next to the joint of the two, in the bore, outside.
  for (const Vec3& x : {Vec3(0.01, -0.0625, 0.01), Vec3(0.075, -0.045, -0.02),
                        Vec3(0.0503, -0.06, 0.03), Vec3(0.0, 0.0, 0.0), Vec3(0.02, 0.11, 0.07)}) {
    const bool inside = f.contains(x);
    const double h = inside ? 0.02 * size : 0.005 * size;
    const Mat3 jac = test::jacobian(H, x, h);
    const double scale = jac.norm() + f.H(x).norm() / size;
    // Inside, the evaluation error ~1e-6 |H| divided by h sets the bound (see the axisymmetric
    // test); outside the far rules are at 1e-8.
    EXPECT_LT(std::abs(jac.trace()), (inside ? 2e-3 : 1e-5) * scale) << x.transpose();
    EXPECT_LT((test::curl(jac) - f.current_density(x)).norm(), (inside ? 2e-3 : 1e-5) * scale)
        << x.transpose();
  }
}

TEST(Racetrack, MatchesBruteForceVolumeIntegration) {
  const CoilField f(racetrack_coil());
  // The coil's own volume rule at orders 40 and 48: a Gauss rule of the Biot-Savart kernel,
  // converged for points away from the conductor (checked by the two orders agreeing).
  auto brute = [&](int order, const Vec3& x) {
    Vec3 h = Vec3::Zero();
    for (const CoilQuadraturePoint& q : f.volume_quadrature(order)) {
      const Vec3 r = x - q.x;
      h += q.weight * f.coil().current * q.j_per_ampere.cross(r) / (4 * pi * std::pow(r.norm(), 3));
    }
    return h;
  };
  for (const Vec3& x : {Vec3(0.0, 0.0, 0.0), Vec3(0.15, 0.02, 0.03), Vec3(0.06, -0.08, 0.09),
                        Vec3(0.0, 0.0, 0.12), Vec3(0.3, -0.2, 0.1)}) {
    const Vec3 fine = brute(48, x), coarse = brute(40, x);
    ASSERT_LT((fine - coarse).norm(), 1e-9 * fine.norm()) << "reference not converged";
    EXPECT_LT((f.H(x) - fine).norm(), far_tol * fine.norm()) << x.transpose();
  }
}

// Without straights the racetrack is a ring of rectangular cross-section: four arc bundles
// must give the solenoid's loops' field, inside and outside the conductor.
TEST(Racetrack, WithoutStraightsIsTheSolenoid) {
  Coil3D ring = racetrack_coil();
  ring.shape = Racetrack{0.0, 0.0, 0.02, 0.01, 0.03};
  Coil3D sol = ring;
  sol.shape = Solenoid{0.02, 0.03, 0.03};
  const CoilField fr(ring), fs(sol);
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> u(-0.06, 0.06);
  for (int t = 0; t < 60; ++t) {
    Vec3 x(u(gen), u(gen), u(gen));
    if (t % 3 == 0) { // inside the conductor
      const double rho = 0.02 + 0.01 * (0.5 + u(gen) / 0.12), phi = 50 * u(gen);
      x = Vec3(rho * std::cos(phi), rho * std::sin(phi), 0.25 * u(gen));
    }
    const Vec3 hs = fs.H(x);
    // Within a bundle size (10 mm) of the conductor both codes use their near rules (~1e-6).
    const double rho = std::hypot(x.x(), x.y());
    const double dist =
        std::hypot(std::max({0.02 - rho, 0.0, rho - 0.03}), std::max(std::abs(x.z()) - 0.015, 0.0));
    const double tol = dist < 0.01 ? near_tol : far_tol;
    EXPECT_LT((fr.H(x) - hs).norm(), tol * hs.norm() + 1e-9) << x.transpose();
  }
}

// Far field: the dipole of moment turns I times the enclosed area averaged over the width
// ((sx + 2t)(sy + 2t) - (4 - pi) t^2 for t from R to R + w). The coil is symmetric about its
// centre, so the first correction is the octupole, (size / r)^2 ~ 4e-6 at r = 50 m.
TEST(Racetrack, FarFieldIsTheDipole) {
  const CoilField f(racetrack_coil());
  const auto& r = std::get<Racetrack>(f.coil().shape);
  auto area = [&](double t) {
    return (r.straight_x + 2 * t) * (r.straight_y + 2 * t) - (4 - pi) * t * t;
  };
  // Simpson is exact for the quadratic.
  const double mean = (area(r.inner_radius) + 4 * area(r.inner_radius + 0.5 * r.width) +
                       area(r.inner_radius + r.width)) /
                      6;
  const Vec3 m = f.coil().turns * f.coil().current * mean * Vec3::UnitZ();
  EXPECT_NEAR(f.magnetic_moment_per_ampere().z() * f.coil().current, m.z(), 1e-12 * m.z());
  for (const Vec3& dir : {Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(0.3, -0.5, 0.7).normalized()}) {
    const Vec3 x = 50.0 * dir;
    const Vec3 dip = test::dipole_H(m, x);
    EXPECT_LT((f.H(x) - dip).norm(), 2e-5 * dip.norm()) << dir.transpose();
  }
}

} // namespace
} // namespace magfem
