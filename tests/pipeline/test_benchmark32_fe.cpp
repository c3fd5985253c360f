// The thesis's 32-magnet benchmark (ch. 3) and the gravity compensator's magnet pair (ch. 4)
// through the FE solver at a coarse mesh, against the charge model, in the default suite.
// The fine-mesh figures (eq. 3.117 within 0.11 % at 695k unknowns) come from `magfem validate`
// and scripts/benchmark.sh; here the point is that a regression in the segment-array
// geometry, the alternating pattern or the radial remanence of the 3D assembler fails fast.
#include <gtest/gtest.h>

#include <cstdio>

#include "pipeline/analytic_scene.hpp"
#include "pipeline/run3d.hpp"
#include "pipeline/run_analytic.hpp"
#include "tests/case_helpers.hpp"
#include "postproc/probe_compare.hpp"
#include "analytic/axisymmetric_interaction.hpp"

using namespace magfem;

namespace {

// Coarse: 16 mm air, 8 mm magnets, 5 mm elements on the probe patch (a sphere of radius
// 62 mm, 7 mm outside the magnets, theta and phi 5..85 deg in 10 deg steps): 168k P2 unknowns.
// The 32-magnet array (thesis Table 3.1) as a case-file region, elements of `mesh_size` mm.
std::string benchmark32_region(const std::string& pattern, double mesh_size) {
  return R"(  - name: m
    shape: segment_array
    r_inner: 40
    r_outer: 55
    theta: [0, 180]
    phi: [0, 360]
    p_theta: 4
    p_phi: 8
    material: pm
    pattern: )" +
         pattern + "\n    mesh_size: " + std::to_string(mesh_size) + "\n";
}

std::string benchmark32_case(const std::string& pattern) {
  return R"(dimension: 3
unit: mm
materials:
  pm: {kind: magnet, B_r: 1.3, mu_r: 1.0}
regions:
)" + benchmark32_region(pattern, 8) +
         R"(boundary: {type: open, radius: 75, shell_ratio: 1.5}
mesh: {size: 16, chord_tolerance: 0.3, probe_size: 5}
solver: {order: 2}
probes:
  - {name: r62, type: sphere, radius: 62, theta: [5, 85], phi: [5, 85], step: 10}
)";
}

// FE against the analytic model on the case's first probe: the spherical components'
// comparisons (printed).
std::vector<ComponentComparison> fe_against_analytic(const std::string& name,
                                                     const std::string& text) {
  const auto path = test::write_temp_case(name + ".yaml", text);
  const auto fe = run_case_3d(read_case(path));
  const auto analytic = run_case_analytic(read_case(path), {});
  EXPECT_TRUE(fe->report.converged);
  std::vector<ComponentComparison> out;
  for (const auto& c : compare_probes(analytic->probes.at(0), fe->probes.at(0))) {
    if (c.component != "Brho" && c.component != "Btheta" && c.component != "Bphi")
      continue;
    std::printf("%s %s: rms %.4f T (analytic) %.4f T (FE), eq. 3.117 %+.3f %%, pointwise %.3f %%\n",
                name.c_str(), c.component.c_str(), c.rms_reference, c.rms_test,
                100 * c.discrepancy_3117, 100 * c.pointwise_rms);
    out.push_back(c);
  }
  return out;
}

// Worst pointwise rms error rms(FE - charge) / rms(charge) and worst |eq. 3.117| over the
// spherical components.
std::pair<double, double> fe_against_charge(const std::string& name, const std::string& text) {
  double pointwise = 0, eq3117 = 0;
  for (const auto& c : fe_against_analytic(name, text)) {
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
  const auto [pointwise, eq3117] = fe_against_charge(
      "b32_parallel", benchmark32_case("{type: parallel_alternating, convention: centre}"));
  EXPECT_LT(pointwise, 0.03);
  EXPECT_LT(eq3117, 0.01);
}

TEST(Benchmark32FE, RadialMagnetizationAgreesWithTheChargeModel) {
  const auto [pointwise, eq3117] =
      fe_against_charge("b32_radial", benchmark32_case("{type: radial_alternating}"));
  EXPECT_LT(pointwise, 0.03);
  EXPECT_LT(eq3117, 0.01);
}

// The bounded benchmark (sec. 3.6: the array inside an iron shell) against the charge model
// with spherical imaging (the shell as an infinitely permeable sphere from its inner radius).
// The thesis's 1 mm gap over the whole sphere is 2.9 M tetrahedra even at one gap layer, so
// the shell starts at 63 mm (8 mm gap) and the probe patch sits mid-gap at 59 mm: 285k P2
// unknowns, ~30 s. Measured: pointwise 4.2 % (B_rho) and 10.4-10.8 % (tangential: the
// coarse elements across the gap), eq. 3.117 within 3.1 %; with a 5 mm patch and a 6 mm
// shell (302k unknowns) 1.2-5.3 %, so it falls with the mesh. Bounds 8 % for B_rho, 15 %
// pointwise and 5 % in eq. 3.117: without the shell the model's field differs by 25-63 %
// pointwise (B_rho -25 % in eq. 3.117), and mu_r 4000 against an ideal shell is 0.1 %.
TEST(Benchmark32FE, IronShellAgreesWithSphericalImaging) {
  const std::string text =
      R"(dimension: 3
unit: mm
materials:
  pm: {kind: magnet, B_r: 1.3, mu_r: 1.0}
  iron: {kind: linear, mu_r: 4000}
regions:
)" + benchmark32_region("{type: parallel_alternating, convention: centre}", 10) +
      R"(  - {name: iron_shell, shape: spherical_segment, r_inner: 63, r_outer: 66, material: iron,
     mesh_size: 10}
boundary: {type: open, radius: 85, shell_ratio: 1.5}
mesh: {size: 18, chord_tolerance: 0.3, gap_layers: 1, probe_size: 6}
solver: {order: 2}
probes:
  - {name: r59, type: sphere, radius: 59, theta: [5, 85], phi: [5, 85], step: 10}
)";
  for (const auto& c : fe_against_analytic("bounded", text)) {
    EXPECT_LT(c.pointwise_rms, c.component == "Brho" ? 0.08 : 0.15) << c.component;
    EXPECT_LT(std::abs(c.discrepancy_3117), 0.05) << c.component;
  }
}

// The gravity compensator's topology (parallel hemisphere in a radially magnetized
// hemispherical shell, the shell turned by 60 deg) through FE against the harmonic form of
// the charge interaction (equal to the charge model's interaction to 1e-6 of the peak,
// test_axisymmetric_interaction). The Table 4.2 gap of 1 mm is widened to 4 mm (inner radius
// 26 mm) so that a coarse mesh resolves it: 180k P2 unknowns, ~20 s. Measured: torque -0.11 %,
// force 1.9 % of |F| (the radial force is the harder quantity for a stress sphere in a gap of
// one element). Bounds 1 % and 4 %: a sign error in the radial remanence or in the rotation
// changes the torque's sign, a factor 2 in either magnet doubles it.
TEST(CompensatorFE, CoarseMeshAgreesWithTheChargeInteraction) {
  const auto path = test::write_temp_case("compensator_coarse.yaml", R"(dimension: 3
unit: mm
materials:
  pm: {kind: magnet, B_r: 1.3, mu_r: 1.0}
regions:
  - name: inner
    shape: spherical_segment
    r_inner: 0
    r_outer: 26
    theta: [0, 90]
    material: pm
    magnetization: {type: parallel, direction: [0, 0, 1]}
    mesh_size: 6
  - name: outer
    shape: spherical_segment
    r_inner: 30
    r_outer: 43
    theta: [0, 90]
    material: pm
    magnetization: {type: radial, sign: -1}
    placement: {rotate: {axis: [0, 1, 0], angle: 60}}
    mesh_size: 6
boundary: {type: open, radius: 60, shell_ratio: 1.5}
mesh: {size: 12, chord_tolerance: 0.3, gap_layers: 1}
solver: {order: 2}
forces:
  - {name: inner, type: sphere, radius: 28}
)");
  const CaseSpec spec = read_case(path);
  const auto fe = run_case_3d(spec);
  ASSERT_TRUE(fe->report.converged);
  ASSERT_EQ(fe->forces.size(), 1u);
  const AnalyticScene scene = analytic_scene(spec);
  std::vector<AnalyticMagnet> inner, outer;
  for (const auto& m : scene.magnets)
    (m.name == "inner" ? inner : outer).push_back(m);
  ASSERT_EQ(inner.size(), 1u);
  const AxisymmetricInteraction exact = axisymmetric_interaction(inner, outer);
  const Eigen::Vector3d t_fe = fe->forces[0].torque, f_fe = fe->forces[0].force;
  const double t_error = (t_fe - exact.torque).norm() / exact.torque.norm();
  const double f_error = (f_fe - exact.force).norm() / exact.force.norm();
  std::printf("compensator: torque FE (%.4f, %.4f, %.4f) N m, charge (%.4f, %.4f, %.4f) N m, "
              "error %.3f %%; force error %.3f %% of %.2f N\n",
              t_fe.x(), t_fe.y(), t_fe.z(), exact.torque.x(), exact.torque.y(), exact.torque.z(),
              100 * t_error, 100 * f_error, exact.force.norm());
  EXPECT_GT(exact.torque.norm(), 1.0) << "the turned shell must exert a torque to compare";
  EXPECT_LT(t_error, 0.01);
  EXPECT_LT(f_error, 0.04);
}
