// 3D coils through the whole pipeline (case file -> two-potential FE -> Lorentz force, flux
// linkage, inductance), checked against exact answers and identities:
//   - a coil over a permeable plate against its image coil (exact for a half-space);
//   - energy identity W = L I^2 / 2 and flux linkage lambda = L I for a linear case, three
//     independent integrals of the same field (energy, reciprocity, sensitivity solve);
//   - action = reaction between a magnet (stress tensor) and a coil (Lorentz force);
//   - bad coil input: exit-2 errors naming file, line and field.
// The coil-over-plate tests share one solve of the example at mesh scale 2 (116k P2
// unknowns, ~20 s with the inductance solve). They were switched off for minutes of CG until the
// example's air cylinder was lifted from 0.5 mm to 2 mm above the plate with one gap layer
// (at 0.5 mm and 3 layers the gap alone asked for 12 M tetrahedra).
#include <gtest/gtest.h>

#include <cmath>

#include "analytic/coil_closed_forms.hpp"
#include "core/constants.hpp"
#include "core/input_error.hpp"
#include "pipeline/run3d.hpp"
#include "pipeline/run_analytic.hpp"
#include "tests/case_helpers.hpp"

using namespace magfem;

namespace {

const ForceResult& force(const Run3D& run, const std::string& name) {
  for (const auto& f : run.forces)
    if (f.name == name)
      return f;
  throw std::runtime_error("no force " + name);
}

// The example solved once for the tests that use it.
const Run3D& coil_over_plate() {
  static const auto run = [] {
    RunOverrides o;
    o.mesh_scale = 2;
    return run_case_3d(read_case(test::example("3d/coil_over_plate.yaml")), o);
  }();
  return *run;
}

} // namespace

// Image solution: a plate of mu_r 1000 under the coil acts as the half-space z < 0, whose
// field in air is the coil's plus that of the mirror coil carrying k = (mu_r-1)/(mu_r+1) of
// its current. Tolerance 2 %: the plate is finite (160 x 160 x 20 mm for a 10 mm coil, which
// the image of a half-space does not see; estimated below 1 %) and the FE error of the
// P2 field sampled in the bundle (measured: see the printed figures).
TEST(Coils3D, CoilOverPlateMatchesTheImageForce) {
  const Run3D* run = &coil_over_plate();
  const double mu_r = 1000, k = (mu_r - 1) / (mu_r + 1);
  const CoaxialCoil coil{6e-3, 10e-3, 5e-3, 9e-3, 200};
  const CoaxialCoil image{6e-3, 10e-3, -9e-3, -5e-3, 200};
  const double exact = coaxial_axial_force(image, coil, k * 1.0, 1.0);
  const double fe = force(*run, "coil").force.z();
  std::printf("coil over plate: F_z FE %.6g N, image %.6g N, difference %.3f %%\n", fe, exact,
              100 * (fe - exact) / exact);
  EXPECT_LT(exact, 0); // attraction
  EXPECT_NEAR(fe, exact, 0.02 * std::abs(exact));
  // Symmetry: no lateral force, no torque about the axis.
  EXPECT_LT(std::hypot(force(*run, "coil").force.x(), force(*run, "coil").force.y()),
            1e-2 * std::abs(exact));
}

// Linear case without magnets: the field energy (1/2 integral B.H over all space), the
// reciprocity flux linkage (integral B.h) and the inductance from the sensitivity solve are
// three computations of one quantity. They share the FE field, so they agree far better
// than the field's own error: 0.5 % allows for the quadrature of the coil field's kinks at the
// bundle surface, which the mesh does not follow (measured below 0.2 %).
TEST(Coils3D, EnergyFluxLinkageAndInductanceAgree) {
  const Run3D* run = &coil_over_plate();
  ASSERT_EQ(run->coil_results.coils.size(), 1u);
  const auto& c = run->coil_results.coils[0];
  const double l = run->coil_results.inductance_H(0, 0);
  const double i = c.current_A;
  std::printf("W %.6g J, L I^2/2 %.6g J, lambda %.6g Wb, L I %.6g Wb\n", run->energy.total_J,
              0.5 * l * i * i, c.flux_linkage_Wb, l * i);
  EXPECT_GT(l, 0);
  EXPECT_NEAR(run->energy.total_J, 0.5 * l * i * i, 5e-3 * run->energy.total_J);
  EXPECT_NEAR(c.flux_linkage_Wb, l * i, 5e-3 * std::abs(c.flux_linkage_Wb));
}

// A thick solenoid in air (r 10..15 mm, length 30 mm, 500 turns, 2 A): its inductance from the
// sensitivity solve against Maxwell's formula integrated over the cross-section
// (analytic/coil_closed_forms.hpp, converged to 1e-13). In air the reduced potential is zero
// and the field is the source field, so the FE inductance measures the energy and linkage
// quadratures of H_s over the mesh and the shell (and the source field's own 1e-4 tolerance
// near the bundle), not a discretisation of phi. Measured against the exact 3.148399 mH:
// -7.1e-6 at 42k P2 unknowns (this mesh, ~6 s of CPU), +8.5e-5 at 118k, -2.7e-5 at 301k: no
// trend, the quadrature level. Tolerance 5e-4. A factor 2 in the energy, a wrong turns count
// or current per turn would be off by 100 % or more.
TEST(Coils3D, ThickSolenoidInductanceEqualsMaxwellsFormula) {
  const auto path = test::write_temp_case("coils3d_solenoid_in_air.yaml", R"(dimension: 3
unit: mm
regions:
  - {name: bore, shape: cylinder, r_outer: 5, height: 10, material: air,
     placement: {translate: [0, 0, -5]}}
coils:
  - {name: coil, shape: solenoid, r_inner: 10, r_outer: 15, length: 30, center: [0, 0, 0],
     axis: [0, 0, 1], turns: 500, current: 2}
boundary: {type: open, radius: 40}
mesh: {size: 12, chord_tolerance: 1}
solver: {order: 2}
output: {vtu: false}
)");
  const auto run = run_case_3d(read_case(path));
  ASSERT_EQ(run->coil_results.coils.size(), 1u);
  const double l = run->coil_results.inductance_H(0, 0);
  const double exact = coaxial_coil_self_inductance({10e-3, 15e-3, -15e-3, 15e-3, 500});
  const auto& c = run->coil_results.coils[0];
  std::printf("solenoid in air: L FE %.7g H, Maxwell %.7g H (%+.1e), %ld unknowns\n", l, exact,
              (l - exact) / exact, static_cast<long>(run->dofs->n_dofs()));
  EXPECT_NEAR(l, exact, 5e-4 * exact);
  // Energy, reciprocity linkage and sensitivity inductance: in air all three integrate the
  // same source field (measured equal to 1e-15); 1e-9 leaves room for summation order only.
  EXPECT_NEAR(run->energy.total_J, 0.5 * l * c.current_A * c.current_A, 1e-9 * run->energy.total_J);
  EXPECT_NEAR(c.flux_linkage_Wb, l * c.current_A, 1e-9 * c.flux_linkage_Wb);
}

// Two coaxial coils over the permeable plate (coil_over_plate's plate, mesh scale 4): the 2 x 2
// inductance matrix from the block solve (both coils' sensitivities in one simultaneous CG,
// solver/simultaneous_pcg.hpp). Checked by
//   - reciprocity, L_12 = L_21: an identity of the symmetric tangent, exact but for the
//     sensitivity solves' error (relative residual 1e-5, with the variational correction of
//     solver/current_sensitivity3d.hpp) and the plate's total-potential discretization:
//     1e-6 of the largest entry (measured 1.6e-8; a column swapped or dropped breaks it by
//     O(1));
//   - the image solution: over a half-space of mu_r 1000, L_ij = M(i, j) + k M(i, j'),
//     j' the image of coil j, k = (mu_r - 1)/(mu_r + 1) (self terms with Maxwell's thick-coil
//     formula). 0.5 %: the finite plate and the coarse mesh's error in the plate's part, a
//     third of each entry (measured -0.05 to +0.07 %; a wrong turns count, current scale or a
//     lost image term is off by 10 % or more).
TEST(Coils3D, TwoCoaxialCoilsInductanceMatrixIsSymmetricAndTheImages) {
  const auto path = test::write_temp_case("coils3d_two_coils_over_plate.yaml", R"(dimension: 3
unit: mm
materials:
  iron1000: {kind: linear, mu_r: 1000}
regions:
  - {name: plate, shape: box, size: [160, 160, 20], material: iron1000,
     placement: {translate: [0, 0, -10]}, mesh_size: 12}
  - {name: near_coil, shape: cylinder, r_outer: 16, height: 18, material: air,
     placement: {translate: [0, 0, 2]}, mesh_size: 1.5}
coils:
  - {name: low, shape: solenoid, r_inner: 6, r_outer: 10, length: 4, center: [0, 0, 7],
     turns: 200, current: 1}
  - {name: high, shape: solenoid, r_inner: 4, r_outer: 7, length: 3, center: [0, 0, 14.5],
     turns: 100, current: 0.5}
boundary: {type: open, radius: 130}
mesh: {size: 20, chord_tolerance: 0.1, gap_layers: 1}
solver: {order: 2}
output: {vtu: false}
)");
  RunOverrides o;
  o.mesh_scale = 4;
  const auto run = run_case_3d(read_case(path), o);
  const Eigen::MatrixXd& l = run->coil_results.inductance_H;
  ASSERT_EQ(l.rows(), 2);
  ASSERT_EQ(l.cols(), 2);
  const double mu_r = 1000, k = (mu_r - 1) / (mu_r + 1);
  const CoaxialCoil low{6e-3, 10e-3, 5e-3, 9e-3, 200}, low_image{6e-3, 10e-3, -9e-3, -5e-3, 200};
  const CoaxialCoil high{4e-3, 7e-3, 13e-3, 16e-3, 100},
      high_image{4e-3, 7e-3, -16e-3, -13e-3, 100};
  Eigen::Matrix2d exact;
  exact(0, 0) = coaxial_coil_self_inductance(low) + k * coaxial_mutual_inductance(low, low_image);
  exact(1, 1) =
      coaxial_coil_self_inductance(high) + k * coaxial_mutual_inductance(high, high_image);
  exact(0, 1) = exact(1, 0) =
      coaxial_mutual_inductance(low, high) + k * coaxial_mutual_inductance(low, high_image);
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      std::printf("L_%d%d FE %.7g H, images %.7g H (%+.2f %%)\n", i + 1, j + 1, l(i, j),
                  exact(i, j), 100 * (l(i, j) - exact(i, j)) / exact(i, j));
      EXPECT_NEAR(l(i, j), exact(i, j), 5e-3 * exact(i, j));
    }
  std::printf("reciprocity: |L_12 - L_21| %.2e of the largest entry\n",
              std::abs(l(0, 1) - l(1, 0)) / l.cwiseAbs().maxCoeff());
  EXPECT_NEAR(l(0, 1), l(1, 0), 1e-6 * l.cwiseAbs().maxCoeff());
}

// Action = reaction: the Lorentz force on the coil from the magnet's field equals minus the
// stress-tensor force on the magnet (a sphere around it, in air). At mesh scale 2.5 (150k
// P2 unknowns, ~20 s) the stress tensor's two spheres differ by 0.46 % and the two methods
// by 0.29 % (at the example's own mesh: 0.09 % and 0.07 %); 1 % bounds that error. A wrong
// sign of J, of H_s or of the self-field subtraction changes the coil force by far more.
TEST(Coils3D, MagnetAndCoilForcesBalance) {
  RunOverrides coarse;
  coarse.mesh_scale = 2.5;
  auto run = run_case_3d(read_case(test::example("3d/coil_and_magnet.yaml")), coarse);
  const auto& magnet = force(*run, "magnet");
  const auto& coil = force(*run, "coil_lorentz");
  std::printf("magnet (stress) F_z %.6g N (spread %.3f %%), coil (Lorentz) F_z %.6g N\n",
              magnet.force.z(), 100 * magnet.check_relative_difference, coil.force.z());
  EXPECT_GT(std::abs(coil.force.z()), 0.05); // a real force, not noise
  EXPECT_NEAR(coil.force.z(), -magnet.force.z(), 0.01 * std::abs(coil.force.z()));
  // The coil's summary entry is the same Lorentz force (about the origin).
  EXPECT_NEAR(run->coil_results.coils[0].force_N.z(), coil.force.z(), 1e-9);
  // `magfem analytic` on the same case file (charge model + source field; exact to 1e-5,
  // AnalyticCoils.Coil3DForceEqualsTheMutualInductanceGradient).
  const auto an = run_case_analytic(read_case(test::example("3d/coil_and_magnet.yaml")), {});
  const double exact = an->coils[0].force_N.z();
  const auto& fe_axis = run->probes[0];
  const auto& an_axis = an->probes[0];
  double err = 0, peak = 0;
  for (std::size_t k = 0; k < an_axis.rows.size(); ++k) {
    const double z = an_axis.rows[k][an_axis.column("z")];
    if (std::abs(std::abs(z) - 5) < 1e-9)
      continue; // on the magnet's end faces the charge model's B is ambiguous (H + M)
    const auto b = [&](const ProbeTable& t) {
      return Eigen::Vector3d(t.rows[k][t.column("Bx")], t.rows[k][t.column("By")],
                             t.rows[k][t.column("Bz")]);
    };
    err = std::max(err, (b(fe_axis) - b(an_axis)).norm());
    peak = std::max(peak, b(an_axis).norm());
  }
  std::printf("analytic: coil F_z %.6g N (FE Lorentz %+.2f %%, FE stress %+.2f %%), axis B max "
              "difference %.2e of the peak, linkage %.6g Wb (FE %.6g Wb)\n",
              exact, 100 * (coil.force.z() - exact) / exact,
              100 * (-magnet.force.z() - exact) / exact, err / peak, an->coils[0].flux_linkage_Wb,
              run->coil_results.coils[0].flux_linkage_Wb);
  // Measured at this mesh: FE Lorentz -0.23 %, FE stress -0.52 % (its two spheres differ by
  // 0.46 %), axis field 4.3e-3 of the peak (P2 at 6-15 mm elements), linkage -1.2e-3. Tolerances:
  // the 1 % above for the forces, about 3 times the measured value for the field and linkage.
  EXPECT_NEAR(coil.force.z(), exact, 0.01 * std::abs(exact));
  EXPECT_NEAR(magnet.force.z(), -exact, 0.01 * std::abs(exact));
  EXPECT_LT(err, 1.5e-2 * peak);
  EXPECT_NEAR(run->coil_results.coils[0].flux_linkage_Wb, an->coils[0].flux_linkage_Wb,
              4e-3 * an->coils[0].flux_linkage_Wb);
}

namespace {

const std::string coil_case = R"(unit: mm
dimension: 3
materials:
  pm: {kind: magnet, B_r: 1.2, mu_r: 1.0}
regions:
  - name: magnet
    shape: cylinder
    r_outer: 5
    height: 10
    material: pm
    magnetization: {type: axial}
coils:
  - name: coil
    shape: solenoid
    r_inner: 4
    r_outer: 8
    length: 10
    center: [0, 0, 30]
    axis: [0, 0, 1]
    turns: 100
    current: 1
boundary: {type: open, radius: 60}
mesh: {size: 10}
solver: {order: 1}
)";

std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto pos = text.find(from);
  if (pos == std::string::npos)
    throw std::logic_error("pattern not in case: " + from);
  return text.replace(pos, from.size(), to);
}

void expect_coil_error(const std::string& name, const std::string& text, int line,
                       const std::string& field, bool needs_mesh = false) {
  const auto path = test::write_temp_case(name + ".yaml", text);
  try {
    auto spec = read_case(path);
    if (needs_mesh)
      run_case_3d(std::move(spec));
    FAIL() << name << ": no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path) << name;
    EXPECT_EQ(e.line(), line) << name << ": " << e.what();
    EXPECT_NE(e.field().find(field), std::string::npos) << name << ": " << e.what();
  }
}

} // namespace

TEST(Coils3D, BadCoilInputNamesFileLineAndField) {
  expect_coil_error("zero_turns", replace(coil_case, "turns: 100", "turns: 0"), 20, "turns");
  expect_coil_error("negative_radius", replace(coil_case, "r_outer: 8", "r_outer: -8"), 16,
                    "r_outer");
  expect_coil_error("zero_axis", replace(coil_case, "axis: [0, 0, 1]", "axis: [0, 0, 0]"), 19,
                    "axis");
  expect_coil_error("crosses_boundary",
                    replace(coil_case, "center: [0, 0, 30]", "center: [0, 0, 55]"), 18, "center");
  expect_coil_error("unknown_shape", replace(coil_case, "shape: solenoid", "shape: donut"), 14,
                    "shape");
  // Overlap with the magnet (the coil's bundle passes through it) is found before meshing: a
  // second part reaching beyond the boundary would stop the mesher (a cheap error of its first
  // step), so the coil's error can only come first if the check runs before the mesh.
  const std::string through =
      replace(replace(coil_case, "center: [0, 0, 30]", "center: [0, 0, 5]"), "coils:\n",
              "  - {name: beyond, shape: box, size: [10, 10, 10],\n"
              "     placement: {translate: [0, 0, 58]}}\ncoils:\n");
  expect_coil_error("overlaps_magnet", through, 15, "coils.coil", true);
  try {
    run_case_3d(read_case(test::write_temp_case("overlaps_magnet.yaml", through)));
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the coil overlaps region 'magnet'"), std::string::npos)
        << e.what();
  }
}

namespace {

// A racetrack tilted over a cylinder magnet, off its axis: no symmetry, so every force and
// torque component is non-trivial. Bundle: straights 8 x 4 mm, corner radius 2 mm, build 3 mm,
// height 4 mm; its lowest point is ~12 mm from the origin, outside both stress spheres.
const std::string racetrack_case = R"(unit: mm
dimension: 3
materials:
  pm: {kind: magnet, B_r: 1.2, mu_r: 1.0}
regions:
  - name: magnet
    shape: cylinder
    r_outer: 5
    height: 10
    material: pm
    magnetization: {type: axial}
    placement: {translate: [0, 0, -5]}
    mesh_size: 1.5
coils:
  - name: track
    shape: racetrack
    straight_x: 8
    straight_y: 4
    inner_radius: 2
    width: 3
    height: 4
    center: [2, 1, 17]
    axis: [0.25, 0, 1]
    x_direction: [1, 0, 0]
    turns: 400
    current: 2
boundary: {type: open, radius: 60}
mesh: {size: 6, chord_tolerance: 0.05, probe_size: 1.2}
solver: {order: 2}
forces:
  - {name: magnet, type: sphere, radius: 9, check_radius: 10}
  - {name: track_lorentz, type: lorentz, coils: [track]}
)";

} // namespace

// The reader maps the case's racetrack keys (length unit mm) onto the geometry: lengths in
// metres, local x along x_direction made normal to the axis, local z along the axis.
TEST(Coils3D, RacetrackIsReadInMetresInItsOwnFrame) {
  const auto spec = read_case(test::write_temp_case("racetrack_read.yaml", racetrack_case));
  ASSERT_EQ(spec.geometry3d.coils.size(), 1u);
  const Coil3D& c = spec.geometry3d.coils[0];
  const auto& r = std::get<Racetrack>(c.shape);
  EXPECT_DOUBLE_EQ(r.straight_x, 8e-3);
  EXPECT_DOUBLE_EQ(r.straight_y, 4e-3);
  EXPECT_DOUBLE_EQ(r.inner_radius, 2e-3);
  EXPECT_DOUBLE_EQ(r.width, 3e-3);
  EXPECT_DOUBLE_EQ(r.height, 4e-3);
  EXPECT_DOUBLE_EQ(c.turns, 400);
  EXPECT_DOUBLE_EQ(c.current, 2);
  const Eigen::Vector3d axis = Eigen::Vector3d(0.25, 0, 1).normalized();
  const Eigen::Matrix3d& rot = c.placement.rotation;
  EXPECT_LT((rot.col(2) - axis).norm(), 1e-12);
  EXPECT_NEAR(rot.col(0).dot(axis), 0, 1e-12);
  EXPECT_GT(rot.col(0).x(), 0.9); // x_direction, tilted with the axis
  EXPECT_NEAR(rot.determinant(), 1, 1e-12);
  EXPECT_LT((c.placement.translation - Eigen::Vector3d(2e-3, 1e-3, 17e-3)).norm(), 1e-15);
}

// Action = reaction for force and torque (about the origin) between a magnet (stress tensor
// on a sphere around it) and a tilted, off-axis racetrack (Lorentz force over its straight
// and corner bundles). The Lorentz side sees the racetrack's straight and arc source fields
// only through the FE field of the magnet, the stress side sees them through the solution, so
// a wrong piece (sign, orientation, missing corner) breaks the balance. Tolerances from the
// stress tensor's measured error, the difference between its two spheres: at mesh scale 1.6
// (235k P2 unknowns, ~30-60 s) they differ by 0.6 % in force, so 1 %; the torque on the
// magnet is small beside force x radius, and there the spheres differ by ~7 %, so the torques
// must balance within that difference plus 1 % (measured: 0.4 % force, 3.4 % torque apart).
// At mesh scale 2.5 the Lorentz torque falls just outside the spheres' spread.
// Long tier (65 s on an idle 2-core machine, twice that loaded): bash scripts/test.sh --long.
TEST(Coils3D, LongRacetrackAndMagnetForcesAndTorquesBalance) {
  RunOverrides coarse;
  coarse.mesh_scale = 1.6;
  auto run =
      run_case_3d(read_case(test::write_temp_case("racetrack_fe.yaml", racetrack_case)), coarse);
  const auto& magnet = force(*run, "magnet");
  const auto& track = force(*run, "track_lorentz");
  std::printf("magnet (stress) F (%.5g, %.5g, %.5g) N T (%.5g, %.5g, %.5g) mN m, spread %.2f %%\n"
              "  check sphere T (%.5g, %.5g, %.5g) mN m\n"
              "track (Lorentz) F (%.5g, %.5g, %.5g) N T (%.5g, %.5g, %.5g) mN m\n",
              magnet.force.x(), magnet.force.y(), magnet.force.z(), 1e3 * magnet.torque.x(),
              1e3 * magnet.torque.y(), 1e3 * magnet.torque.z(),
              100 * magnet.check_relative_difference, 1e3 * magnet.check_torque.x(),
              1e3 * magnet.check_torque.y(), 1e3 * magnet.check_torque.z(), track.force.x(),
              track.force.y(), track.force.z(), 1e3 * track.torque.x(), 1e3 * track.torque.y(),
              1e3 * track.torque.z());
  ASSERT_TRUE(magnet.checked);
  EXPECT_GT(track.force.norm(), 0.05); // a real force, not noise
  EXPECT_LT((track.force + magnet.force).norm(), 0.01 * track.force.norm());
  EXPECT_LT((track.torque + magnet.torque).norm(),
            (magnet.torque - magnet.check_torque).norm() + 0.01 * track.torque.norm());
}

// Racetrack-specific bad input: exit-2 errors at the key's line.
TEST(Coils3D, BadRacetrackInputNamesFileLineAndField) {
  expect_coil_error("racetrack_zero_width", replace(racetrack_case, "width: 3", "width: 0"), 20,
                    "width");
  expect_coil_error("racetrack_negative_radius",
                    replace(racetrack_case, "inner_radius: 2", "inner_radius: -2"), 19,
                    "inner_radius");
  expect_coil_error("racetrack_unknown_key",
                    replace(racetrack_case, "straight_y: 4", "straight_z: 4"), 18, "straight_z");
  expect_coil_error("racetrack_x_along_axis",
                    replace(racetrack_case, "x_direction: [1, 0, 0]", "x_direction: [0.25, 0, 1]"),
                    24, "x_direction");
}
