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

// rms |B_h - B| over the table's points relative to its rms |B| (%).
double true_probe_error_pct(const Run3D& run) {
  const ProbeTable& t = run.probes.at(0);
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

std::unique_ptr<Run3D> solve_with(const CaseSpec& spec, std::vector<SizeSample3D> sizes) {
  return test::solve_with_sizes_3d(spec, std::move(sizes));
}

} // namespace

// One pass planned from the same coarse first mesh two ways: with the probe's goal (energy
// aimed at 0.1 %, the probe at 0.5 % rms pointwise) and by the energy alone, aimed low enough
// (0.0125 %) to spend more unknowns. Measured (order 2): first mesh 22.1k unknowns, probe
// error 2.17 % true, 4.04 % estimated; goal 69.3k unknowns, 0.46 % true, 0.62 % estimated
// (before the probe points were sources: 66.1k, 0.70 %, 1.03 %); energy alone 107k unknowns,
// 0.75 % true (at 84k 0.99 %, at 139k 0.61 %). So the goal beats the energy rule's error with
// 1.5x fewer unknowns; asserted: 1.5x fewer and a lower error (the meshes are deterministic).
// Planted: the probe rule not applied (apply_probe_rule returning at once): the goal pass is
// the energy's 0.1 % pass, 52k unknowns and 1.41 % true, and the error comparison fails.
// The estimate's effectivity (estimated / true, both rms over the 40 points) is held to
// issue 29's 3x both ways on both meshes: it is the tet's rms of |B* - B_h| where the probe
// reads the recovered nodal B, an upper-side estimate (measured 1.86 and 1.35). Planted: mu
// dropped from e_K (1658x).
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
    const double effectivity =
        probe_goals_3d(*run, quantities)[0].error_pct / true_probe_error_pct(*run);
    EXPECT_GT(effectivity, 1.0 / 3);
    EXPECT_LT(effectivity, 3.0);
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

// The loop from the coarse start to the spec's accuracy: the passes it took, the true error
// of the last one and its estimate, both honest.
void expect_one_jump(const CaseSpec& spec, std::size_t max_unknowns) {
  const double target = spec.adapt.accuracy_pct;
  const auto run = run_adaptive_3d(spec, {});
  ASSERT_TRUE(run->adapt);
  const auto& passes = run->adapt->passes;
  const double estimated = passes.back().quantity_error_pct.at(0),
               truth = true_probe_error_pct(*run);
  std::cout << passes.size() << " passes, " << passes.back().unknowns << " unknowns: " << estimated
            << " % estimated, " << truth << " % true\n";
  EXPECT_TRUE(run->adapt->converged);
  EXPECT_EQ(passes.size(), 2u);
  EXPECT_LE(estimated, target);
  EXPECT_LE(truth, target);
  EXPECT_LE(truth, 3 * estimated);
  EXPECT_LE(estimated, 3 * truth);
  // Not overshooting: a pass whose local estimate (the table's e_K, ProbeGoal3D) lands at e
  // below its aim spent about (aim / e)^(3/p) times the tets it needed around the points; more
  // than 3x below the aim is a 5x waste. (The loop's estimate is floored by the change from
  // the coarse pass and cannot show it.)
  const double landed = probe_goals_3d(*run, resolve_adapt_quantities(spec)).at(0).error_pct;
  std::cout << "landed at " << landed << " % (aim " << aim_below_target * target << " %)\n";
  EXPECT_GE(landed, aim_below_target * target / 3);
  EXPECT_LE(std::size_t(passes.back().unknowns), max_unknowns);
}

} // namespace

// The probe points as sources sized in one jump (adapt3d.hpp): from the 22k-unknown start
// the example's patch (40 points, 0.5 %) is reached on the first refinement. Measured: pass 2
// 64.0k unknowns, 0.325 % estimated, 0.24 % true (rms of |B_h - B| over |B|); the zone rule
// alone took 3 passes to 96.0k (0.296 % estimated). Planted: the point sources left out (3
// passes, 96.0k: the pass count and the unknowns fail); their exponent 2/p instead of 1/p (the
// jump squared: 234k unknowns, 0.034 % true, 0.28 % estimated: the unknowns, the effectivity
// and the landing bound fail).
TEST(Adapt3DProbe, PointSourcesReachThePatchInOneJump) {
  expect_one_jump(probe_spec(), 80000);
}

// Target (a) of issue 29: the whole r = 12 mm table to 0.1 %. Measured: 2 passes, 814k
// unknowns, 0.076 % estimated, 0.056-0.061 % true per component (15 s CPU on 2 cores; the
// zone rule alone: 4 passes to 1.33M, 55 s CPU). Asserted below 1.0M: the zone rule alone
// would need 1.33M. Long (15-40 s on a shared machine).
TEST(Adapt3DProbe, LongSphereTableToAPointOnePercentInOneJump) {
  expect_one_jump(sphere_table_spec(), 1000000);
}
