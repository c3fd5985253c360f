// The adaptive loop of 3D solves (pipeline/adapt3d): on the uniformly magnetized sphere
// (exact stored energy B_r^2 V / (6 mu0)) from a coarse start it reaches a requested energy
// accuracy, the estimate's effectivity stays within 0.3..3 on every pass, the size sources
// refine the open boundary's shell where its indicator asks and leave an unmarked mesh as it
// was, and reaching a limit is reported (converged: false, a stop reason, a warning).
//
// Not here: adaptivity beating uniform refinement by the true error at equal unknowns. On
// this sphere it does not (adaptive 0.0315 % at 84k unknowns, uniform 0.0363 % at 70k and
// 0.0182 % at 124k, about 0.029 % at 84k): the field is smooth on both sides of the one
// interface and the case's sizes are already graded to it. The indicators of the first mesh
// bound what any refinement could gain: equidistributing them (h ~ eta_K^(-2/(2p+3))) needs
// 1.4x fewer tets than uniform refinement for the same error, before the mesher's grading
// (0.3) spreads the fine sizes outward. scripts/benchmark.sh prints both curves.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "core/constants.hpp"
#include "pipeline/adapt3d.hpp"
#include "tests/case_helpers.hpp"

using namespace magfem;

namespace {

// examples/3d/magnetized_sphere_adaptive.yaml with the energy alone as the named quantity:
// a = 10 mm, B_r = 1 T, mu_r 1, open boundary at 25 mm; 22k P2 unknowns on the first pass.
const std::string coarse_sphere_case =
    test::magnetized_sphere_case3d("4") + R"(boundary: {type: open, radius: 25, shell_ratio: 1.5}
mesh: {size: 8, chord_tolerance: 0.5}
solver: {order: 2}
adapt: {accuracy_pct: 0.05, quantities: [energy], max_passes: 4}
)";

// The energy of a uniformly magnetized sphere (demagnetizing factor 1/3): mu0 M^2 V / 6.
double exact_sphere_energy() {
  const double a = 0.010, volume = 4.0 / 3.0 * pi * a * a * a;
  return volume / (6 * mu0);
}

double true_error_pct(double energy) {
  return 100 * std::abs(energy - exact_sphere_energy()) / exact_sphere_energy();
}

// One file per test: ctest runs this file's tests at once, and a shared name let one test
// read the file while another rewrote it ("the file is empty").
CaseSpec sphere_spec() {
  const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  return read_case(test::write_temp_case("adapt3d_sphere_" + name + ".yaml", coarse_sphere_case));
}

} // namespace

TEST(Adapt3D, SphereReachesTheEnergyTargetAndTheEstimateHolds) {
  const auto run = run_adaptive_3d(sphere_spec(), {});
  ASSERT_TRUE(run->adapt);
  for (const auto& p : run->adapt->passes)
    std::cout << "pass " << p.pass << ": " << p.unknowns << " unknowns, estimated "
              << p.energy_error_pct << " %, true " << true_error_pct(p.energy_J) << " %\n";
  ASSERT_TRUE(run->adapt->converged);
  ASSERT_GE(run->adapt->passes.size(), 2u); // the coarse start misses 0.05 % (0.079 %)
  EXPECT_LE(run->error_estimate.energy_error_pct, 0.05);
  // The true error of the final energy is below the target too (measured 0.034 %).
  EXPECT_LT(true_error_pct(run->energy.total_J), 0.05);
  // Effectivity (estimated / true) on every pass within issue 29's 0.3..3: measured 0.89 and
  // 0.85. The open-boundary shell holds 40..60 % of the true error here; with its indicator
  // dropped the passes read 0.51 and 0.26 (commit before the shell's indicator).
  for (const auto& p : run->adapt->passes) {
    const double effectivity = p.energy_error_pct / true_error_pct(p.energy_J);
    EXPECT_GT(effectivity, 0.3) << "pass " << p.pass;
    EXPECT_LT(effectivity, 3.0) << "pass " << p.pass;
  }
  // The unknowns spent: measured 84k (uniform --mesh-scale refinement reaches the estimate
  // reached here, 0.027 %, at about 90k). Asking every tet for its TetGen edges instead of
  // its requested size (Mesh3D::tet_size) gave 103k.
  EXPECT_LT(run->dofs->n_dofs(), 110000);
  // Regions and materials survive the remeshing: the magnet's volume is the sphere's (P2
  // curved onto it, 1e-4 for the coarse facets' curving).
  const double a = 0.010;
  EXPECT_NEAR(run->energy.regions[0].volume_m3, 4.0 / 3.0 * pi * a * a * a,
              1e-4 * 4.0 / 3.0 * pi * a * a * a);
}

TEST(Adapt3D, ReachingALimitIsReportedNotSilent) {
  CaseSpec spec = sphere_spec();
  spec.adapt.max_passes = 1;
  const auto run = run_adaptive_3d(spec, {});
  EXPECT_FALSE(run->adapt->converged);
  EXPECT_EQ(run->adapt->passes.size(), 1u);
  EXPECT_NE(run->adapt->stop_reason.find("max_passes"), std::string::npos);
  ASSERT_FALSE(run->warnings.empty());
  EXPECT_NE(run->warnings.back().find("stopped before reaching"), std::string::npos);

  spec.adapt.max_passes = 4;
  spec.adapt.max_unknowns = 30000; // the first pass has 22k; the next needs ~90k
  const auto capped = run_adaptive_3d(spec, {});
  EXPECT_FALSE(capped->adapt->converged);
  EXPECT_EQ(capped->adapt->passes.size(), 1u);
  EXPECT_NE(capped->adapt->stop_reason.find("max_unknowns"), std::string::npos);
}

// The first pass's size sources, aimed at half the test's target: the shell's tets, which
// carry 43 % of the estimate here (and most of it at the outer sphere, where the map's metric
// is largest), must ask for smaller tets where their indicator is large, as the physical tets
// do. Measured: the shell's error-weighted mean ratio of the new size to the requested size
// 0.73; the 10 % of shell tets with the largest indicators 0.65, the 10 % with the smallest
// 1.12 (they may grow; the case's sizes still cap them in the mesher). Planted: the shell's
// tets keeping their size (ratio 1, the indicator not fed to the sources) reads 1, 1, 1.
TEST(Adapt3D, ShellIsRefinedWhereItsIndicatorAsks) {
  CaseSpec spec = sphere_spec();
  spec.adapt = {};
  const auto run = run_case_3d(spec, {});
  const Mesh3D& mesh = run->mesh;
  ASSERT_EQ(mesh.tet_size.size(), mesh.n_tets());
  const std::vector<SizeSample3D> samples = adapted_size_samples_3d(*run, 0.025, true);
  ASSERT_GE(samples.size(), mesh.n_tets()); // centroid sources first, in tet order
  const std::vector<double>& eta2 = run->error_estimate.eta2_J;
  std::vector<std::size_t> shell;
  double weighted = 0, weight = 0;
  for (std::size_t t = 0; t < mesh.n_tets(); ++t)
    if (run->problem.is_shell(t)) {
      shell.push_back(t);
      weighted += eta2[t] * samples[t].h / mesh.tet_size[t];
      weight += eta2[t];
    }
  ASSERT_GT(weight, 0.2 * run->error_estimate.error_norm2_J); // the shell matters here
  std::sort(shell.begin(), shell.end(), [&](auto a, auto b) { return eta2[a] > eta2[b]; });
  auto mean_ratio = [&](std::size_t lo, std::size_t hi) {
    double sum = 0;
    for (std::size_t k = lo; k < hi; ++k)
      sum += samples[shell[k]].h / mesh.tet_size[shell[k]];
    return sum / double(hi - lo);
  };
  const std::size_t tenth = shell.size() / 10;
  const double top = mean_ratio(0, tenth), bottom = mean_ratio(shell.size() - tenth, shell.size());
  std::cout << "shell: weighted ratio " << weighted / weight << ", largest tenth " << top
            << ", smallest tenth " << bottom << "\n";
  EXPECT_LT(weighted / weight, 0.85);
  EXPECT_LT(top, 0.75);
  EXPECT_GT(bottom, top + 0.2);
}

// Sources that ask every tet for the size it was asked to have (a target far above the
// estimate: every ratio 1) give back about the same mesh: measured 22.1k -> 27.1k unknowns
// (the point sources' grading). Asking for the edges TetGen produced instead (about 0.7 of
// the request) gave 65k: every pass refined everywhere by that factor, whatever the
// indicators said.
TEST(Adapt3D, UnmarkedMeshIsKept) {
  CaseSpec spec = sphere_spec();
  spec.adapt = {};
  const auto first = run_case_3d(spec, {});
  CaseSpec again = spec;
  again.geometry3d.options.refine_sizes = std::make_shared<const std::vector<SizeSample3D>>(
      adapted_size_samples_3d(*first, 1e3, false));
  const auto second = run_case_3d(again, {});
  std::cout << "kept: " << first->dofs->n_dofs() << " -> " << second->dofs->n_dofs()
            << " unknowns\n";
  EXPECT_LT(second->dofs->n_dofs(), 1.4 * first->dofs->n_dofs());
}
