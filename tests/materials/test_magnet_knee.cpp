// materials/magnet_knee: the knee B_r(T) - mu0 mu_r H_cJ(T) of a bundled grade against hand
// arithmetic at 20 and 100 C, and grades without knee data saying so.
#include <gtest/gtest.h>

#include "materials/material_library.hpp"

using namespace magfem;

namespace {

// Hand numbers are written to 7 significant digits: 1e-6 T is their rounding, not physics.
constexpr double hand_tol = 1e-6;

TEST(MagnetKnee, BundledN42At20AndAt100C) {
  const Material* n42 = MaterialLibrary::bundled().find("N42");
  ASSERT_NE(n42, nullptr);
  // Library: B_r 1.31 T, mu_r 1.11, H_cJ 955 kA/m, alpha -0.12 %/K, beta -0.75 %/K.
  // 20 C: mu0 mu_r H_cJ = 1.256637e-6 * 1.11 * 955e3 = 1.3320981 T; knee 1.31 - 1.3320981.
  ASSERT_TRUE(n42->knee_T());
  EXPECT_NEAR(*n42->knee_T(), -0.0220981, hand_tol);
  // 100 C: B_r = 1.31 (1 - 0.0012 * 80) = 1.184240 T; H_cJ = 955 (1 - 0.0075 * 80) = 382 kA/m;
  // mu0 mu_r H_cJ = 1.256637e-6 * 1.11 * 382e3 = 0.5328392 T; knee 0.6514008 T.
  const Material hot = n42->at_temperature(100);
  EXPECT_NEAR(hot.B_r, 1.184240, hand_tol);
  ASSERT_TRUE(hot.coercivity_Apm());
  EXPECT_NEAR(*hot.coercivity_Apm(), 382e3, 1e-6);
  EXPECT_NEAR(*hot.knee_T(), 0.6514008, hand_tol);
  EXPECT_DOUBLE_EQ(hot.temperature_C, 100);
  // The 20 C grade is unchanged by asking for it at 20 C.
  EXPECT_DOUBLE_EQ(n42->at_temperature(20).B_r, n42->B_r);
}

TEST(MagnetKnee, GradesWithoutDataHaveNoKnee) {
  const auto& lib = MaterialLibrary::bundled();
  for (const char* name : {"VACODYM633HR", "NdFeB_bonded", "Sm2Co17", "ferrite_Y30"}) {
    const Material* m = lib.find(name);
    ASSERT_NE(m, nullptr) << name;
    EXPECT_FALSE(m->knee_T()) << name;
  }
  // Every grade with knee data names the coefficients, so it can be checked hot as well.
  for (const auto& name : lib.names()) {
    const Material* m = lib.find(name);
    if (m->is_magnet() && m->knee.HcJ_Apm) {
      EXPECT_TRUE(m->knee.alpha_pct_per_K && m->knee.beta_pct_per_K) << name;
      EXPECT_NE(m->source.find("knee"), std::string::npos) << name << ": source of the knee";
    }
  }
  // Off 20 C, H_cJ without its temperature coefficient is unknown, not the 20 C value.
  Material m = Material::make_magnet("x", 1.2, 1.05, "test");
  m.knee.HcJ_Apm = 900e3;
  m.knee.alpha_pct_per_K = -0.1;
  EXPECT_TRUE(m.knee_T());
  EXPECT_FALSE(m.at_temperature(60).knee_T());
}

} // namespace
