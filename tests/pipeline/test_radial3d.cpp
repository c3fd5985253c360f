// The radial-remanence path of the 3D assembler (magnetization e_rho about a part's origin)
// in the default suite: a full radial shell, whose field is known exactly, and a radial
// hemispherical shell against the charge model.
#include <gtest/gtest.h>

#include <cmath>

#include "pipeline/run3d.hpp"
#include "pipeline/run_analytic.hpp"
#include "tests/case_helpers.hpp"
#include "core/constants.hpp"

using namespace magfem;

namespace {

std::string shell_case(const std::string& theta, double mesh_size, const std::string& probes) {
  return R"(dimension: 3
unit: mm
materials:
  pm: {kind: magnet, B_r: 1.0, mu_r: 1.0}
regions:
  - name: shell
    shape: spherical_segment
    r_inner: 5
    r_outer: 8
    theta: )" +
         theta + R"(
    material: pm
    magnetization: {type: radial}
    mesh_size: )" +
         std::to_string(mesh_size) + R"(
    placement: {translate: [1, 2, 3]}
boundary: {type: open, radius: 25}
mesh: {size: 4}
)" + probes;
}

} // namespace

// A uniformly radially magnetized full shell has a spherically symmetric magnetic charge of
// total zero: H = -M e_rho inside the shell material and zero elsewhere, so B = 0 everywhere.
// (Ignoring the remanence would give H = 0 in the shell; a radial centre at the global origin
// instead of the part's, here displaced to (1, 2, 3) mm, would give B != 0.) The faceted
// surfaces break the symmetry at the level of the chord error: measured rms |B| 1.5e-4 T and
// rms mu0 |H - H_exact| 9e-4 T; the bounds allow 5-7x that for other meshes, while the bugs
// named above are of order 0.1-1 T.
TEST(Radial3D, FullRadialShellHasNoFieldAndHEqualsMinusM) {
  auto run = run_case_3d(
      read_case(test::write_temp_case("radial_shell.yaml", shell_case("[0, 180]", 2.0, ""))));
  ASSERT_TRUE(run->report.converged);
  const Eigen::Vector3d origin(1e-3, 2e-3, 3e-3);
  const std::array<double, 4> centroid{0.25, 0.25, 0.25, 0.25};
  double b2 = 0, h_error2 = 0, volume_all = 0, volume_shell = 0;
  for (std::size_t t = 0; t < run->mesh.n_tets(); ++t) {
    if (run->problem.is_shell(t))
      continue;
    const auto& n = run->mesh.nodes;
    const auto& tet = run->mesh.tets[t];
    const double v =
        std::abs(
            (n[tet[1]] - n[tet[0]]).dot((n[tet[2]] - n[tet[0]]).cross(n[tet[3]] - n[tet[0]]))) /
        6;
    const Eigen::Vector3d b = run->field->B(t, centroid);
    b2 += b.squaredNorm() * v;
    volume_all += v;
    if (run->mesh.tet_part[t] == 0) {
      const Eigen::Vector3d rho = (run->field->point(t, centroid) - origin).normalized();
      const Eigen::Vector3d h_exact = -1.0 / mu0 * rho;
      h_error2 += (run->field->H(t, centroid) - h_exact).squaredNorm() * mu0 * mu0 * v;
      volume_shell += v;
    }
  }
  const double b_rms = std::sqrt(b2 / volume_all), h_rms = std::sqrt(h_error2 / volume_shell);
  std::printf("radial shell: rms |B| %.3e T, rms |mu0 (H - H_exact)| %.3e T (B_r 1 T)\n", b_rms,
              h_rms);
  EXPECT_LT(b_rms, 1e-3);
  EXPECT_LT(h_rms, 5e-3);
}

// Half the shell (theta 0..90) has a net field; the charge model integrates its surface and
// volume charges exactly. Tolerance 3 % of the peak: the coarse mesh's measured error is
// 0.3 % on the axis and 1.5 % beside the shell's rim, where the field varies fastest.
TEST(Radial3D, RadialHemisphericalShellMatchesTheChargeModel) {
  const std::string probes = R"(probes:
  - {name: axis, type: line, start: [1, 2, 12], end: [1, 2, 20], points: 9}
  - {name: side, type: line, start: [11, 2, 4], end: [18, 2, 4], points: 8}
)";
  const auto path =
      test::write_temp_case("radial_hemishell.yaml", shell_case("[0, 90]", 1.2, probes));
  const auto fe = run_case_3d(read_case(path));
  const auto charge = run_case_analytic(read_case(path), {});
  ASSERT_EQ(fe->probes.size(), charge->probes.size());
  for (std::size_t p = 0; p < fe->probes.size(); ++p) {
    const auto& f = fe->probes[p];
    const auto& c = charge->probes[p];
    ASSERT_EQ(f.rows.size(), c.rows.size());
    double peak = 0, worst = 0;
    for (std::size_t i = 0; i < f.rows.size(); ++i)
      for (const char* comp : {"Bx", "By", "Bz"}) {
        peak = std::max(peak, std::abs(c.rows[i][c.column(comp)]));
        worst = std::max(worst, std::abs(f.rows[i][f.column(comp)] - c.rows[i][c.column(comp)]));
      }
    std::printf("%s: peak %.4f T, max |FE - charge| %.2e T (%.2f %%)\n", f.name.c_str(), peak,
                worst, 100 * worst / peak);
    EXPECT_GT(peak, 1e-2) << "the hemispherical shell must have a field to compare";
    EXPECT_LT(worst, 0.03 * peak) << f.name;
  }
}
