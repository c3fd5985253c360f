// `magfem analytic` on a half-model case (boundary.symmetry): the planes tell the mesher which
// share to mesh, the case still describes the whole device, and the analytic models evaluate
// that whole device. So a half-model example and the same file without its `symmetry` key
// give the same analytic outputs bit for bit (same models, same sources, same points):
// probes, coils (linkage, force), inductance matrix, forces. The half model's notes say the
// planes were not used.
// Planted bug the tests caught: the plane's cut applied to the analytic geometry (the
// axisymmetric source check saw the cut coil: "region winding covers part of region
// winding"; in 3D the sphere cut to its upper half: probes off by up to ~0.3 T).
#include <gtest/gtest.h>

#include "pipeline/run_analytic.hpp"
#include "tests/case_helpers.hpp"

using namespace magfem;

namespace {

void expect_same_analytic_outputs(const std::string& example, const std::string& name) {
  const std::string whole = test::example_without_symmetry(example);
  ASSERT_FALSE(whole.empty()) << example << " has no symmetry key";
  const auto half = run_case_analytic(read_case(test::example(example)), {});
  const auto full = run_case_analytic(read_case(test::write_temp_case(name, whole)), {});
  ASSERT_EQ(half->probes.size(), full->probes.size());
  ASSERT_FALSE(half->probes.empty());
  for (std::size_t p = 0; p < half->probes.size(); ++p) {
    EXPECT_EQ(half->probes[p].columns, full->probes[p].columns);
    const auto &h = half->probes[p].rows, &f = full->probes[p].rows;
    ASSERT_EQ(h.size(), f.size());
    for (std::size_t r = 0; r < h.size(); ++r)
      if (h[r] != f[r]) { // the first differing row says enough
        ADD_FAILURE() << half->probes[p].name << " row " << r << ": half "
                      << ::testing::PrintToString(h[r]) << ", full "
                      << ::testing::PrintToString(f[r]);
        break;
      }
  }
  ASSERT_EQ(half->coils.size(), full->coils.size());
  for (std::size_t c = 0; c < half->coils.size(); ++c) {
    EXPECT_EQ(half->coils[c].flux_linkage_Wb, full->coils[c].flux_linkage_Wb);
    EXPECT_EQ(half->coils[c].force_N, full->coils[c].force_N);
    EXPECT_EQ(half->coils[c].torque_Nm, full->coils[c].torque_Nm);
  }
  EXPECT_EQ(half->linkage_known, full->linkage_known);
  ASSERT_EQ(half->inductance_H.rows(), full->inductance_H.rows());
  ASSERT_EQ(half->inductance_H.cols(), full->inductance_H.cols());
  EXPECT_EQ(half->inductance_H, full->inductance_H);
  ASSERT_EQ(half->forces.size(), full->forces.size());
  for (std::size_t f = 0; f < half->forces.size(); ++f) {
    EXPECT_EQ(half->forces[f].force, full->forces[f].force);
    EXPECT_EQ(half->forces[f].torque, full->forces[f].torque);
  }
  bool noted = false;
  for (const auto& n : half->scene.notes)
    noted = noted || n.find("symmetry plane z = 0") != std::string::npos;
  EXPECT_TRUE(noted) << "the half model's notes do not mention the plane";
}

} // namespace

TEST(AnalyticHalfModel, AxiSolenoidHalfIsTheWholeSolenoid) {
  expect_same_analytic_outputs("axi/solenoid_half.yaml", "an_solenoid_nosym.yaml");
}

// The pair's lower coil lies wholly beyond the plane: the models take it as described.
TEST(AnalyticHalfModel, AxiCoilPairHalfIsTheWholePair) {
  expect_same_analytic_outputs("axi/coil_pair_half.yaml", "an_coil_pair_nosym.yaml");
}

TEST(AnalyticHalfModel, MagnetizedSphereHalfIsTheWholeSphere) {
  expect_same_analytic_outputs("3d/magnetized_sphere_half.yaml", "an_sphere_nosym.yaml");
}
