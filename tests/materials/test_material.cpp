// Material: the constitutive laws seen by the solvers.
#include <gtest/gtest.h>

#include <memory>

#include "core/constants.hpp"
#include "materials/material.hpp"

using magfem::Material;
using magfem::MaterialKind;
using magfem::mu0;

TEST(Material, LinearLawIsConstant) {
  const auto m = Material::make_linear("core", 1000, "test");
  for (double b2 : {0.0, 0.25, 4.0}) {
    double nu = 0, dnu = 1;
    m.reluctivity(b2, nu, dnu);
    EXPECT_DOUBLE_EQ(nu, 1.0 / (1000 * mu0));
    EXPECT_EQ(dnu, 0.0);
    double mu = 0, dmu = 1;
    m.permeability(b2 * 1e10, mu, dmu);
    EXPECT_DOUBLE_EQ(mu, 1000 * mu0);
    EXPECT_EQ(dmu, 0.0);
  }
  EXPECT_FALSE(m.is_nonlinear());
  EXPECT_FALSE(m.is_magnet());
}

TEST(Material, MagnetLawIsTheRecoilLine) {
  const auto m = Material::make_magnet("pm", 1.31, 1.11, "test");
  EXPECT_TRUE(m.is_magnet());
  EXPECT_EQ(m.B_r, 1.31);
  double nu = 0, dnu = 1;
  m.reluctivity(1.0, nu, dnu);
  EXPECT_DOUBLE_EQ(nu, 1.0 / (1.11 * mu0));
  EXPECT_EQ(dnu, 0.0);
  // The solver adds the remanence: H = nu (B - B_r m) vanishes at B = B_r (open circuit
  // with no demagnetizing field), and B = mu0 mu_r H + B_r.
  double mu = 0, dmu = 0;
  m.permeability(0.0, mu, dmu);
  EXPECT_DOUBLE_EQ(mu * nu, 1.0);
}

TEST(Material, SoftLawFollowsItsCurveInBothForms) {
  auto curve = std::make_shared<const magfem::BhCurve>(
      std::vector<double>{0, 100, 300, 1000, 10000}, std::vector<double>{0, 0.5, 1.2, 1.5, 1.9});
  const auto m = Material::make_soft("iron", curve, "test");
  EXPECT_TRUE(m.is_nonlinear());
  EXPECT_EQ(m.kind, MaterialKind::soft);
  EXPECT_DOUBLE_EQ(m.mu_r, curve->initial_slope() / mu0);
  for (double h : {0.0, 50.0, 200.0, 700.0, 5000.0, 50000.0}) {
    const double b = curve->b_of_h(h);
    double nu = 0, dnu = 0, mu = 0, dmu = 0;
    m.reluctivity(b * b, nu, dnu);
    m.permeability(h * h, mu, dmu);
    // Both forms describe one curve: nu(B^2) mu(H^2) = 1 at corresponding points, up to the
    // inverse's round-off.
    EXPECT_NEAR(nu * mu, 1.0, 1e-12) << "H = " << h;
    if (h > 0) {
      EXPECT_NEAR(nu * b, h, 1e-12 * h);
    }
  }
}

TEST(Material, SoftWithoutCurveIsAnInternalError) {
  Material m;
  m.kind = MaterialKind::soft;
  double nu = 0, dnu = 0;
  EXPECT_THROW(m.reluctivity(1.0, nu, dnu), std::logic_error);
}
