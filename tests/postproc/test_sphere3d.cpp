// Physics tests of the 3D scalar-potential solver with TetGen meshes (mesh/mesher3d.hpp):
// the uniformly magnetized sphere (exact: uniform (2/3) B_r inside, a dipole outside), its
// energy, the open boundary, convergence rates of orders 1 and 2, and a magnetized sphere in
// a concentric permeable shell (exact l = 1 solution). Meshes are kept coarse for the test
// budget; tolerances are stated with their reason. The strict accuracy study at finer meshes
// is magfem_sphere3d_study (tests/postproc/sphere3d_study.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "postproc/energy3d.hpp"
#include "postproc/patch_recovery3d.hpp"
#include "postproc/point_locator3d.hpp"
#include "postproc/probes3d.hpp"
#include "postproc/recovered_b3d.hpp"
#include "sphere_cases3d.hpp"
#include "tests/threads_variable.hpp"

namespace magfem {
namespace {

using test::mm;

struct ProbeError {
  double rms = 0, max = 0; // relative to the rms / max of the exact field
};

// Which B a probe reads (probes3d.hpp).
enum class Reading { element, nodal_average, patch_recovery };

// Error of B on a full sphere probe of radius r.
template <class Exact>
ProbeError sphere_probe_error(const test::SphereSolution& s, double r, const Exact& exact,
                              Reading reading = Reading::element) {
  const PointLocator3D locator(s.mesh);
  ProbeSpec p;
  p.name = "probe";
  p.kind = ProbeSpec::Kind::sphere;
  p.radius = r;
  p.theta_min = 0;
  p.theta_max = pi;
  p.phi_min = 0;
  p.phi_max = 2 * pi;
  p.theta_steps = 19;
  p.phi_steps = 24;
  const ProbeTable t = [&] {
    switch (reading) {
    case Reading::nodal_average: {
      const RecoveredB3D rec(*s.field);
      return sample_probe_3d(*s.field, locator, p, 1.0, &rec);
    }
    case Reading::patch_recovery:
      return sample_probe_3d(*s.field, locator, p, 1.0, PatchRecovery3D(*s.field));
    case Reading::element:
      break;
    }
    return sample_probe_3d(*s.field, locator, p, 1.0);
  }();
  double se = 0, sr = 0, me = 0, mr = 0;
  for (const auto& row : t.rows) {
    const Eigen::Vector3d x(row[2], row[3], row[4]), b(row[5], row[6], row[7]);
    const Eigen::Vector3d e = exact(x);
    se += (b - e).squaredNorm();
    sr += e.squaredNorm();
    me = std::max(me, (b - e).norm());
    mr = std::max(mr, e.norm());
  }
  return {std::sqrt(se / sr), me / mr};
}

Eigen::Vector3d dipole(const Eigen::Vector3d& x) {
  return test::sphere_exact_B(x, 10 * mm, 1.0);
}

// Volume average of B over the tets of `part`.
Eigen::Vector3d average_B(const test::SphereSolution& s, int part) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double vol = 0;
  for (std::size_t t = 0; t < s.mesh.n_tets(); ++t) {
    if (s.mesh.tet_part[t] != part)
      continue;
    const auto& k = s.mesh.tets[t];
    const Eigen::Vector3d* p = s.mesh.nodes.data();
    Eigen::Matrix3d j;
    j << p[k[1]] - p[k[0]], p[k[2]] - p[k[0]], p[k[3]] - p[k[0]];
    const double v = j.determinant() / 6;
    sum += v * s.field->B(t, {0.25, 0.25, 0.25, 0.25});
    vol += v;
  }
  return sum / vol;
}

test::SphereCase default_like_case() {
  test::SphereCase c;
  c.order = 2;
  c.size_scale = 2.5;
  c.probe_radius = 12 * mm;
  return c;
}

TEST(MagnetizedSphere, FieldInsideAndOnProbeSphere) {
  const auto c = default_like_case();
  const auto s = test::solve_sphere_case(c);
  ASSERT_TRUE(s->report.converged);
  const ProbeError inside = sphere_probe_error(*s, 6 * mm, dipole);
  const ProbeError r12 = sphere_probe_error(*s, 12 * mm, dipole);
  const ProbeError r12_rec = sphere_probe_error(*s, 12 * mm, dipole, Reading::nodal_average);
  std::printf("sphere: %zu tets, %d unknowns, mesh %.1f s, setup %.1f s, assemble %.1f s, "
              "solve %.1f s (%s)\n  inside r6: rms %.3f%% max %.3f%%; r12 element: rms %.3f%% "
              "max %.3f%%; r12 recovered: rms %.3f%% max %.3f%%\n",
              s->mesh.n_tets(), s->assembler->n_unknowns(), s->mesh_s, s->setup_s,
              s->report.assemble_s, s->report.solve_s, s->report.linear_solver.c_str(),
              100 * inside.rms, 100 * inside.max, 100 * r12.rms, 100 * r12.max, 100 * r12_rec.rms,
              100 * r12_rec.max);
  // Inside: the 0.3 %. On r12 the 0.2 % rms / 0.5 % max (recovered field)
  // are met at 654k unknowns (magfem_sphere3d_study 2 1.5 0.02 0.6: 0.105 % rms, 0.245 % max
  // recovered, 0.010 % inside), beyond this test's time budget. The P2 field error falls as
  // h^2 ~ N^(-2/3) (ConvergenceRatesOrders1And2 checks the rate), so on this mesh (2.5 mm
  // elements near r12, about 238k unknowns) the targets scale by (654k / N)^(2/3), about 1.96.
  // Measured 0.27 % rms / 0.71 % max recovered, 0.44 % rms element field. The recovered field
  // must beat the element field it is recovered from (a broken recovery would not).
  const double mesh_factor = std::pow(654e3 / s->assembler->n_unknowns(), 2.0 / 3.0);
  EXPECT_LT(inside.max, 0.003);
  EXPECT_LT(r12_rec.rms, 0.002 * mesh_factor);
  EXPECT_LT(r12_rec.max, 0.005 * mesh_factor);
  EXPECT_LT(r12_rec.rms, r12.rms);
  EXPECT_LT(r12.rms, 0.005 * mesh_factor);
}

// Energy of the magnetized sphere measured from the remanent state: (1/2) mu0 N M^2 V with
// N = 1/3, i.e. (2/9) pi a^3 B_r^2 / mu0 in total, of which the exterior of radius R holds
// the dipole energy mu0 m^2 / (12 pi R^3) = (4/27) pi a^6 B_r^2 / (mu0 R^3). Doubling the
// domain radius must change nothing but the split between air and exterior.
TEST(MagnetizedSphere, EnergyAndOpenBoundary) {
  const double a = 10 * mm;
  const double w_total = 2.0 / 9.0 * pi * std::pow(a, 3) / mu0;
  double w_prev = 0, bz_prev = 0;
  for (double radius : {25 * mm, 50 * mm}) {
    test::SphereCase c;
    c.order = 2;
    c.domain_radius = radius;
    c.size_scale = 3;
    c.chord_tolerance = 0.1 * mm;
    const auto s = test::solve_sphere_case(c);
    ASSERT_TRUE(s->report.converged);
    const EnergySummary3D e = summarize_energy_3d(*s->field, {"magnet"});
    const double w_exterior = 4.0 / 27.0 * pi * std::pow(a, 6) / (mu0 * std::pow(radius, 3));
    const double bz = average_B(*s, 0).z();
    const double v_error = s->mesh.part_volumes[0] / (4.0 / 3.0 * pi * std::pow(a, 3)) - 1;
    std::printf(
        "R = %.0f mm: %d unknowns, straight-facet magnet volume %+.3f%%, energy total %+.3f%%, "
        "exterior %+.3f%%, mean Bz in magnet %+.4f%%\n",
        radius / mm, s->assembler->n_unknowns(), 100 * v_error, 100 * (e.total_J / w_total - 1),
        100 * (e.regions[2].energy_J / w_exterior - 1), 100 * (bz / (2.0 / 3.0) - 1));
    // The magnet surface is curved (isoparametric, also in the energy integral), so its
    // volume and moment are right even on this coarse mesh, whose straight facets lose 1.3 %
    // of the volume. Measured: total -0.08 % / -0.02 %, exterior -0.5 % / -0.2 % (the air
    // elements at R are 12 mm here); bounds 0.2 % and 1 %.
    EXPECT_NEAR(e.total_J / w_total, 1.0, 0.002);
    EXPECT_NEAR(e.regions[2].energy_J / w_exterior, 1.0, 0.01);
    // The summary's per-element shares are added in element order: one thread must give the
    // same bits as the automatic count (two or more here, on a machine with two cores).
    EXPECT_GT(s->mesh.n_tets(), 20000u) << "too few tets for a threaded summary";
    const EnergySummary3D serial = [&] {
      const test::ThreadsVariable one_thread("1");
      return summarize_energy_3d(*s->field, {"magnet"});
    }();
    // With the recovery's peak |B| per tet (as run_case_3d does; shell and curved tets here):
    // the same bits too.
    const RecoveredB3D rec(*s->field);
    const EnergySummary3D shared =
        summarize_energy_3d(*s->field, {"magnet"}, &rec.element_peak_B());
    for (std::size_t i = 0; i < e.regions.size(); ++i) {
      EXPECT_EQ(serial.regions[i].energy_J, e.regions[i].energy_J) << e.regions[i].name;
      EXPECT_EQ(serial.regions[i].volume_m3, e.regions[i].volume_m3) << e.regions[i].name;
      EXPECT_EQ(serial.regions[i].peak_B_T, e.regions[i].peak_B_T) << e.regions[i].name;
      EXPECT_EQ(shared.regions[i].energy_J, e.regions[i].energy_J) << e.regions[i].name;
      EXPECT_EQ(shared.regions[i].peak_B_T, e.regions[i].peak_B_T) << e.regions[i].name;
    }
    if (w_prev > 0) {
      EXPECT_NEAR(e.total_J / w_prev, 1.0, 0.001);
      EXPECT_NEAR(bz / bz_prev, 1.0, 0.001);
    }
    w_prev = e.total_J;
    bz_prev = bz;
  }
}

// Rates under uniform refinement (every size, including the surface facets, scales with h):
// the element B error on r12 is O(h) for order 1 and O(h^2) for order 2 (the faceting of the
// sphere is O(h^2) as well). The patch recovery (what the probe CSVs hold) is one order
// better on this smooth exterior field: O(h^2) for order 1, O(h^3) for order 2 (Zienkiewicz &
// Zhu 1992; the isoparametric sphere's geometry error is O(h^3) too). Rates are fitted over
// three levels.
TEST(MagnetizedSphere, ConvergenceRatesOrders1And2) {
  const std::vector<double> scales = {2.0, 1.41, 1.0};
  std::vector<double> h, e1, e2, patch1, patch2;
  for (double scale : scales) {
    test::SphereCase c;
    c.chord_tolerance = 0;
    c.magnet_size = 2 * mm;
    c.air_size = 4 * mm;
    c.size_scale = scale;
    const Mesh3D mesh = test::build_sphere_mesh(c);
    h.push_back(std::cbrt(1.0 / static_cast<double>(mesh.n_tets())));
    for (int order : {1, 2}) {
      c.order = order;
      const auto s = test::solve_sphere_case(c, mesh);
      ASSERT_TRUE(s->report.converged);
      const double e = sphere_probe_error(*s, 12 * mm, dipole).rms;
      const double e_patch = sphere_probe_error(*s, 12 * mm, dipole, Reading::patch_recovery).rms;
      (order == 1 ? e1 : e2).push_back(e);
      (order == 1 ? patch1 : patch2).push_back(e_patch);
      std::printf("h-scale %.2f: %zu tets, order %d, %d unknowns, r12 rms error %.4f%% element, "
                  "%.4f%% patch-recovered\n",
                  scale, mesh.n_tets(), order, s->assembler->n_unknowns(), 100 * e, 100 * e_patch);
    }
  }
  auto rate = [&](const std::vector<double>& e) {
    return std::log(e.front() / e.back()) / std::log(h.front() / h.back());
  };
  std::printf("observed rates: element order 1 %.2f, order 2 %.2f; patch-recovered order 1 "
              "%.2f, order 2 %.2f\n",
              rate(e1), rate(e2), rate(patch1), rate(patch2));
  EXPECT_GT(rate(e1), 0.8);
  EXPECT_LT(rate(e1), 1.5);
  EXPECT_GT(rate(e2), 1.7);
  // Measured 2.55 (order 1) and 3.59 (order 2). Planted: the nodal averages (RecoveredB3D)
  // read instead show 2.00 (order 1: averaging P1 gradients superconverges too) and 1.72
  // (order 2), which fails.
  EXPECT_GT(rate(patch1), 1.8);
  EXPECT_GT(rate(patch2), 2.7);
  for (std::size_t i = 0; i < h.size(); ++i) {
    EXPECT_LT(patch1[i], e1[i]) << "level " << i;
    EXPECT_LT(patch2[i], e2[i]) << "level " << i;
  }
}

// Magnetized sphere (10 mm, B_r 1 T) inside a concentric linear shell (15..20 mm, mu_r 100):
// the exact l = 1 solution (test::ShellSphereExact) inside the magnet, in the air gap and in
// the shell, within 0.5 % rms over each probe sphere. The test mesh is coarse (chord
// tolerance 0.05 mm, air gap resolved by a probe band); the spheres are curved
// (isoparametric edge nodes), so the exact solution is that of the true radii.
TEST(MagnetizedSphere, InsidePermeableShell) {
  test::SphereCase c;
  c.shell_inner = 15 * mm;
  c.shell_outer = 20 * mm;
  c.shell_mu_r = 100;
  c.domain_radius = 30 * mm;
  c.chord_tolerance = 0.05 * mm;
  c.size_scale = 2;
  c.probe_radius = 12.5 * mm; // resolve the air gap
  c.probe_size = 0.75 * mm;   // times size_scale
  const auto s = test::solve_sphere_case(c);
  ASSERT_TRUE(s->report.converged);
  const test::ShellSphereExact exact(10 * mm, 15 * mm, 20 * mm, 100, 1.0);
  auto b = [&](const Eigen::Vector3d& x) { return exact.B(x); };
  std::printf("shell: %d unknowns, solve %.1f s\n", s->assembler->n_unknowns(), s->report.solve_s);
  for (double r : {6.0, 12.5, 17.5}) {
    const ProbeError e = sphere_probe_error(*s, r * mm, b, Reading::nodal_average);
    std::printf("  r = %.1f mm: rms %.3f%% max %.3f%% (|B| exact at pole %.4f T)\n", r, 100 * e.rms,
                100 * e.max, exact.B(Eigen::Vector3d(0, 0, r * mm)).norm());
    EXPECT_LT(e.rms, 0.005) << r;
  }
}

} // namespace
} // namespace magfem
