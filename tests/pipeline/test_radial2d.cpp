// Radial remanence through the planar 2D solver: a uniformly radially magnetized ring,
// placed off the origin, has a field of its own that vanishes exactly. Its magnetic charge
// (-M/r in the ring, -M and +M on its inner and outer circles) encloses -2 pi M r per unit
// length at radius r inside the ring and nothing outside, so H = -M e_r in the ring, zero
// elsewhere, and B = mu0 (H + M) = 0 everywhere. Ignoring the remanence gives H = 0 in the
// ring; a radial centre at the origin instead of the ring's, or a wrong sign, gives B of
// order B_r.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/case_helpers.hpp"
#include "core/constants.hpp"

using namespace magfem;

TEST(Radial2D, RadialRingHasNoFieldAndHEqualsMinusM) {
  const auto path = test::write_temp_case("radial_ring.yaml", R"(unit: mm
materials:
  pm: {kind: magnet, B_r: 1.0, mu_r: 1.0}
regions:
  - {name: ring, shape: annulus, center: [3, -2], r_inner: 5, r_outer: 8, material: pm,
     magnetization: {type: radial, center: [3, -2], sign: -1}, mesh_size: 0.6}
boundary: {type: open, radius: 25}
mesh: {size: 2}
)");
  const auto run = run_case_2d(read_case(path));
  ASSERT_TRUE(run->report.converged);
  const Eigen::Vector2d centre(3e-3, -2e-3);
  const std::array<double, 3> centroid{1.0 / 3, 1.0 / 3, 1.0 / 3};
  double b2 = 0, h_error2 = 0, area_all = 0, area_ring = 0;
  for (std::size_t t = 0; t < run->mesh.n_triangles(); ++t) {
    if (run->problem.is_shell(t))
      continue;
    const auto& tri = run->mesh.triangles[t];
    const auto& n = run->mesh.nodes;
    const Eigen::Vector2d e1 = n[tri[1]] - n[tri[0]], e2 = n[tri[2]] - n[tri[0]];
    const double area = 0.5 * std::abs(e1.x() * e2.y() - e1.y() * e2.x());
    const Eigen::Vector2d b = run->field->B(t, centroid);
    b2 += b.squaredNorm() * area;
    area_all += area;
    if (run->mesh.triangle_part[t] == 0) {
      const Eigen::Vector2d x = run->field->point(t, centroid);
      // sign -1: the remanence points inward, so H = -M points outward.
      const Eigen::Vector2d h_exact = (x - centre).normalized() / mu0;
      h_error2 += (run->field->H(t, x, b) - h_exact).squaredNorm() * mu0 * mu0 * area;
      area_ring += area;
    }
  }
  const double b_rms = std::sqrt(b2 / area_all), h_rms = std::sqrt(h_error2 / area_ring);
  std::printf("radial ring: rms |B| %.3e T, rms mu0 |H - H_exact| %.3e T (B_r 1 T)\n", b_rms,
              h_rms);
  // The polygonal circles (chord tolerance) break the symmetry slightly: measured 2.4e-4 T
  // and 6.9e-4 T. Bounds at ~3-4x; the radial centre left at the origin instead (checked by
  // hand) gives |B| up to 0.58 T in the ring and 0.36 T in the air.
  EXPECT_LT(b_rms, 1e-3);
  EXPECT_LT(h_rms, 2e-3);
}
