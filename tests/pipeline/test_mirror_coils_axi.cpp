// Axisymmetric coils that are each other's mirror images about z = 0 (issue 36), solved as a
// half model: the share drives both coils, and a second sensitivity solve with the plane's
// other condition separates the pair's self and mutual inductance
// (pipeline/coil_results_axi.hpp). Checked against
//   - the full model of the same device (its own sensitivities give the matrix directly),
//   - the exact self and mutual inductance of coaxial coils of rectangular cross-section
//     (analytic/coil_closed_forms.hpp: Maxwell's loop formula integrated over the sections),
//   - identities: lambda = L I in air, W = I^T L I / 2, L symmetric, and the image's linkage
//     s (N_B / N_A) times the meshed coil's.
// A Helmholtz-like pair (same current, field: normal), the same pair anti-Helmholtz (field:
// parallel) and one with unequal turns (N_B = 2 N_A, I_B = I_A / 2) exercise the sign s and
// the current ratio t = s N_A / N_B; a winding on the plane beside the pair, the cross terms;
// a saturated core, the tangent at the operating point.
// Planted bugs the tests caught (branch mirror36): the complementary condition not switched,
// L_AB's sign, the factor 1/2 dropped, the image linkage's sign under `parallel` dropped, the
// complementary tangent taken at A = 0 or with the plane's values dropped (the saturated core
// only), the winding on the plane linking the antisymmetric field.
#include <gtest/gtest.h>

#include <regex>

#include "analytic/coil_closed_forms.hpp"
#include "core/input_error.hpp"
#include "pipeline/run2d.hpp"
#include "tests/case_helpers.hpp"

using namespace magfem;

namespace {

// Coil A: r 18..22 mm, z 6..10 mm, 100 turns, 1 A; coil B its mirror image, NB turns, IB A.
const char* pair_case = R"(
dimension: axi
unit: mm
regions:
  - {name: upper, shape: rectangle, center: [20, 8], width: 4, height: 4, turns: 100,
     current: 1, mesh_size: 0.5}
  - {name: lower, shape: rectangle, center: [20, -8], width: 4, height: 4, turns: NB,
     current: IB, mesh_size: 0.5}
boundary: {type: open, radius: 50, shell_ratio: 1.5SYMMETRY}
mesh: {size: 3, chord_tolerance: 0.005}
solver: {order: 2}
)";

std::unique_ptr<Run2D> solve(const std::string& nb, const std::string& ib,
                             const std::string& symmetry, const std::string& name) {
  std::string t = std::regex_replace(pair_case, std::regex("NB"), nb);
  t = std::regex_replace(t, std::regex("IB"), ib);
  t = std::regex_replace(t, std::regex("SYMMETRY"), symmetry);
  return run_case_2d(read_case(test::write_temp_case(name, t)));
}

CoaxialCoil coil(double z_min, double turns) {
  return {18e-3, 22e-3, z_min, z_min + 4e-3, turns};
}

// The FE matrix of two coils against another model's, entry by entry, relative to L_AA.
void expect_matrix_near(const Eigen::MatrixXd& l, const Eigen::MatrixXd& ref, double rel,
                        const char* what) {
  ASSERT_EQ(l.rows(), 2);
  ASSERT_EQ(ref.rows(), 2);
  for (int i = 0; i < 2; ++i)
    for (int k = 0; k < 2; ++k)
      EXPECT_NEAR(l(i, k), ref(i, k), rel * ref(0, 0)) << what << " (" << i << ", " << k << ")";
}

// The identities any run of the pair in air satisfies.
void expect_identities(const Run2D& run) {
  const Eigen::MatrixXd& l = run.inductance_H;
  ASSERT_EQ(run.coil_results.size(), 2u);
  const Eigen::Vector2d i(run.coil_results[0].current_A, run.coil_results[1].current_A);
  // Galerkin: L_jk = f_j . K^-1 f_k, symmetric to round-off.
  EXPECT_NEAR(l(0, 1), l(1, 0), 1e-9 * l(0, 0));
  // In air the linkage is L I, and the energy I^T L I / 2 (the whole device's).
  for (int k = 0; k < 2; ++k)
    EXPECT_NEAR(run.coil_results[std::size_t(k)].flux_linkage_Wb, (l * i)(k), 1e-9 * l(0, 0))
        << run.coil_results[std::size_t(k)].name;
  EXPECT_NEAR(run.energy.total_J_per_m, 0.5 * i.dot(l * i), 1e-6 * run.energy.total_J_per_m);
  for (int k = 0; k < 2; ++k)
    EXPECT_DOUBLE_EQ(run.coil_results[std::size_t(k)].inductance_H, l(k, k));
}

TEST(MirrorCoilsAxi, HelmholtzPairHalfModelMatchesFullAndExact) {
  const auto full = solve("100", "1", "", "mirror_axi_full.yaml");
  const auto half =
      solve("100", "1", ", symmetry: [{plane: z, field: normal}]", "mirror_axi_half.yaml");
  Eigen::MatrixXd exact(2, 2);
  exact(0, 0) = exact(1, 1) = coaxial_coil_self_inductance(coil(6e-3, 100));
  exact(0, 1) = exact(1, 0) = coaxial_mutual_inductance(coil(6e-3, 100), coil(-10e-3, 100));
  // Measured: the full and the half model differ by 4e-7 L_AA (their meshes); both are within
  // 2.7e-5 L_AA of the exact values (L_AA's element error at 0.5 mm in the coils, L_AB's is
  // 1e-6 of it; the open boundary's shell is exact). Tolerances about 4x those.
  expect_matrix_near(half->inductance_H, full->inductance_H, 2e-6, "half vs full");
  expect_matrix_near(half->inductance_H, exact, 1e-4, "half vs exact");
  expect_matrix_near(full->inductance_H, exact, 1e-4, "full vs exact");
  EXPECT_GT(half->inductance_H(0, 1), 0.1 * half->inductance_H(0, 0)); // a real coupling
  expect_identities(*half);
  expect_identities(*full);
  EXPECT_EQ(half->coil_results[0].mirror_image, "lower");
  EXPECT_EQ(half->coil_results[1].mirror_image, "upper");
  // The image's linkage is the meshed coil's (same turns, field: normal).
  EXPECT_DOUBLE_EQ(half->coil_results[1].flux_linkage_Wb, half->coil_results[0].flux_linkage_Wb);
  EXPECT_NEAR(half->coil_results[0].flux_linkage_Wb, full->coil_results[0].flux_linkage_Wb,
              1e-6 * full->coil_results[0].flux_linkage_Wb);
}

TEST(MirrorCoilsAxi, AntiHelmholtzPairUnderParallelPlane) {
  const auto full = solve("100", "-1", "", "mirror_axi_anti_full.yaml");
  const auto half =
      solve("100", "-1", ", symmetry: [{plane: z, field: parallel}]", "mirror_axi_anti_half.yaml");
  // The matrix is geometry's (air): the same as the Helmholtz pair's, within the meshes'.
  expect_matrix_near(half->inductance_H, full->inductance_H, 2e-6, "half vs full");
  EXPECT_GT(half->inductance_H(0, 1), 0.1 * half->inductance_H(0, 0));
  expect_identities(*half);
  // I_B = -I_A: lambda_B = -lambda_A (the potential is odd about a parallel plane).
  EXPECT_DOUBLE_EQ(half->coil_results[1].flux_linkage_Wb, -half->coil_results[0].flux_linkage_Wb);
  for (int k = 0; k < 2; ++k)
    EXPECT_NEAR(half->coil_results[std::size_t(k)].flux_linkage_Wb,
                full->coil_results[std::size_t(k)].flux_linkage_Wb,
                1e-6 * std::abs(full->coil_results[0].flux_linkage_Wb));
}

TEST(MirrorCoilsAxi, UnequalTurnsPair) {
  // N_B = 200 at 0.5 A: the same ampere-turns as A, so the same device's field.
  const auto full = solve("200", "0.5", "", "mirror_axi_turns_full.yaml");
  const auto half =
      solve("200", "0.5", ", symmetry: [{plane: z, field: normal}]", "mirror_axi_turns_half.yaml");
  expect_matrix_near(half->inductance_H, full->inductance_H, 2e-6, "half vs full");
  // L scales with the turns: L_BB = 4 L_AA, L_AB twice the equal pair's.
  EXPECT_NEAR(half->inductance_H(1, 1), 4 * half->inductance_H(0, 0),
              1e-9 * half->inductance_H(1, 1));
  expect_identities(*half);
  EXPECT_DOUBLE_EQ(half->coil_results[1].flux_linkage_Wb,
                   2 * half->coil_results[0].flux_linkage_Wb);
}

// The pair around a steel_1010 core (r 0..15 mm, z -14..14 mm, its own image), driven into
// saturation: the differential matrix comes from the tangent at the operating point, which
// the complementary solve takes with the share's potential on the plane (Assembler2D::
// evaluate_full), where its own condition would hold A = 0.
const char* iron_case = R"(
dimension: axi
unit: mm
regions:
  - {name: core, shape: rectangle, center: [7.5, 0], width: 15, height: 28,
     material: steel_1010, mesh_size: 1}
  - {name: upper, shape: rectangle, center: [20, 8], width: 4, height: 4, turns: 100,
     current: 80, mesh_size: 0.5}
  - {name: lower, shape: rectangle, center: [20, -8], width: 4, height: 4, turns: 100,
     current: 80, mesh_size: 0.5}
boundary: {type: open, radius: 50, shell_ratio: 1.5SYMMETRY}
mesh: {size: 3, chord_tolerance: 0.005}
solver: {order: 2}
)";

TEST(MirrorCoilsAxi, SaturatedCoreDifferentialMatrix) {
  auto run = [](const std::string& symmetry, const std::string& name) {
    const std::string t = std::regex_replace(iron_case, std::regex("SYMMETRY"), symmetry);
    return run_case_2d(read_case(test::write_temp_case(name, t)));
  };
  const auto full = run("", "mirror_axi_iron_full.yaml");
  const auto half = run(", symmetry: [{plane: z, field: normal}]", "mirror_axi_iron_half.yaml");
  ASSERT_GT(full->energy.regions.at(0).peak_B_T, 1.6); // saturated: the tangent matters
  // Measured: half and full differ by 3e-5 L_AA, as much as the full model's two coils
  // differ from each other (its mesh is not mirror-symmetric): element error. 5x that.
  expect_matrix_near(half->inductance_H, full->inductance_H, 1.5e-4, "half vs full");
  EXPECT_NEAR(half->inductance_H(0, 1), half->inductance_H(1, 0), 1e-9 * half->inductance_H(0, 0));
  // The linkages (not a derivative) agree to 2e-6.
  EXPECT_NEAR(half->coil_results[1].flux_linkage_Wb, full->coil_results[1].flux_linkage_Wb,
              1e-5 * full->coil_results[1].flux_linkage_Wb);
}

// The pair with a winding the plane cuts (its own image: r 8..10 mm, z -12..12 mm, 50 turns):
// the entries between the winding and the pair use the symmetric solve alone (the winding
// links nothing of the antisymmetric field, whose potential is odd about the plane).
TEST(MirrorCoilsAxi, PairWithAWindingOnThePlane) {
  const std::string winding = R"(
  - {name: winding, shape: rectangle, center: [9, 0], width: 2, height: 24, turns: 50,
     current: 2, mesh_size: 0.5}
boundary:)";
  std::string t = std::regex_replace(pair_case, std::regex("NB"), "100");
  t = std::regex_replace(t, std::regex("IB"), "1");
  t = std::regex_replace(t, std::regex("\nboundary:"), winding);
  auto run = [&](const std::string& symmetry, const std::string& name) {
    return run_case_2d(read_case(
        test::write_temp_case(name, std::regex_replace(t, std::regex("SYMMETRY"), symmetry))));
  };
  const auto full = run("", "mirror_axi_winding_full.yaml");
  const auto half = run(", symmetry: [{plane: z, field: normal}]", "mirror_axi_winding_half.yaml");
  const Eigen::MatrixXd& l = half->inductance_H;
  ASSERT_EQ(l.rows(), 3);
  // Measured: at most 4.7e-6 of L_AA apart (L_BB; the full model's own L_AA and L_BB differ
  // by 2.4e-6, its mesh not being mirror-symmetric): element error. 3x that.
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(l(i, k), full->inductance_H(i, k), 1.5e-5 * l(0, 0)) << i << ", " << k;
  EXPECT_GT(l(2, 0), 0.1 * l(2, 2)); // the winding couples to the pair
  EXPECT_NEAR(l(0, 2), l(2, 0), 1e-9 * l(0, 0));
  const Eigen::Vector3d i(1, 1, 2);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(half->coil_results[std::size_t(k)].flux_linkage_Wb, (l * i)(k), 1e-9 * l(0, 0));
  EXPECT_TRUE(half->coil_results[2].mirror_image.empty());
}

TEST(MirrorCoilsAxi, RefusedWhenOnlyOneHasTurns) {
  // The lower coil as a current density (its ampere-turns over its area, 100 A / 16 mm^2).
  std::string t = std::regex_replace(pair_case, std::regex("turns: NB,\\s*current: IB"),
                                     "current_density: 6.25e6");
  t = std::regex_replace(t, std::regex("SYMMETRY"), ", symmetry: [{plane: z, field: normal}]");
  const std::string path = test::write_temp_case("mirror_axi_bad.yaml", t);
  try {
    run_case_2d(read_case(path));
    FAIL() << "accepted";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(path + ":5"), std::string::npos) << msg;
    EXPECT_NE(msg.find("its mirror image is region 'lower', and only one of the two has turns"),
              std::string::npos)
        << msg;
  }
}

} // namespace
