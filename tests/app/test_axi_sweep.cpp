// Axisymmetric sweep (magfem sweep --move): the voice-coil example's coil moved along the
// axis; the force at every position equals the exact current-sheet model of the magnet
// (mu_r = 1: the magnet is the sheet M0 l on its side), and bad requests are InputErrors.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "app/sweep_axi.hpp"
#include "case_helpers.hpp"
#include "core/constants.hpp"
#include "core/input_error.hpp"
#include "validation/coil_closed_forms.hpp"

using namespace magfem;

TEST(AxiSweep, ForceVersusSeparationEqualsTheCurrentSheetModel) {
  const auto spec = read_case(test::example("axi/voice_coil_magnet.yaml"));
  AxiSweepOptions o;
  o.group = "coil";
  o.positions_m = {0.0, 0.002, 0.005};
  o.jobs = 2;
  const auto rows = run_sweep_axi(spec, o);
  const double l = 0.0127;
  const CoaxialCoil sheet{0.00635, 0.00635, -0.5 * l, 0.5 * l, 1};
  for (const auto& r : rows) {
    ASSERT_TRUE(r.ok) << r.error;
    const double z0 = 0.00685 + r.position_m;
    const CoaxialCoil coil{0.00476, 0.0095, z0, z0 + 0.0254, 1050};
    const double exact = coaxial_axial_force(sheet, coil, 1.27 * l / mu0, 4.0);
    std::cout << "position " << 1e3 * r.position_m << " mm: FE " << r.fz_N << " N, exact " << exact
              << " N (rel " << (r.fz_N - exact) / exact << "), " << r.seconds << " s\n";
    // As for the unmoved example (3.5e-6 measured): tolerance 1e-4.
    EXPECT_NEAR(r.fz_N, exact, 1e-4 * std::abs(exact));
  }
  EXPECT_NE(sweep_axi_csv(rows).rfind("position_mm,Fz_N\n", 0), std::string::npos);
}

TEST(AxiSweep, BadRequestsAreInputErrors) {
  const auto spec = read_case(test::example("axi/voice_coil_magnet.yaml"));
  AxiSweepOptions o;
  o.group = "nothing";
  o.positions_m = {0.0};
  EXPECT_THROW(run_sweep_axi(spec, o), InputError);
  const auto planar = read_case(test::example("2d/c_core.yaml"));
  EXPECT_THROW(move_group_axi(planar, "coil", 0.001), InputError);
}
