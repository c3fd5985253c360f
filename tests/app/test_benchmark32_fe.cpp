// The thesis's 32-magnet benchmark (ch. 3) through the FE solver at a coarse mesh, against the
// charge model, in the default suite: parallel (centre convention) and radial magnetization.
// The fine-mesh figures (eq. 3.117 within 0.11 % at 695k unknowns) come from `magfem validate`
// and scripts/benchmark.sh; here the point is that a regression in the segment-array
// geometry, the alternating pattern or the radial remanence of the 3D assembler fails fast.
#include <gtest/gtest.h>

#include <cstdio>

#include "app/run3d.hpp"
#include "app/run_analytic.hpp"
#include "case_helpers.hpp"
#include "postproc/probe_compare.hpp"

using namespace magfem;

namespace {

// Coarse: 16 mm air, 8 mm magnets, 5 mm elements on the probe patch (a sphere of radius
// 62 mm, 7 mm outside the magnets, theta and phi 5..85 deg in 10 deg steps): 168k P2 unknowns.
std::string benchmark32_case(const std::string& pattern) {
  return R"(dimension: 3
unit: mm
materials:
  pm: {kind: magnet, B_r: 1.3, mu_r: 1.0}
regions:
  - name: m
    shape: segment_array
    r_inner: 40
    r_outer: 55
    theta: [0, 180]
    phi: [0, 360]
    p_theta: 4
    p_phi: 8
    material: pm
    pattern: )" +
         pattern + R"(
    mesh_size: 8
boundary: {type: open, radius: 75, shell_ratio: 1.5}
mesh: {size: 16, chord_tolerance: 0.3, probe_size: 5}
solver: {order: 2}
probes:
  - {name: r62, type: sphere, radius: 62, theta: [5, 85], phi: [5, 85], step: 10}
)";
}

// Worst pointwise rms error rms(FE - charge) / rms(charge) and worst |eq. 3.117| over the
// spherical components.
std::pair<double, double> fe_against_charge(const std::string& name, const std::string& pattern) {
  const auto path = test::write_temp_case(name + ".yaml", benchmark32_case(pattern));
  const auto fe = run_case_3d(read_case(path));
  const auto charge = run_case_analytic(read_case(path), {});
  EXPECT_TRUE(fe->report.converged);
  double pointwise = 0, eq3117 = 0;
  for (const auto& c : compare_probes(charge->probes.at(0), fe->probes.at(0))) {
    if (c.component != "Brho" && c.component != "Btheta" && c.component != "Bphi")
      continue;
    std::printf("%s %s: rms %.4f T (charge) %.4f T (FE), eq. 3.117 %+.3f %%, pointwise %.3f %%\n",
                name.c_str(), c.component.c_str(), c.rms_reference, c.rms_test,
                100 * c.discrepancy_3117, 100 * c.pointwise_rms);
    pointwise = std::max(pointwise, c.pointwise_rms);
    eq3117 = std::max(eq3117, std::abs(c.discrepancy_3117));
  }
  return {pointwise, eq3117};
}

} // namespace

// Measured on this mesh: pointwise 1.36-1.52 % (parallel), 1.53-1.55 % (radial); eq. 3.117
// within 0.18 %. It is discretisation error: 5 -> 2.5 mm elements on the patch (382k
// unknowns) bring the pointwise error to 0.29-0.40 %. Bounds 3 % pointwise and 1 % for eq.
// 3.117 (the thesis's criterion). The bugs they guard against are far larger: the edge
// convention instead of the centre one differs by 25-28 % pointwise (1.3-7.7 % in eq. 3.117),
// a flipped segment by twice the field of a whole magnet.
TEST(Benchmark32FE, ParallelMagnetizationAgreesWithTheChargeModel) {
  const auto [pointwise, eq3117] =
      fe_against_charge("b32_parallel", "{type: parallel_alternating, convention: centre}");
  EXPECT_LT(pointwise, 0.03);
  EXPECT_LT(eq3117, 0.01);
}

TEST(Benchmark32FE, RadialMagnetizationAgreesWithTheChargeModel) {
  const auto [pointwise, eq3117] = fe_against_charge("b32_radial", "{type: radial_alternating}");
  EXPECT_LT(pointwise, 0.03);
  EXPECT_LT(eq3117, 0.01);
}
