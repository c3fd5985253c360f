// Goal-oriented 3D refinement for a stress-tensor torque (pipeline/force_goal3d.hpp): two
// uniformly magnetized spheres, whose torque is exactly the dipole-dipole one (the field
// outside a uniformly magnetized sphere is a dipole's), refined for the torque on the fixed
// one from a coarse first mesh whose stress sphere carries no probe refinement.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "core/constants.hpp"
#include "pipeline/adapt3d.hpp"
#include "pipeline/force_goal3d.hpp"
#include "tests/case_helpers.hpp"

using namespace magfem;

namespace {

// examples/3d/two_spheres.yaml (radius 5 mm, B_r 1.2 T along z at the origin; radius 4 mm
// along x at (0, 0, 14) mm; stress sphere of radius 7.5 mm about the origin) without its
// stress-sphere refinement (mesh.probe_size), the torque named in adapt.quantities.
CaseSpec spheres_spec() {
  CaseSpec spec = read_case(test::example("3d/two_spheres.yaml"));
  spec.geometry3d.options.probe_size = 0;
  spec.adapt.accuracy_pct = 0.5;
  spec.adapt.quantities = {"forces.fixed.torque"};
  return spec;
}

// |torque| on the fixed sphere: m_a x B_b(0) = mu0 m_a m_b / (4 pi d^3) (N m).
double exact_torque(double d_m) {
  const double m_a = 4.0 / 3.0 * pi * std::pow(0.005, 3) * 1.2 / mu0;
  const double m_b = 4.0 / 3.0 * pi * std::pow(0.004, 3) * 1.2 / mu0;
  return mu0 / (4 * pi) * m_a * m_b / std::pow(d_m, 3);
}

double true_error_pct(const Run3D& run) {
  const double exact = exact_torque(0.014);
  return 100 * std::abs(run.forces.at(0).torque.norm() - exact) / exact;
}

double estimated_error_pct(const Run3D& run) {
  return 100 * run.forces.at(0).torque_err.norm() / run.forces.at(0).torque.norm();
}

// At --mesh-scale 1.5: a coarse first mesh (80k unknowns).
std::unique_ptr<Run3D> solve_with(const CaseSpec& spec, std::vector<SizeSample3D> sizes) {
  RunOverrides ov;
  ov.mesh_scale = 1.5;
  return test::solve_with_sizes_3d(spec, std::move(sizes), ov);
}

} // namespace

// One pass from the same first mesh two ways: the torque's goal (its surface's sources on the
// case's sizes, as adapt3d plans once the energy is within its target) and the energy rule's
// push that the loop asks for then (a quarter of the energy error reached). Measured (order
// 2, --mesh-scale 1.5): first mesh 80.3k unknowns, torque 0.334 % true, 1.04 % estimated,
// energy 0.050 %; goal 144k unknowns, 0.080 % true, 0.172 % estimated (16.7k sources); energy
// push 231k unknowns, 0.178 % true. On another machine (2026-11-27, same code and first mesh)
// the goal was 0.117 % and the energy push 0.0011 %: errors of 0.1 % on these meshes change
// sign with the last bits of the input (glibc's libm picks FMA variants per CPU), so which
// of two such errors is smaller is luck, not the method, and is not asserted. Asserted: the
// goal pass at least halves the first mesh's torque error (measured 0.334 -> 0.080 and 0.117
// %) with fewer unknowns than the energy push, every source on the stress sphere, and the
// torque's one-mesh estimate honest (true <= 3x estimated) on both of the goal's meshes.
// Planted: the size rule's exponent negated (sources no finer than their tets: goal 80.1k,
// 0.277 %) fails the halving; the element B replaced by the average (no local differences,
// no source) fails at once.
TEST(Adapt3DForce, GoalRefinesOnTheStressSphereAndHalvesTheTorqueErrorWithFewerUnknowns) {
  const CaseSpec spec = spheres_spec();
  const auto quantities = resolve_adapt_quantities(spec);
  const auto first = solve_with(spec, {});
  const double radius = spec.forces.at(0).radius;
  const std::vector<SizeSample3D> sources = force_goal_sources_3d(
      *first, quantities, spec.adapt.accuracy_pct, first->mesh.tet_size, 1e-9);
  ASSERT_FALSE(sources.empty());
  double h_max = 0;
  for (double h : first->mesh.tet_size)
    h_max = std::max(h_max, h);
  for (const auto& s : sources) {
    EXPECT_NEAR(s.x.norm(), radius, 1e-9 * radius);
    EXPECT_GE(s.h, min_force_ratio * 0.999 * 1e-3); // no tet of this mesh is below 1 mm
    EXPECT_LT(s.h, h_max);
  }
  const auto goal = solve_with(spec, sources);
  const double push = 0.25 * first->error_estimate.energy_error_pct;
  const auto energy = solve_with(spec, adapted_size_samples_3d(*first, push, false));
  std::cout << "first " << first->dofs->n_dofs() << " unknowns: torque " << true_error_pct(*first)
            << " % true, " << estimated_error_pct(*first) << " % estimated, energy "
            << first->error_estimate.energy_error_pct << " %; " << sources.size()
            << " sources\ngoal " << goal->dofs->n_dofs() << ": " << true_error_pct(*goal)
            << " % true, " << estimated_error_pct(*goal) << " % estimated\nenergy push "
            << energy->dofs->n_dofs() << ": " << true_error_pct(*energy) << " % true\n";
  EXPECT_LT(goal->dofs->n_dofs(), energy->dofs->n_dofs());
  EXPECT_LE(true_error_pct(*goal), 0.5 * true_error_pct(*first));
  for (const Run3D* run : {first.get(), goal.get()})
    EXPECT_LE(true_error_pct(*run), 3 * estimated_error_pct(*run));
}

// The loop with the goal on the same spheres (from --mesh-scale 2, to 0.35 %): it reaches the
// torque's target, every pass refines the one before, and the estimate of every pass that has
// one is honest. Measured: 51.7k, 151k, 271k unknowns; torque 0.180, 0.279, 0.035 % true,
// 0.333, 0.315 % estimated (passes 2, 3; to 0.3 % a fourth pass, 440k, 0.0558 %). Planted:
// the size rule's exponent negated (no source finer than its tet) fails.
TEST(Adapt3DForce, LoopReachesTheTorqueAndEveryPassRefines) {
  CaseSpec spec = spheres_spec();
  spec.adapt.accuracy_pct = 0.35;
  spec.adapt.max_passes = 4;
  spec.adapt.max_unknowns = 2e6;
  RunOverrides ov;
  ov.mesh_scale = 2;
  const auto run = run_adaptive_3d(spec, ov);
  const AdaptHistory& h = *run->adapt;
  for (const auto& p : h.passes)
    std::cout << "pass " << p.pass << ": " << p.unknowns << " unknowns, torque "
              << p.quantities[0].second << ", estimated " << p.quantity_error_pct[0] << " %\n";
  EXPECT_TRUE(h.converged) << h.stop_reason;
  ASSERT_GE(h.passes.size(), 2u);
  const double exact = exact_torque(0.014);
  for (std::size_t k = 1; k < h.passes.size(); ++k) {
    EXPECT_GT(h.passes[k].unknowns, h.passes[k - 1].unknowns) << "pass " << k + 1;
    const double truth = 100 * std::abs(h.passes[k].quantities[0].second - exact) / exact;
    EXPECT_LE(truth, 3 * h.passes[k].quantity_error_pct[0]) << "pass " << k + 1;
  }
}

// scripts/benchmark.sh's issue 29 target (b): examples/3d/compensator_adaptive.yaml as it is,
// the torque on the inner magnet at 90 deg to 0.2 %, estimated and true: the charge model's
// exact 12.3653 N m (`magfem sweep examples/3d/compensator_table42.yaml --rotate outer --axis
// y --angles 90 --analytic`, docs/example_accuracy.md). Minutes on 2 cores: label long.
TEST(Adapt3DForce, LongCompensatorTorqueToAPointTwoPercent) {
  const CaseSpec spec = read_case(test::example("3d/compensator_adaptive.yaml"));
  const auto run = run_adaptive_3d(spec, {});
  const AdaptHistory& h = *run->adapt;
  constexpr double exact = 12.3653;
  for (const auto& p : h.passes)
    std::cout << "pass " << p.pass << ": " << p.unknowns << " unknowns, torque "
              << p.quantities[0].second << " (true "
              << 100 * std::abs(p.quantities[0].second - exact) / exact << " %), estimated "
              << p.quantity_error_pct[0] << " %, " << p.seconds << " s\n";
  ASSERT_TRUE(h.converged) << h.stop_reason;
  const auto& last = h.passes.back();
  const double truth = 100 * std::abs(last.quantities[0].second - exact) / exact;
  EXPECT_LE(truth, spec.adapt.accuracy_pct);
  EXPECT_LE(last.quantity_error_pct[0], spec.adapt.accuracy_pct);
  for (std::size_t k = 1; k < h.passes.size(); ++k) {
    const double t = 100 * std::abs(h.passes[k].quantities[0].second - exact) / exact;
    EXPECT_LE(t, 3 * h.passes[k].quantity_error_pct[0]) << "pass " << k + 1;
  }
}
