// The error estimate of 2D and axisymmetric solutions (postproc/error_estimate2d) is honest:
// on three exact cases its energy error estimate stays within 0.3..3 of the true energy error
// on every pass of a short adaptive run.
//
// The true error. The passes of an adaptive run mesh the same polygons (mesher2d.hpp,
// refine_sizes), so the discrete problem differs from pass to pass only by the mesh. Its
// energy error is |W_ref - W_h| / W_ref, with W_ref from the same polygons on a much finer
// mesh (reference_energy). The outer circles are the exception: vertices added on them move
// onto the circle; the cases keep their chord tolerance small enough that this stays below
// the errors measured (at 0.005 mm the sphere's second pass read an effectivity of 0.2).
// For a linear Galerkin solution |W - W_h| = ||B - B_h||_E^2 / 2 exactly, which is what the
// estimate's energy_error_pct measures. Each reference is also checked against the closed
// form of the smooth geometry, to the polygon's own error (the chord tolerance).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "analytic/coil_closed_forms.hpp"
#include "core/constants.hpp"
#include "pipeline/adapt2d.hpp"
#include "tests/case_helpers.hpp"

using namespace magfem;

namespace {

// Diametrically magnetized cylinder (radius 10 mm, B_r 1 T, mu_r 1) in open space, planar.
// Exact energy per metre: (B_r^2 / mu0) pi a^2 / 4.
const char* cylinder_case = R"(
unit: mm
materials:
  pm: {kind: magnet, B_r: 1.0, mu_r: 1.0}
regions:
  - {name: magnet, shape: disk, center: [0, 0], radius: 10, material: pm,
     magnetization: {type: parallel, angle: 0}, mesh_size: 4.0}
boundary: {type: open, radius: 25, shell_ratio: 1.5}
mesh: {size: 8.0, chord_tolerance: 0.01}
solver: {order: 2}
)";

// Uniformly magnetized sphere (radius 10 mm, B_r 1 T along z), axisymmetric. Exact energy
// 3 (mu0/2) (B_r / (3 mu0))^2 (4/3) pi a^3 (inside, and twice that outside).
const char* sphere_case = R"(
dimension: axi
unit: mm
materials:
  pm: {kind: magnet, B_r: 1.0, mu_r: 1.0}
regions:
  - {name: ball, shape: disk, center: [0, 0], radius: 10, material: pm,
     magnetization: {type: parallel}, mesh_size: 4.0}
boundary: {type: open, radius: 30, shell_ratio: 1.5}
mesh: {size: 8.0, chord_tolerance: 0.001}
solver: {order: 2}
)";

// The solenoid around a linear iron core (mu_r 200) that sticks out of the winding: B_t jumps
// by 200 across the core's faces, where the recovery must stay on each side and H(B*) must use
// each side's law. No closed form: the same-polygon reference alone. (The iron carries little
// of the error: an indicator using the air's reluctivity in the iron too still read 1.15 and
// 1.36 here, so this case guards the recovery across the faces, not the law.)
const char* cored_solenoid_case = R"(
dimension: axi
unit: mm
materials:
  iron: {kind: linear, mu_r: 200}
regions:
  - {name: winding, shape: rectangle, center: [12.5, 0], width: 5, height: 30, turns: 500,
     current: 2.0, mesh_size: 4.0}
  - {name: core, shape: rectangle, center: [4, 5], width: 8, height: 40, material: iron,
     mesh_size: 4.0}
boundary: {type: open, radius: 50, shell_ratio: 1.5}
mesh: {size: 8.0, chord_tolerance: 0.002}
solver: {order: 2}
)";

constexpr double a = 0.010, B_r = 1.0; // the magnets: metres, tesla

double exact_solenoid_energy() {
  const double l = coaxial_coil_self_inductance(CoaxialCoil{0.010, 0.015, -0.015, 0.015, 500});
  return 0.5 * l * 2.0 * 2.0;
}
double exact_cylinder_energy() {
  return B_r * B_r / mu0 * pi * a * a / 4;
}
double exact_sphere_energy() {
  return 3 * 0.5 * mu0 * std::pow(B_r / (3 * mu0), 2) * 4.0 / 3 * pi * a * a * a;
}

// The energy of the same polygons on a much finer mesh: the adaptive loop run on, to a tenth
// of the last pass's estimated error (it lands further below: each pass overshoots), finer
// than the tested passes everywhere, including at the iron corners, where uniform refinement
// gains little. Its own estimate is printed: it must be far below the errors it measures.
double reference_energy(CaseSpec spec, const Run2D& last) {
  spec.adapt.accuracy_pct = last.error_estimate.energy_error_pct / 10;
  spec.adapt.max_passes = 3;
  const auto ref = run_adaptive_2d(spec, {});
  std::cout << "  reference: " << ref->dofs->n_dofs() << " unknowns, estimated error "
            << ref->error_estimate.energy_error_pct << " %\n";
  // A reference within a quarter of the tested error biases an effectivity by 25 % at most.
  EXPECT_LT(ref->error_estimate.energy_error_pct, last.error_estimate.energy_error_pct / 4);
  return ref->energy.total_J_per_m;
}

struct PassCheck {
  double estimated_pct, true_pct;
};

// A short adaptive run of the case toward accuracy_pct, every pass's estimated and true
// energy error.
std::vector<PassCheck> adaptive_effectivity(const std::string& name, const char* text, double exact,
                                            double accuracy_pct) {
  CaseSpec spec = read_case(test::write_temp_case(name + ".yaml", text));
  spec.adapt.accuracy_pct = accuracy_pct;
  spec.adapt.max_passes = 2;
  const auto run = run_adaptive_2d(spec, {});
  const double w_ref = reference_energy(spec, *run);
  // The polygons' own error against the smooth geometry: a polygon of sagitta s inside a
  // circle of radius a misses (2/3) s / a of its area; 3 s / a leaves a margin.
  const double s = spec.geometry2d.options.chord_tolerance;
  if (exact > 0) { // 0: no closed form
    std::cout << "  reference vs closed form: " << (w_ref - exact) / exact << "\n";
    EXPECT_NEAR(w_ref, exact, 3 * s / a * exact) << name;
  }
  std::vector<PassCheck> out;
  for (const auto& p : run->adapt->passes) {
    const double w = p.energy_J;
    out.push_back({p.energy_error_pct, 100 * std::abs(w_ref - w) / w_ref});
    std::cout << name << " pass " << p.pass << ": " << p.unknowns << " unknowns, estimated "
              << out.back().estimated_pct << " %, true " << out.back().true_pct
              << " %, effectivity " << out.back().estimated_pct / out.back().true_pct << ", "
              << p.seconds << " s\n";
  }
  return out;
}

// A diametric magnet (radius 10 mm) in a thick keeper ring of permeable material (mu_r 8,
// radii 10..20 mm) in open space, planar: the ring carries a good part of the field and of
// the error, so the estimate depends on the ring's law. It guards what the cored solenoid
// does not: an indicator that uses the air's reluctivity in the ring too (mu0 for mu) read
// effectivities 7.7 and 6.5 here (planted and measured), the correct one 1.15 and 1.41.
const char* keeper_case = R"(
unit: mm
materials:
  pm: {kind: magnet, B_r: 1.0, mu_r: 1.0}
  keeper: {kind: linear, mu_r: 8}
regions:
  - {name: magnet, shape: disk, center: [0, 0], radius: 10, material: pm,
     magnetization: {type: parallel, angle: 0}, mesh_size: 4.0}
  - {name: ring, shape: annulus, center: [0, 0], r_inner: 10, r_outer: 20, material: keeper,
     mesh_size: 4.0}
boundary: {type: open, radius: 35, shell_ratio: 1.5}
mesh: {size: 8.0, chord_tolerance: 0.01}
solver: {order: 2}
)";

// The issue's bound for the energy estimate's effectivity (estimated / true), on every pass.
// In the energy norm that is 0.55..1.7: the ZZ recovery is asymptotically exact only on
// smooth solutions, and these have corners (winding) and material interfaces (magnets).
// Inside that bound, a guard on the recovery itself: 0.7..2 (measured 0.89-1.53 over the five
// cases and both passes). A recovery whose patches at the outline's vertices reach a second
// ring (at least 4 triangles instead of 3, patch_recovery2d.hpp) smooths over corners and read
// 1.82-2.23 on the solenoids and the keeper, still inside the issue's bound.
void expect_effectivity(const std::vector<PassCheck>& passes) {
  for (std::size_t i = 0; i < passes.size(); ++i) {
    const double eff = passes[i].estimated_pct / passes[i].true_pct;
    EXPECT_GT(eff, 0.3) << "pass " << i + 1;
    EXPECT_LT(eff, 3.0) << "pass " << i + 1;
    EXPECT_GT(eff, 0.7) << "pass " << i + 1 << ": the recovery's guard";
    EXPECT_LT(eff, 2.0) << "pass " << i + 1 << ": the recovery's guard";
  }
}

} // namespace

TEST(ErrorEstimate2D, AxisymmetricSolenoidEffectivity) {
  expect_effectivity(adaptive_effectivity("ee_solenoid", test::coarse_solenoid_case,
                                          exact_solenoid_energy(), 1e-3));
}

TEST(ErrorEstimate2D, PlanarDiametricCylinderEffectivity) {
  expect_effectivity(
      adaptive_effectivity("ee_cylinder", cylinder_case, exact_cylinder_energy(), 5e-3));
}

TEST(ErrorEstimate2D, AxisymmetricMagnetizedSphereEffectivity) {
  expect_effectivity(adaptive_effectivity("ee_sphere", sphere_case, exact_sphere_energy(), 3e-3));
}

TEST(ErrorEstimate2D, PlanarMagnetInAPermeableRingEffectivity) {
  expect_effectivity(adaptive_effectivity("ee_keeper", keeper_case, 0.0, 5e-3));
}

TEST(ErrorEstimate2D, AxisymmetricSolenoidWithIronCoreEffectivity) {
  expect_effectivity(adaptive_effectivity("ee_cored", cored_solenoid_case, 0.0, 1e-3));
}
