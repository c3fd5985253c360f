// Goal-oriented 3D refinement for a named probe table (pipeline/adapt3d.cpp ProbeGoal3D): on
// the uniformly magnetized sphere (exact field outside: the point dipole B_r a^3 / 3), a
// patch of probe points near the sphere makes the marking refine around them.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <iterator>
#include <regex>

#include "core/constants.hpp"
#include "pipeline/adapt3d.hpp"
#include "postproc/point_locator3d.hpp"
#include "postproc/probes3d.hpp"
#include "tests/case_helpers.hpp"

using namespace magfem;

namespace {

// examples/3d/magnetized_sphere_probe_adaptive.yaml: the coarse sphere of test_adapt3d.cpp
// (a = 10 mm, B_r = 1 T; 22k P2 unknowns) with a patch of 40 points at r = 12 mm, 2 mm
// outside the magnet, over an eighth of its surface, named in adapt.quantities.
CaseSpec probe_spec() {
  return read_case(test::example("3d/magnetized_sphere_probe_adaptive.yaml"));
}

// The exact B (T) outside a sphere of radius a = 10 mm magnetized along z with B_r = 1 T: the
// point dipole mu0 m / (4 pi) = B_r a^3 / 3.
Eigen::Vector3d dipole_B(const Eigen::Vector3d& x) {
  const double a = 0.010, r = x.norm();
  const Eigen::Vector3d rhat = x / r, z(0, 0, 1);
  return a * a * a / 3 * (3 * rhat.z() * rhat - z) / (r * r * r);
}

// rms |B_written - B| over a table's points relative to its rms |B| (%).
double true_table_error_pct(const Run3D& run, const ProbeTable& t) {
  const std::size_t x = t.column("x"), bx = t.column("Bx");
  double err2 = 0, b2 = 0;
  for (const auto& row : t.rows) {
    const Eigen::Vector3d p =
        run.spec.length_unit * Eigen::Vector3d(row[x], row[x + 1], row[x + 2]);
    const Eigen::Vector3d b(row[bx], row[bx + 1], row[bx + 2]), exact = dipole_B(p);
    err2 += (b - exact).squaredNorm();
    b2 += exact.squaredNorm();
  }
  return 100 * std::sqrt(err2 / b2);
}

// The true error of the table `magfem solve` writes (the patch-recovered B*, probes3d.hpp).
double true_probe_error_pct(const Run3D& run) {
  return true_table_error_pct(run, run.probes.at(0));
}

// The true error of the element field B_h at the table's points: what the probe's estimate
// (the tets' rms of |B* - B_h|, postproc/probe_error3d.hpp) estimates. The written B* is one
// order better, so the estimate bounds the written table's error from above.
double true_element_error_pct(const Run3D& run) {
  const PointLocator3D locator(run.mesh);
  return true_table_error_pct(
      run, sample_probe_3d(*run.field, locator, run.spec.probes.at(0), run.spec.length_unit));
}

std::unique_ptr<Run3D> solve_with(const CaseSpec& spec, std::vector<SizeSample3D> sizes) {
  return test::solve_with_sizes_3d(spec, std::move(sizes));
}

} // namespace

// One pass planned from the same coarse first mesh two ways: with the probe's goal (energy
// aimed at 0.1 %, the probe at 0.5 % rms pointwise) and by the energy alone, aimed low enough
// (0.0125 %) to spend more unknowns. Measured (order 2; true: the written, patch-recovered
// table): first mesh 22.1k unknowns, probe error 1.46 % true, 3.98 % estimated; goal 69.3k
// unknowns, 0.100 % true, 0.63 % estimated; energy alone 108k unknowns, 0.21 % true. (With the
// nodal averages written: 2.17, 0.46 and 0.75 %.) So the goal beats the energy rule's error with
// 1.5x fewer unknowns; asserted: 1.5x fewer and a lower error (the meshes are deterministic).
// Planted: the probe rule not applied (apply_probe_rule returning at once): the goal pass is
// the energy's 0.1 % pass, 52k unknowns and 1.41 % true, and the error comparison fails.
// The estimate's effectivity (estimated / true, both rms over the 40 points) is held to
// issue 29's 3x both ways on both meshes against the error of the element field, which it
// estimates (the tet's rms of |B* - B_h|; measured 1.14 and 1.11); the written table, the
// patch recovery, is one order better and the estimate bounds its error (measured 2.7x and
// 6.3x above it). Planted: mu dropped from e_K (1658x).
TEST(Adapt3DProbe, GoalRefinesAtTheProbeAndItsEstimateHolds) {
  const CaseSpec spec = probe_spec();
  const auto quantities = resolve_adapt_quantities(spec);
  const auto first = solve_with(spec, {});
  const auto goals = probe_goals_3d(*first, quantities);
  ASSERT_EQ(goals.size(), 1u);
  ASSERT_EQ(goals[0].point_tets.size(), 40u);
  const auto goal = solve_with(spec, adapted_size_samples_3d(*first, 0.1, true, goals, 0.5));
  const auto energy = solve_with(spec, adapted_size_samples_3d(*first, 0.0125, true));
  const double goal_true = true_probe_error_pct(*goal), energy_true = true_probe_error_pct(*energy);
  std::cout << "first " << first->dofs->n_dofs() << " unknowns: " << true_probe_error_pct(*first)
            << " % true, " << goals[0].error_pct << " % estimated\ngoal " << goal->dofs->n_dofs()
            << ": " << goal_true << " %, " << probe_goals_3d(*goal, quantities)[0].error_pct
            << " % estimated\nenergy alone " << energy->dofs->n_dofs() << ": " << energy_true
            << " %\n";
  EXPECT_LE(1.5 * goal->dofs->n_dofs(), energy->dofs->n_dofs());
  EXPECT_LT(goal_true, energy_true);
  for (const Run3D* run : {first.get(), goal.get()}) {
    const double estimate = probe_goals_3d(*run, quantities)[0].error_pct;
    const double effectivity = estimate / true_element_error_pct(*run);
    std::cout << run->dofs->n_dofs() << " unknowns: estimate " << estimate << " %, element field "
              << true_element_error_pct(*run) << " %, written " << true_probe_error_pct(*run)
              << " %\n";
    EXPECT_GT(effectivity, 1.0 / 3);
    EXPECT_LT(effectivity, 3.0);
    EXPECT_LE(true_probe_error_pct(*run), estimate);
    // The written table is the patch recovery, one order better than the element field:
    // measured 0.42x and 0.17x its error on the two meshes. Planted: the pipeline writing the
    // nodal averages (RecoveredB3D) instead: 0.62x and 0.81x -> fails.
    EXPECT_LT(true_probe_error_pct(*run), 0.5 * true_element_error_pct(*run));
  }
}

namespace {

// The sphere's whole r = 12 mm table (703 points, 10 deg steps) named to 0.1 %: scripts/
// benchmark.sh's issue 29 target (a), from the same coarse start.
CaseSpec sphere_table_spec() {
  std::ifstream in(test::example("3d/magnetized_sphere_probe_adaptive.yaml"));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text = std::regex_replace(text, std::regex("theta: \\[30, 60\\], phi: \\[0, 90\\]"),
                            "theta: [0, 180], phi: [0, 360]");
  text = std::regex_replace(text, std::regex("accuracy_pct: 0.5"), "accuracy_pct: 0.1");
  text = std::regex_replace(text, std::regex("max_unknowns: 1.0e6"), "max_unknowns: 3.0e6");
  return read_case(test::write_temp_case("adapt3d_probe_sphere_table.yaml", text));
}

// The loop from the coarse start, stopped after its first refinement (max_passes 2): that
// pass must reach the spec's accuracy by its own one-mesh estimate, the local error of the
// table (ProbeGoal3D), and in truth. The loop's own estimate is not asserted below the target
// here: it is floored by the table's change from the coarse pass (adapt_loop.hpp), and the
// coarse pass's patch-recovered table is 1 % off in its rms |B| (0.3080 against 0.3050 T),
// so the loop checks with a third pass what the second already met (its estimate is then at
// least that floor: asserted as the loop's rule).
void expect_one_jump(CaseSpec spec, std::size_t max_unknowns) {
  const double target = spec.adapt.accuracy_pct;
  spec.adapt.max_passes = 2;
  const auto run = run_adaptive_3d(spec, {});
  ASSERT_TRUE(run->adapt);
  const auto& passes = run->adapt->passes;
  ASSERT_EQ(passes.size(), 2u);
  const double local = probe_goals_3d(*run, resolve_adapt_quantities(spec)).at(0).error_pct;
  const double truth = true_probe_error_pct(*run), element_truth = true_element_error_pct(*run);
  std::cout << passes.back().unknowns << " unknowns: " << local << " % estimated (local), "
            << passes.back().quantity_error_pct.at(0) << " % (the loop's), " << truth
            << " % true (written), " << element_truth << " % true (element field)\n";
  EXPECT_LE(local, target);
  EXPECT_GE(passes.back().quantity_error_pct.at(0), local);
  EXPECT_LE(truth, target);
  // The estimate is the element field's local error (within issue 29's 3x both ways), and an
  // upper bound of the written, patch-recovered table's.
  EXPECT_LE(truth, local);
  EXPECT_LE(element_truth, 3 * local);
  EXPECT_LE(local, 3 * element_truth);
  // Not overshooting: a pass whose local estimate lands at e below its aim spent about
  // (aim / e)^(3/p) times the tets it needed around the points; more than 3x below the aim is
  // a 5x waste.
  std::cout << "landed at " << local << " % (aim " << aim_below_target * target << " %)\n";
  EXPECT_GE(local, aim_below_target * target / 3);
  EXPECT_LE(std::size_t(passes.back().unknowns), max_unknowns);
}

} // namespace

// The probe points as sources sized in one jump (adapt3d.hpp): from the 22k-unknown start
// the example's patch (40 points, 0.5 %) is reached on the first refinement. Measured: pass 2
// 63.8k unknowns, 0.30 % estimated, 0.055 % true (the element field 0.34 %); the zone rule
// alone took 3 passes to 96.0k (0.296 % estimated). Planted: the point sources left out;
// their exponent 2/p instead of 1/p (the jump squared: 234k unknowns, 0.034 % true, 0.28 %
// estimated: the unknowns, the effectivity and the landing bound fail).
TEST(Adapt3DProbe, PointSourcesReachThePatchInOneJump) {
  expect_one_jump(probe_spec(), 80000);
}

// Target (a) of issue 29: the whole r = 12 mm table to 0.1 %. Measured: pass 2 807k
// unknowns, 0.064 % estimated, 0.031 % true (the element field 0.073 %); the zone rule alone
// took 4 passes to 1.33M. Asserted below 1.0M: the zone rule alone
// would need 1.33M. Long (15-40 s on a shared machine).
TEST(Adapt3DProbe, LongSphereTableToAPointOnePercentInOneJump) {
  expect_one_jump(sphere_table_spec(), 1000000);
}
