// Line sections of planar and axisymmetric solutions (postproc/section_flux2d): the flux is
// integrated from the element field over the pieces of the line in each triangle.
// - Exact values: a diametrically magnetized cylinder (planar, mu_r 1) has the uniform
//   B = B_r / 2 inside, so a diameter across the magnetization carries B_r a per metre; a
//   uniformly magnetized sphere (axisymmetric) has the uniform B = (2/3) B_r inside, so its
//   equatorial disk carries (2/3) B_r pi a^2. Both within the element and polygon error.
// - An identity: with B = curl A the flux through any line is the difference of the potential
//   at its ends (planar A(start) - A(end); axisymmetric 2 pi (r A)(end) - 2 pi (r A)(start)),
//   which holds for the discrete field exactly (A is continuous, B.n integrated exactly), so
//   it is checked to round-off on an oblique line through magnet and air. Would fail on: a
//   wrong normal or sign, a dropped 2 pi r weight, pieces counted twice or missed, B read at
//   the wrong point of the element.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/constants.hpp"
#include "core/input_error.hpp"
#include "pipeline/run2d.hpp"
#include "postproc/point_locator2d.hpp"
#include "tests/case_helpers.hpp"

using namespace magfem;

namespace {

constexpr double a = 0.010, B_r = 1.0;

const char* cylinder_case = R"(
unit: mm
materials:
  pm: {kind: magnet, B_r: 1.0, mu_r: 1.0}
regions:
  - {name: magnet, shape: disk, center: [0, 0], radius: 10, material: pm,
     magnetization: {type: parallel, angle: 0}, mesh_size: 2.0}
boundary: {type: open, radius: 25, shell_ratio: 1.5}
mesh: {size: 4.0, chord_tolerance: 0.002}
solver: {order: 2}
sections:
  - {name: diameter, type: line, start: [0, 10], end: [0, -10]}
  - {name: oblique, type: line, start: [-15, -5], end: [12, 8]}
)";

const char* sphere_case = R"(
dimension: axi
unit: mm
materials:
  pm: {kind: magnet, B_r: 1.0, mu_r: 1.0}
regions:
  - {name: ball, shape: disk, center: [0, 0], radius: 10, material: pm,
     magnetization: {type: parallel}, mesh_size: 2.0}
boundary: {type: open, radius: 30, shell_ratio: 1.5}
mesh: {size: 4.0, chord_tolerance: 0.002}
solver: {order: 2}
sections:
  - {name: equator, type: line, start: [0, 0], end: [10, 0]}
  - {name: oblique, type: line, start: [3, -14], end: [16, 9]}
)";

double potential_at(const Run2D& run, const Eigen::Vector2d& x) {
  const PointLocator2D locator(run.mesh);
  const auto at = locator.locate(x);
  EXPECT_TRUE(at.has_value());
  return run.field->A(at->triangle, at->bary);
}

} // namespace

TEST(SectionFlux2D, PlanarCylinderDiameterCarriesBrTimesRadius) {
  const auto run = run_case_2d(read_case(test::write_temp_case("sf_cyl.yaml", cylinder_case)));
  ASSERT_EQ(run->sections.size(), 2u);
  const auto& d = run->sections[0];
  // Start (0, 10) to end (0, -10): the normal z x t is +x, along the magnetization.
  const double exact = B_r * a;
  std::cout << "diameter flux " << d.total.flux_Wb << " Wb/m, exact " << exact << "\n";
  // The magnet is a polygon of sagitta s = 2 um inside the circle: the line's last ~s at each
  // end runs in air, where B_x = -B_r / 2 at the poles, so the flux falls short by up to
  // 2 s / a = 4e-4 (measured 3.9e-4; the P2 field itself is exact here). 3 s / a.
  EXPECT_NEAR(d.total.flux_Wb, exact, 3 * 2e-6 / a * exact);
  EXPECT_NEAR(d.total.area_m2, 2 * a * 1.0, 1e-12); // per metre of depth
  EXPECT_NEAR(d.total.Bn_avg_T(), B_r / 2, 3 * 2e-6 / a);
  EXPECT_NEAR(d.total.B_avg_T(), B_r / 2, 3 * 2e-6 / a);
  // Inside the magnet but for the polygon's sagitta at the two ends (in air).
  ASSERT_FALSE(d.parts.empty());
  EXPECT_EQ(d.parts.back().region, 0);
  EXPECT_GT(d.parts.back().area_m2, (1 - 2 * 2e-6 / a) * 2 * a);

  // The oblique line from air through the magnet into air: the potential's difference.
  const auto& o = run->sections[1];
  const double difference =
      potential_at(*run, {-0.015, -0.005}) - potential_at(*run, {0.012, 0.008});
  std::cout << "oblique flux " << o.total.flux_Wb << ", A(start) - A(end) " << difference << "\n";
  EXPECT_NEAR(o.total.flux_Wb, difference, 1e-9 * std::abs(difference));
  EXPECT_EQ(o.parts.size(), 2u); // air and magnet
  EXPECT_NEAR(o.total.area_m2, std::hypot(0.027, 0.013), 1e-12);
}

TEST(SectionFlux2D, AxisymmetricSphereEquatorCarriesTwoThirdsBrPiASquared) {
  const auto run = run_case_2d(read_case(test::write_temp_case("sf_sph.yaml", sphere_case)));
  ASSERT_EQ(run->sections.size(), 2u);
  const auto& e = run->sections[0];
  const double exact = 2.0 / 3.0 * B_r * pi * a * a;
  std::cout << "equator flux " << e.total.flux_Wb << " Wb, exact " << exact << "\n";
  // As the cylinder's (polygon sagitta 2 um at the rim; measured 1.5e-4).
  EXPECT_NEAR(e.total.flux_Wb, exact, 3 * 2e-6 / a * exact);
  EXPECT_NEAR(e.total.area_m2, pi * a * a, 1e-12 * pi * a * a); // 2 pi r dr, exactly
  EXPECT_NEAR(e.total.Bn_avg_T(), 2.0 / 3.0 * B_r, 3 * 2e-6 / a);

  const auto& o = run->sections[1];
  const Eigen::Vector2d s(0.003, -0.014), t(0.016, 0.009);
  const double difference =
      2 * pi * (t.x() * potential_at(*run, t) - s.x() * potential_at(*run, s));
  std::cout << "oblique flux " << o.total.flux_Wb << ", 2 pi (rA)(end) - (rA)(start) " << difference
            << "\n";
  EXPECT_NEAR(o.total.flux_Wb, difference, 1e-9 * std::abs(difference));
  EXPECT_NEAR(o.total.area_m2, pi * (s.x() + t.x()) * (t - s).norm(), 1e-12);
}

TEST(SectionFlux2D, OutputsAndBadInput) {
  const auto run = run_case_2d(read_case(test::write_temp_case("sf_out.yaml", sphere_case)));
  const auto dir = std::filesystem::temp_directory_path() / "magfem_sf2d_out";
  std::filesystem::remove_all(dir);
  write_outputs_2d(*run, dir);
  std::ifstream csv(dir / "sections.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "section,region,region_id,flux_Wb,area_m2,Bn_avg_T,B_avg_T");
  EXPECT_TRUE(std::filesystem::exists(dir / "summary.json"));

  std::string text = sphere_case;
  const std::string line = "start: [0, 0], end: [10, 0]";
  auto with = [&](const std::string& replacement) {
    std::string t = text;
    t.replace(t.find(line), line.size(), replacement);
    return test::write_temp_case("sf_bad.yaml", t);
  };
  EXPECT_THROW(read_case(with("start: [-1, 0], end: [10, 0]")), InputError); // r < 0
  EXPECT_THROW(read_case(with("start: [0, 0], end: [0, 0]")), InputError);   // no length
  EXPECT_THROW(read_case(with("start: [0, 0], end: [31, 0]")), InputError);  // outside
  std::string disk = text;
  disk.replace(disk.find("type: line, start: [0, 0], end: [10, 0]"),
               std::string("type: line, start: [0, 0], end: [10, 0]").size(),
               "type: disk, center: [0, 0, 0], normal: [0, 0, 1], radius: 5");
  try {
    read_case(test::write_temp_case("sf_bad2.yaml", disk));
    ADD_FAILURE() << "a 3D section type in a 2D case was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("(line)"), std::string::npos) << e.what();
  }
}
