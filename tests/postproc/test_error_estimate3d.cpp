// The 3D error estimator (postproc/error_estimate3d.hpp) against the exact field of the
// uniformly magnetized sphere in air (sphere_cases3d.hpp): the energy-norm effectivity
// (estimated / true error) on two mesh scales for orders 1 and 2, and the estimate falling
// at the rate of the energy norm (h^p) under refinement. The open-boundary shell has no
// indicator, so the true error is measured on the same physical tets.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "postproc/energy3d.hpp"
#include "postproc/error_estimate3d.hpp"
#include "solver/tet_quadrature.hpp"
#include "sphere_cases3d.hpp"

namespace magfem {
namespace {

using test::mm;

// Exact H of the sphere (radius a, B_r along z), continued smoothly within each region: the
// uniform interior field in magnet tets, the dipole in air tets (a P1 tet's faceted face
// leaves points of one region on the other side of the true sphere).
Eigen::Vector3d exact_H(const Eigen::Vector3d& x, bool in_magnet, double a, double B_r) {
  if (in_magnet)
    return Eigen::Vector3d(0, 0, -B_r / (3 * mu0));
  const Eigen::Vector3d m(0, 0, 4.0 / 3.0 * pi * a * a * a * B_r / mu0);
  const double r = x.norm();
  return (3 * m.dot(x) * x / std::pow(r, 5) - m / std::pow(r, 3)) / (4 * pi);
}

// True ||H - H_h||^2 in the energy norm, int mu |H - H_h|^2 over the physical tets (J);
// exact(t, x): the exact H of tet t's region at x.
template <class Exact> double true_error2(const test::SphereSolution& s, const Exact& exact) {
  double sum = 0;
  for (std::size_t t = 0; t < s.mesh.n_tets(); ++t) {
    if (s.problem.is_shell(t))
      continue;
    const double mu = mu0 * s.problem.physics(s.mesh.tet_part[t]).material->mu_r;
    for (const auto& q : tet_rule(5)) {
      const Eigen::Vector3d x = s.field->point(t, q.bary);
      const Eigen::Vector3d e = exact(t, x) - s.field->H(t, q.bary);
      sum += q.weight * s.field->volume_density(t, q.bary) * mu * e.squaredNorm();
    }
  }
  return sum;
}

// The magnetized sphere in a permeable shell (test::ShellSphereExact), H per region.
Eigen::Vector3d shell_exact_H(const test::ShellSphereExact& ex, const test::SphereSolution& s,
                              std::size_t t, const Eigen::Vector3d& x) {
  const int part = s.mesh.tet_part[t];
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  // H of (P r + Q / r^2) cos(theta), as in ShellSphereExact::B.
  auto h = [&](double p, double q) {
    const double r = x.norm();
    return Eigen::Vector3d(-p * z - q * (z / std::pow(r, 3) - 3 * x.z() * x / std::pow(r, 5)));
  };
  if (part == 0)
    return -ex.coef[0] * z;
  if (part == 1)
    return h(ex.coef[3], ex.coef[4]);
  const auto& k = s.mesh.tets[t];
  const Eigen::Vector3d centroid =
      0.25 * (s.mesh.nodes[k[0]] + s.mesh.nodes[k[1]] + s.mesh.nodes[k[2]] + s.mesh.nodes[k[3]]);
  return centroid.norm() < ex.b ? h(ex.coef[1], ex.coef[2]) : h(0, ex.coef[5]);
}

struct Measured {
  double estimated2 = 0, true2 = 0, pct = 0;
  long unknowns = 0;
  double effectivity() const { return std::sqrt(estimated2 / true2); }
};

template <class Exact> Measured measure(const test::SphereCase& c, const Exact& exact_of) {
  const auto s = test::solve_sphere_case(c);
  EXPECT_TRUE(s->report.converged);
  const auto t0 = std::chrono::steady_clock::now();
  const PatchRecovery3D rec(*s->field);
  const double rec_s = test::seconds_since(t0);
  const std::vector<std::string> names = {"magnet", "shell"};
  const double energy =
      summarize_energy_3d(*s->field, {names.begin(), names.begin() + s->problem.parts.size()})
          .total_J;
  const auto t1 = std::chrono::steady_clock::now();
  const ErrorEstimate3D est = estimate_error_3d(rec, energy);
  std::printf("recovery %.3f s, indicator %.3f s, solve %.3f s\n", rec_s, test::seconds_since(t1),
              s->report.solve_s);
  Measured m;
  m.estimated2 = est.error_norm2_J;
  m.true2 =
      true_error2(*s, [&](std::size_t t, const Eigen::Vector3d& x) { return exact_of(*s, t, x); });
  m.pct = est.energy_error_pct;
  m.unknowns = s->dofs->n_dofs();
  std::printf("order %d scale %.2f: %ld unknowns, estimated %.4g %%, effectivity %.3f, "
              "%zu patches degraded\n",
              c.order, c.size_scale, m.unknowns, m.pct, m.effectivity(), est.degraded_patches);
  return m;
}

Measured measure_sphere(int order, double scale) {
  test::SphereCase c;
  c.order = order;
  c.size_scale = scale;
  c.chord_tolerance = 0; // every size, the facets too, scales with h (as test_sphere3d's rates)
  return measure(c, [&](const test::SphereSolution& s, std::size_t t, const Eigen::Vector3d& x) {
    return exact_H(x, s.mesh.tet_part[t] == 0, c.magnet_radius, c.B_r);
  });
}

// Effectivity within 0.3..3 (issue 29's bound for every estimate it names): a recovery
// estimator is asymptotically exact only where the recovery superconverges, which meshes
// of a few elements across the magnet are not, so the bound is the honest one, not 1 +- 0.1.
// Rate: the energy error of order p falls as h^p = N^(-p/3) with N unknowns; the observed
// exponent of the estimate between the two scales is asserted within 0.6p..1.5p (two coarse
// TetGen meshes are not exactly similar, and the curved/faceted sphere adds its own
// geometric term), which still tells p = 1 from p = 2.
void check_order(int order, double coarse, double fine) {
  const Measured a = measure_sphere(order, coarse);
  const Measured b = measure_sphere(order, fine);
  for (const Measured* m : {&a, &b}) {
    EXPECT_GT(m->effectivity(), 0.3) << "order " << order;
    EXPECT_LT(m->effectivity(), 3.0) << "order " << order;
    // Measured 0.88..1.02 (commit of this test). Order 2 recovered with degree 1 instead of 2
    // gives 1.7 (within 0.3..3); dropping the background air gives 0.06.
    EXPECT_GT(m->effectivity(), 0.75) << "order " << order;
    EXPECT_LT(m->effectivity(), 1.3) << "order " << order;
  }
  const double rate = -std::log(std::sqrt(b.estimated2 / a.estimated2)) /
                      std::log(static_cast<double>(b.unknowns) / a.unknowns) * 3;
  std::printf("order %d: observed rate of the estimate h^%.2f\n", order, rate);
  EXPECT_GT(rate, 0.6 * order);
  EXPECT_LT(rate, 1.5 * order);
}

TEST(ErrorEstimate3D, SphereOrder1EffectivityAndRate) {
  check_order(1, 2.0, 1.0);
}
TEST(ErrorEstimate3D, SphereOrder2EffectivityAndRate) {
  check_order(2, 2.0, 1.41);
}

// A magnet in a mu_r 100 shell: the permeability enters eta_K (mu |H* - H_h|^2) and the
// regions' fits must not mix (H jumps by mu_r across the shell's faces). Bounds as above.
TEST(ErrorEstimate3D, SphereInPermeableShellOrder2) {
  test::SphereCase c;
  c.shell_inner = 15 * mm;
  c.shell_outer = 20 * mm;
  c.shell_mu_r = 100;
  c.domain_radius = 30 * mm;
  c.chord_tolerance = 0; // sizes alone
  c.size_scale = 3;
  const test::ShellSphereExact ex(10 * mm, 15 * mm, 20 * mm, 100, 1.0);
  const Measured m =
      measure(c, [&](const test::SphereSolution& s, std::size_t t, const Eigen::Vector3d& x) {
        return shell_exact_H(ex, s, t, x);
      });
  EXPECT_GT(m.effectivity(), 0.3);
  EXPECT_LT(m.effectivity(), 3.0);
  // Measured 0.998. Patches that mix the regions (H jumps by mu_r across the shell) give 43.
  // A wrong mu in the shell's eta_K is not visible here: the shell carries under 1 % of the
  // error energy (mu |e_H|^2 = |e_B|^2 / mu), which is also why it matters little.
  EXPECT_GT(m.effectivity(), 0.75);
  EXPECT_LT(m.effectivity(), 1.3);
}

} // namespace
} // namespace magfem
