// The 3D error estimator (postproc/error_estimate3d.hpp) against the exact field of the
// uniformly magnetized sphere in air (sphere_cases3d.hpp): the energy-norm effectivity
// (estimated / true error) on two mesh scales for orders 1 and 2, and the estimate falling
// at the rate of the energy norm (h^p) under refinement; and the open-boundary shell's own
// indicator (mapped coordinates, the shell's metric) against the exact exterior field.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "postproc/energy3d.hpp"
#include "postproc/error_estimate3d.hpp"
#include "solver/shell_transform.hpp"
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

// True ||H - H_h||^2 in the energy norm (J), over the physical tets and over the shell.
struct TrueError2 {
  double physical = 0, shell = 0;
};

// Physical tets: int mu |H - H_h|^2 with exact(t, x) the exact H of tet t's region at x.
// Shell tets, independently of the metric the estimator uses: the mesh point x stands for
// x' = map(x), where the exact field is the dipole's H'(x') and the FE field J^-1 (-grad phi_h);
// int mu0 |H' - J^-1 G_h|^2 |det J| dV is that error's energy over the exterior.
template <class Exact> TrueError2 true_error2(const test::SphereSolution& s, const Exact& exact) {
  TrueError2 sum;
  const ShellTransform shell{s.mesh.shell_inner_radius, s.mesh.shell_outer_radius};
  for (std::size_t t = 0; t < s.mesh.n_tets(); ++t) {
    const bool in_shell = s.problem.is_shell(t);
    const double mu = mu0 * s.problem.physics(s.mesh.tet_part[t]).material->mu_r;
    for (const auto& q : tet_rule(5)) {
      const Eigen::Vector3d x = s.field->point(t, q.bary);
      const double dv = q.weight * s.field->volume_density(t, q.bary);
      if (in_shell) {
        const Eigen::Vector3d e =
            exact(t, shell.map(x)) - shell.inverse_jacobian(x) * s.field->H(t, q.bary);
        sum.shell += dv * mu0 * e.squaredNorm() * shell.det_jacobian(x);
      } else {
        const Eigen::Vector3d e = exact(t, x) - s.field->H(t, q.bary);
        sum.physical += dv * mu * e.squaredNorm();
      }
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

// Squared error norms (J) estimated and true, over the physical tets and over the shell.
struct Measured {
  double estimated2 = 0, true2 = 0, pct = 0;
  double shell_estimated2 = 0, shell_true2 = 0;
  long unknowns = 0;
  double effectivity() const { return std::sqrt(estimated2 / true2); }
  double shell_effectivity() const { return std::sqrt(shell_estimated2 / shell_true2); }
  double total_effectivity() const {
    return std::sqrt((estimated2 + shell_estimated2) / (true2 + shell_true2));
  }
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
  for (std::size_t t = 0; t < s->mesh.n_tets(); ++t)
    (s->problem.is_shell(t) ? m.shell_estimated2 : m.estimated2) += est.eta2_J[t];
  const TrueError2 truth =
      true_error2(*s, [&](std::size_t t, const Eigen::Vector3d& x) { return exact_of(*s, t, x); });
  m.true2 = truth.physical;
  m.shell_true2 = truth.shell;
  m.pct = est.energy_error_pct;
  m.unknowns = s->dofs->n_dofs();
  std::printf("order %d scale %.2f: %ld unknowns, estimated %.4g %%, effectivity %.3f "
              "(physical tets), %.3f (shell), %.3f (all; shell holds %.0f %% of the true "
              "error), %zu patches degraded\n",
              c.order, c.size_scale, m.unknowns, m.pct, m.effectivity(), m.shell_effectivity(),
              m.total_effectivity(), 100 * m.shell_true2 / (m.true2 + m.shell_true2),
              est.degraded_patches);
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
    // The open-boundary shell holds 26..43 % of the true error here. Its own effectivity,
    // measured 0.79..1.01 (the lowest: order 1, one or two tets across the shell), and that
    // of the whole estimate (0.86..1.02) within the same bounds as the physical tets'.
    // Planted (shell; whole): the shell's indicator dropped 0; 0.76..0.77 (the whole alone
    // would pass); the identity in place of the shell's metric 0.32..0.46; 0.79..0.82; the
    // fits' tangential part kept at infinity (order 2) 2.24..2.27; 1.65..1.66.
    EXPECT_GT(m->shell_effectivity(), 0.7) << "order " << order;
    EXPECT_LT(m->shell_effectivity(), 1.3) << "order " << order;
    EXPECT_GT(m->total_effectivity(), 0.75) << "order " << order;
    EXPECT_LT(m->total_effectivity(), 1.3) << "order " << order;
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
  // The open-boundary shell's own: measured 1.04 (the identity for its metric: 0.32).
  EXPECT_GT(m.shell_effectivity(), 0.7);
  EXPECT_LT(m.shell_effectivity(), 1.3);
}

} // namespace
} // namespace magfem
