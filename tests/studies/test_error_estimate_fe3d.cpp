// Error estimates of 3D FE results against exact answers (issue 29): the gravity
// compensator's torque at 90 deg, whose exact value in the charge model (mu_r 1 magnets in
// air, closed form) is 12.365 N m, must not be more than 3x off its own estimate; and the
// run reports the estimate where a user sees it (summary.json, forces.csv).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "core/constants.hpp"
#include "pipeline/run3d.hpp"
#include "pipeline/run_analytic.hpp"
#include "studies/sweep.hpp"
#include "tests/case_helpers.hpp"

#include <nlohmann/json.hpp>

using namespace magfem;

namespace {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct TorqueCheck {
  double fe = 0, exact = 0, estimate = 0, energy_pct = 0;
  long unknowns = 0;
};

// The compensator at 90 deg at the given mesh scale: the torque about y on the outer group
// (the reverse of the case's `inner` stress sphere) with its estimate, and the charge
// model's exact value.
// out_dir: where to write the run's outputs ("" = nowhere).
TorqueCheck compensator_at_90(double mesh_scale, const std::string& out_dir = "") {
  const auto spec = read_case(test::example("3d/compensator_table42.yaml"));
  const CaseSpec turned = rotate_group(spec, "outer", Eigen::Vector3d::UnitY(), 90 * deg_to_rad,
                                       Eigen::Vector3d::Zero());
  RunOverrides ov;
  ov.mesh_scale = mesh_scale;
  const auto run = run_case_3d(turned, ov);
  SweepOptions o;
  o.group = "outer";
  o.axis = Eigen::Vector3d::UnitY();
  o.angles_deg = {90};
  o.analytic = true;
  const auto charge = run_sweep(spec, o);
  EXPECT_TRUE(charge.at(0).ok);
  TorqueCheck c;
  const ForceResult& inner = run->forces.at(0);
  EXPECT_EQ(inner.name, "inner");
  EXPECT_TRUE(inner.estimated);
  c.fe = -inner.torque.y();
  c.exact = charge[0].torque.y();
  c.estimate = inner.torque_err.y();
  c.energy_pct = run->error_estimate.energy_error_pct;
  c.unknowns = run->dofs->n_dofs();
  if (!out_dir.empty())
    write_outputs_3d(*run, out_dir);
  std::printf("mesh scale %.1f: %ld unknowns, torque %.4f N m (exact %.4f), true error %.4f, "
              "estimate %.4f N m; energy error %.3f %%, estimator %.2f s of %.2f s\n",
              mesh_scale, c.unknowns, c.fe, c.exact, std::abs(c.fe - c.exact), c.estimate,
              c.energy_pct, run->timings.error_estimate, run->timings.total);
  return c;
}

} // namespace

// The honesty bound: true error <= 3x the estimate; and the estimate not a
// uselessly loose one (<= 10x the true error: a sanity check on its scale, not a claim of
// the issue). Measured (commit of this test): true / estimate 1.30 at mesh scale 3, 1.10 at
// 2, 0.87 at 1.6.
void check_torque(const TorqueCheck& c) {
  const double truth = std::abs(c.fe - c.exact);
  EXPECT_NEAR(c.exact, 12.365, 0.01);
  EXPECT_LE(truth, 3 * c.estimate);
  EXPECT_LE(c.estimate, 10 * truth);
}

// Mesh scale 3 (100k P2 unknowns, a few seconds): the FE torque is 3 % off, so the bound is
// tested where it matters. The run's outputs carry the estimates.
TEST(ErrorEstimateFE3D, CompensatorTorqueWithinThreeEstimates) {
  const std::string out =
      (std::filesystem::temp_directory_path() / "magfem_tests" / "error_estimate_fe3d").string();
  check_torque(compensator_at_90(3, out));
  const auto summary = nlohmann::json::parse(slurp(out + "/summary.json"));
  const double pct = summary.at("error_estimate").at("energy_error_pct").get<double>();
  EXPECT_GT(pct, 0);
  EXPECT_LT(pct, 100);
  EXPECT_EQ(summary.at("error_estimate").at("indicator"), "zz_spr_energy");
  const auto& inner = summary.at("forces").at(0);
  EXPECT_EQ(inner.at("error_estimate").at("torque_Nm").size(), 3u);
  const std::string csv = slurp(out + "/forces.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "name,method,Fx,Fy,Fz,Tx,Ty,Tz,Fx_err,Fy_err,Fz_err,Tx_err,Ty_err,Tz_err");
}

// Finer meshes (200k and 300k unknowns, ~15 s each).
TEST(ErrorEstimateFE3D, LongCompensatorTorqueAtFinerMeshes) {
  for (double scale : {2.0, 1.6})
    check_torque(compensator_at_90(scale));
}

// The Lorentz torque's one-mesh estimate (pipeline/coil_run3d.cpp: the element field's
// integral against the patch-recovered field's) on the small spherical actuator with coil a1
// at 1 A: the charge model's torque (run_case_analytic, exact for mu_r 1 magnets in air: the
// actuator tests) is the exact answer. The bound, true error <= 3x the estimate, at
// mesh scales 1 and 0.8 (88k and 146k unknowns; measured true / estimate 0.14 and 0.31).
// What it cannot see: error carried in from elsewhere (coarse magnets: at mesh scale 1.5 the
// torque was 4.5 % off with an estimate of 0.13 %, the field at the coil smooth and wrong);
// the adaptive loop takes the larger of this and the change between passes, which does.
TEST(ErrorEstimateFE3D, LorentzTorqueOnACoilWithinThreeEstimates) {
  std::string text = test::small_actuator_case;
  const std::string a1 = "axis_angles: [60, 0], turns: 100, current: 0";
  text.replace(text.find(a1), a1.size(), "axis_angles: [60, 0], turns: 100, current: 1");
  text += "forces:\n  - {name: a1, type: lorentz, coils: [a1]}\n";
  const CaseSpec spec = read_case(test::write_temp_case("lorentz_estimate.yaml", text));
  const Eigen::Vector3d exact = run_case_analytic(spec, {})->forces.at(0).torque;
  for (double scale : {1.0, 0.8}) {
    RunOverrides ov;
    ov.mesh_scale = scale;
    const auto run = run_case_3d(spec, ov);
    const ForceResult& f = run->forces.at(0);
    ASSERT_EQ(f.name, "a1");
    ASSERT_TRUE(f.estimated);
    const double truth = (f.torque - exact).norm(), estimate = f.torque_err.norm();
    std::printf("mesh scale %.1f: Lorentz torque %.3g %% off the charge model, estimated %.3g %%\n",
                scale, 100 * truth / exact.norm(), 100 * estimate / exact.norm());
    EXPECT_LE(truth, 3 * estimate);
    // A sanity check on its scale (an own field left in the recovered integral would be
    // tens of per cent): measured 0.86 % and 0.45 %.
    EXPECT_LT(estimate, 0.02 * exact.norm());
  }
}
