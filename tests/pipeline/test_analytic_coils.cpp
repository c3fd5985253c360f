// `magfem analytic` on coil cases (issues 9 and 11): axisymmetric cases by the exact thick-coil
// field and the magnets' current sheets, 3D coils by their source fields plus the charge model,
// against the FE on the same case files and against independent closed forms; iron refused.
// The 3D FE comparison lives in test_coils3d.cpp (Coils3D.MagnetAndCoilForcesBalance), which
// already solves examples/3d/coil_and_magnet.yaml.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sys/wait.h>

#include "analytic/coil_closed_forms.hpp"
#include "analytic/rotor_coil_pair.hpp"
#include "core/constants.hpp"
#include "core/input_error.hpp"
#include "pipeline/run_analytic.hpp"
#include "tests/case_helpers.hpp"
#include "tests/test_paths.hpp"

using namespace magfem;

namespace {

const ForceResult& force(const std::vector<ForceResult>& forces, const std::string& name) {
  return test::named(forces, name);
}

const ProbeTable& probe(const std::vector<ProbeTable>& probes, const std::string& name) {
  for (const auto& p : probes)
    if (p.name == name)
      return p;
  throw std::runtime_error("no probe " + name);
}

// Max |B_a - B_b| over two tables of the same probe relative to the largest |B_b| on it, after
// checking that they have the same columns and points.
double table_difference(const ProbeTable& a, const ProbeTable& b, const std::string& c1,
                        const std::string& c2) {
  EXPECT_EQ(a.columns, b.columns);
  EXPECT_EQ(a.rows.size(), b.rows.size());
  const auto i1 = b.column(c1), i2 = b.column(c2);
  double err = 0, peak = 0;
  for (std::size_t k = 0; k < std::min(a.rows.size(), b.rows.size()); ++k) {
    EXPECT_NEAR(a.rows[k][0], b.rows[k][0], 1e-9);
    EXPECT_NEAR(a.rows[k][1], b.rows[k][1], 1e-9);
    err = std::max(err, std::hypot(a.rows[k][i1] - b.rows[k][i1], a.rows[k][i2] - b.rows[k][i2]));
    peak = std::max(peak, std::hypot(b.rows[k][i1], b.rows[k][i2]));
  }
  return err / peak;
}

int run_cli(const std::string& args, std::string& out) {
  const std::string cmd = std::string(magfem::test::magfem_binary()) + " " + args + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  std::array<char, 4096> buf{};
  while (pipe && fgets(buf.data(), buf.size(), pipe))
    out += buf.data();
  const int raw = pipe ? pclose(pipe) : -1;
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

} // namespace

TEST(AnalyticCoils, AxiSolenoidMatchesTheFe) {
  const auto fe = run_case_2d(read_case(test::example("axi/solenoid.yaml")));
  const auto an = run_case_analytic(read_case(test::example("axi/solenoid.yaml")), {});
  // The FE's own discretisation error against the exact loop integration, measured in
  // AxiCoils.SolenoidFieldEqualsTheLoopIntegration (relative to the peak on each probe):
  // 3.2e-4 axis, 2.6e-4 bore, 1.3e-3 outside, 8.5e-4 arc. Tolerances: 3 times those.
  EXPECT_LT(table_difference(probe(fe->probes, "axis"), probe(an->probes, "axis"), "Br", "Bz"),
            1e-3);
  EXPECT_LT(table_difference(probe(fe->probes, "bore"), probe(an->probes, "bore"), "Br", "Bz"),
            1e-3);
  EXPECT_LT(
      table_difference(probe(fe->probes, "outside"), probe(an->probes, "outside"), "Br", "Bz"),
      4e-3);
  EXPECT_LT(table_difference(probe(fe->probes, "arc30"), probe(an->probes, "arc30"), "Br", "Bz"),
            3e-3);
  // Linkage / current: the FE's energy-type error is O(h^4), measured ~1e-5 against
  // Maxwell's formula (AxiCoils.SolenoidInductanceEqualsMaxwellsFormulaAndTheEnergy): 2e-4.
  ASSERT_EQ(an->coils.size(), 1u);
  ASSERT_EQ(fe->coil_results.size(), 1u);
  ASSERT_TRUE(an->linkage_known[0]);
  EXPECT_NEAR(an->coils[0].flux_linkage_Wb, fe->coil_results[0].flux_linkage_Wb,
              2e-4 * fe->coil_results[0].flux_linkage_Wb);
  ASSERT_EQ(an->inductance_H.rows(), 1);
  EXPECT_NEAR(an->inductance_H(0, 0) * an->coils[0].current_A, an->coils[0].flux_linkage_Wb,
              1e-12 * an->coils[0].flux_linkage_Wb);
  // A lone coil feels no net force from its own field.
  EXPECT_EQ(an->coils[0].force_N.norm(), 0.0);
}

TEST(AnalyticCoils, AxiVoiceCoilForceAndFieldMatchTheFe) {
  const std::string file = test::example("axi/voice_coil_magnet.yaml");
  const auto fe = run_case_2d(read_case(file));
  const auto an = run_case_analytic(read_case(file), {});
  const double coil = force(an->forces, "coil_lorentz").force.z();
  const double magnet = force(an->forces, "magnet_stress").force.z();
  std::printf("analytic: coil %.8g N, magnet %.8g N; FE: coil (Lorentz) %.8g N, magnet "
              "(stress) %.8g N\n",
              coil, magnet, force(fe->forces, "coil_lorentz").force.z(),
              force(fe->forces, "magnet_stress").force.z());
  // The FE Lorentz force against the sheet model: measured 3e-6 at this mesh
  // (AxiCoils.VoiceCoilExampleForceEqualsTheCurrentSheetModel), tolerance 1e-4; the FE stress
  // box around the magnet: measured 4.4e-4 (discretisation of the air field it samples), 3e-3.
  EXPECT_NEAR(coil, force(fe->forces, "coil_lorentz").force.z(), 1e-4 * std::abs(coil));
  EXPECT_NEAR(magnet, force(fe->forces, "magnet_stress").force.z(), 3e-3 * std::abs(coil));
  // The two analytic forces are separate pair integrals (dM/dz with the roles of the coil and
  // the sheet swapped): action = reaction to their convergence tolerance (1e-11).
  EXPECT_NEAR(magnet, -coil, 1e-9 * std::abs(coil));
  EXPECT_LT(coil, 0); // like coaxial dipoles attract: the coil is pulled towards the magnet
  ASSERT_EQ(an->coils.size(), 1u);
  EXPECT_DOUBLE_EQ(an->coils[0].force_N.z(), coil);
  // Same device, axis probe: the FE's largest error is at the magnet's end faces, where dB_z/dz
  // jumps (1.6e-3 T measured in AxiCoils.CylinderMagnetOnAxisFieldEqualsTheClosedForm without
  // the coil); tolerance 5e-3 relative to the peak (~0.6 T).
  EXPECT_LT(table_difference(probe(fe->probes, "axis"), probe(an->probes, "axis"), "Br", "Bz"),
            5e-3);
  // Flux linkage: the magnet's flux through the coil plus L I; the FE's linkage is an energy-
  // type quantity (O(h^4)): measured difference printed, tolerance 1e-3.
  ASSERT_TRUE(an->linkage_known[0]);
  std::printf("linkage analytic %.8g Wb, FE %.8g Wb\n", an->coils[0].flux_linkage_Wb,
              fe->coil_results[0].flux_linkage_Wb);
  EXPECT_NEAR(an->coils[0].flux_linkage_Wb, fe->coil_results[0].flux_linkage_Wb,
              1e-3 * std::abs(fe->coil_results[0].flux_linkage_Wb));
}

// The 3D path on the coaxial magnet and coil of examples/3d/coil_and_magnet.yaml: the Lorentz
// force on the coil by the charge model's field integrated over the bundle
// (azimuthal_current_wrench) against the mutual-inductance gradient of the coil and the
// magnet's current sheet (elliptic integrals; no charge model, no volume quadrature). A sign
// error of J or B, a factor 2 (e.g. both halves of an action-reaction pair added) or a wrong
// current per turn changes the force by 100 % or more; the two methods agree to their
// quadrature tolerances (charge model 1e-6, pair integral 1e-11): 1e-5.
TEST(AnalyticCoils, Coil3DForceEqualsTheMutualInductanceGradient) {
  const auto spec = read_case(test::example("3d/coil_and_magnet.yaml"));
  const auto an = run_case_analytic(spec, {});
  ASSERT_EQ(an->coils.size(), 1u);
  // Magnet: radius 5, z -5..5 mm, B_r 1.2 T along +z (a one-turn sheet of M l amperes);
  // coil: rho 4..8, z 15..25 mm, 500 turns x 2 A.
  const CoaxialCoil sheet{5e-3, 5e-3, -5e-3, 5e-3, 1};
  const CoaxialCoil coil{4e-3, 8e-3, 15e-3, 25e-3, 500};
  const double exact = coaxial_axial_force(sheet, coil, 1.2 / mu0 * 10e-3, 2.0);
  const Eigen::Vector3d f = an->coils[0].force_N;
  std::printf("coil force analytic (%.6g, %.6g, %.8g) N, exact F_z %.8g N\n", f.x(), f.y(), f.z(),
              exact);
  EXPECT_NEAR(f.z(), exact, 1e-5 * std::abs(exact));
  EXPECT_LT(std::hypot(f.x(), f.y()), 1e-8 * std::abs(exact)); // axial symmetry
  // No torque about the origin on the axis (lever arm ~20 mm): round-off only.
  EXPECT_LT(an->coils[0].torque_Nm.norm(), 1e-8 * std::abs(exact) * 0.02);
  // The stress sphere around the magnet: minus the coil's force (action = reaction).
  EXPECT_NEAR(force(an->forces, "magnet").force.z(), -exact, 1e-5 * std::abs(exact));
  EXPECT_NEAR(force(an->forces, "coil_lorentz").force.z(), f.z(), 1e-12 * std::abs(exact));
  // Linkage: L I (Maxwell's formula) plus the sheet's flux; resistance from the bundle.
  ASSERT_TRUE(an->linkage_known[0]);
  const double linkage = coaxial_coil_self_inductance(coil) * 2.0 +
                         coaxial_mutual_inductance(coil, sheet) * 1.2 / mu0 * 10e-3;
  EXPECT_NEAR(an->coils[0].flux_linkage_Wb, linkage, 1e-10 * std::abs(linkage));
  EXPECT_GT(an->coils[0].resistance_ohm, 0);
}

// The same device written as an axisymmetric case: the 3D path (charge model, Biot-Savart
// source field, bundle quadrature) and the axisymmetric one (current sheets, loop field, pair
// integrals) share no field code, and must agree on the axis field and the force to the charge
// model's tolerance (1e-6 relative per box; 1e-5 allowed).
TEST(AnalyticCoils, Coil3DAgreesWithTheAxisymmetricModels) {
  const auto axi = test::write_temp_case("analytic_coil_magnet_axi.yaml", R"(dimension: axi
unit: mm
materials:
  pm: {kind: magnet, B_r: 1.2, mu_r: 1.0}
regions:
  - {name: magnet, shape: rectangle, center: [2.5, 0], width: 5, height: 10, material: pm,
     magnetization: {type: parallel}}
  - {name: coil, shape: rectangle, center: [6, 20], width: 4, height: 10, turns: 500, current: 2}
boundary: {type: open, radius: 60}
mesh: {size: 6}
probes:
  - {name: axis, type: line, start: [0, -30], end: [0, 40], points: 141}
forces:
  - {name: coil_lorentz, type: lorentz, regions: [coil]}
)");
  const auto a = run_case_analytic(read_case(axi), {});
  const auto b = run_case_analytic(read_case(test::example("3d/coil_and_magnet.yaml")), {});
  const auto& pa = probe(a->probes, "axis");
  const auto& pb = probe(b->probes, "axis");
  ASSERT_EQ(pa.rows.size(), pb.rows.size());
  double err = 0, peak = 0;
  for (std::size_t k = 0; k < pa.rows.size(); ++k) {
    const double z = pb.rows[k][pb.column("z")];
    EXPECT_NEAR(pa.rows[k][pa.column("z")], z, 1e-9);
    // On an end face itself the charge model adds M or not depending on which side the point
    // is taken to be (B_z is continuous there, its H + M is not): those two samples are left out.
    if (std::abs(std::abs(z) - 5) < 1e-9)
      continue;
    err = std::max(err, std::abs(pa.rows[k][pa.column("Bz")] - pb.rows[k][pb.column("Bz")]));
    peak = std::max(peak, std::abs(pa.rows[k][pa.column("Bz")]));
  }
  std::printf("axis B_z: 3D vs axisymmetric models max difference %.2e of the peak\n", err / peak);
  EXPECT_LT(err, 1e-5 * peak);
  EXPECT_NEAR(force(a->forces, "coil_lorentz").force.z(),
              force(b->forces, "coil_lorentz").force.z(),
              1e-5 * std::abs(force(a->forces, "coil_lorentz").force.z()));
  EXPECT_NEAR(a->coils[0].flux_linkage_Wb, b->coils[0].flux_linkage_Wb,
              1e-9 * std::abs(a->coils[0].flux_linkage_Wb));
}

// Iron has no analytic model: exit 2 naming the file, the region's line and field, and no
// output folder (the axisymmetric pot core; TEAM 20's yoke in 3D).
TEST(AnalyticCoils, IronIsRefusedNamingTheRegion) {
  const std::string pot = test::example("axi/pot_core.yaml");
  try {
    run_case_analytic(read_case(pot), {});
    ADD_FAILURE() << "pot core accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "regions[0].material");
    EXPECT_EQ(e.file(), pot);
    EXPECT_EQ(e.line(), read_case(pot).regions[0].line);
    EXPECT_NE(e.reason().find("core"), std::string::npos) << e.what();
  }
  const auto out = std::filesystem::temp_directory_path() / "magfem_tests" / "analytic_iron";
  std::filesystem::remove_all(out);
  for (const std::string& c : {pot, test::example("3d/team20.yaml")}) {
    std::string text;
    EXPECT_EQ(run_cli("analytic " + c + " --out " + out.string(), text), 2) << text;
    EXPECT_NE(text.find("regions[0].material"), std::string::npos) << text;
    EXPECT_FALSE(std::filesystem::exists(out)) << c;
  }
}

// What the axisymmetric models cannot represent is refused, naming the field: a magnet
// magnetized radially, a coil partly covered by a later region.
TEST(AnalyticCoils, AxiRefusesWhatItCannotRepresent) {
  const std::string head = R"(dimension: axi
unit: mm
materials:
  pm: {kind: magnet, B_r: 1.2, mu_r: 1.0}
boundary: {type: open, radius: 60}
mesh: {size: 6}
regions:
)";
  const auto radial = test::write_temp_case(
      "analytic_axi_radial.yaml",
      head + "  - {name: ring, shape: rectangle, center: [7, 0], width: 4, height: 10, "
             "material: pm, magnetization: {type: parallel, angle: 0}}\n");
  try {
    run_case_analytic(read_case(radial), {});
    ADD_FAILURE() << "radial ring accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "regions[0].magnetization");
    EXPECT_EQ(e.line(), 8);
  }
  const auto covered = test::write_temp_case(
      "analytic_axi_covered.yaml",
      head + "  - {name: coil, shape: rectangle, center: [6, 0], width: 4, height: 10, "
             "turns: 10, current: 1}\n"
             "  - {name: hole, shape: disk, center: [6, 0], radius: 1, overlap: replace}\n");
  try {
    run_case_analytic(read_case(covered), {});
    ADD_FAILURE() << "covered coil accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "regions[1]");
    EXPECT_EQ(e.line(), 9);
  }
}

// A coil and a magnet off each other's axes (examples/3d/voice_coil_torque.yaml: the seed-002
// magnet on its motor's rotor, 10 deg from the stator coil): the torque about the rotor centre
// on the coil (charge model of the magnet, bundle quadrature over the coil) against minus the
// torque on the magnet's current sheet in the coil's exact loop field
// (analytic/rotor_coil_pair.hpp): the roles of source and target swapped, no shared field
// code. Measured: 7.6e-7 apart in torque, 6.7e-7 in force (0.165025 N m);
// tolerance 1e-3. A sign or factor-2 error in the coil's Lorentz torque fails it.
TEST(AnalyticCoils, OffAxisCoilTorqueIsMinusTheMagnetsTorque) {
  const auto an = run_case_analytic(read_case(test::example("3d/voice_coil_torque.yaml")), {});
  ASSERT_EQ(an->forces.size(), 1u);
  const RotorCoilPair pair;
  const Wrench on_magnet = magnet_wrench(pair, pair.coil, pair.current, 10 * pi / 180);
  const Eigen::Vector3d t = an->forces[0].torque, f = an->forces[0].force;
  std::printf("torque on the coil (%.6g, %.6g, %.6g) N m, on the magnet (%.6g, %.6g, %.6g) N m; "
              "|sum| / |T| = %.1e, force %.1e\n",
              t.x(), t.y(), t.z(), on_magnet.torque.x(), on_magnet.torque.y(), on_magnet.torque.z(),
              (t + on_magnet.torque).norm() / on_magnet.torque.norm(),
              (f + on_magnet.force).norm() / on_magnet.force.norm());
  EXPECT_LT((t + on_magnet.torque).norm(), 1e-3 * on_magnet.torque.norm());
  EXPECT_LT((f + on_magnet.force).norm(), 1e-3 * on_magnet.force.norm());
}
