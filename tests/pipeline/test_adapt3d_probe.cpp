// Goal-oriented 3D refinement for a named probe table (pipeline/adapt3d.cpp ProbeGoal3D): on
// the uniformly magnetized sphere (exact field outside: the point dipole B_r a^3 / 3), a
// patch of probe points near the sphere makes the marking refine around them.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

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
  CaseSpec s = spec;
  s.adapt = {};
  if (!sizes.empty()) // none: the case's own mesh
    s.geometry3d.options.refine_sizes =
        std::make_shared<const std::vector<SizeSample3D>>(std::move(sizes));
  return run_case_3d(s, {});
}

} // namespace

// One pass planned from the same coarse first mesh two ways: with the probe's goal (energy
// aimed at 0.1 %, the probe at 0.5 % rms pointwise) and by the energy alone, aimed low enough
// (0.0125 %) to spend more unknowns. Measured (order 2): first mesh 22.1k unknowns, probe
// error 2.17 % true, 4.04 % estimated; goal 66.1k unknowns, 0.70 % true, 1.03 % estimated;
// energy alone 107k unknowns, 0.75 % true (at 84k 0.99 %, at 139k 0.61 %). So the goal
// reaches the energy rule's error with 1.6x fewer unknowns; asserted: 1.5x fewer and a lower
// error (margins 8 % and 7 %; the meshes are deterministic). Planted: the probe rule not
// applied (apply_probe_rule returning at once): the goal pass is the energy's 0.1 % pass, 52k
// unknowns and 1.41 % true, and the error comparison fails.
// The estimate's effectivity (estimated / true, both rms over the 40 points) is held to
// issue 29's 3x both ways on both meshes: it is the tet's rms of |B* - B_h| where the probe
// reads the recovered nodal B, an upper-side estimate (measured 1.86 and 1.46). Planted: mu
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
