// Sections through the 3D pipeline: the sections.csv and summary.json contracts, and a
// section inside the boundary radius but outside the faceted outer sphere refused after the
// solve with the section's line (a coarse order-1 sphere, well under a second); the flux of
// a solenoid through a disk in its mid-plane against Maxwell's mutual inductance.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "tests/case_helpers.hpp"
#include "core/constants.hpp"
#include "core/gauss_legendre.hpp"
#include "core/input_error.hpp"
#include "pipeline/run3d.hpp"
#include "pipeline/run_analytic.hpp"
#include "pipeline/section_results.hpp"
#include "sources/loop_field.hpp"

using namespace magfem;

namespace {

const char* sphere_case = R"(dimension: 3
unit: mm
materials:
  pm: {kind: magnet, B_r: 1.0, mu_r: 1.0}
regions:
  - {name: ball, shape: spherical_segment, r_outer: 10, material: pm,
     magnetization: {type: parallel, direction: [0, 0, 1]}, mesh_size: 4}
boundary: {type: dirichlet, radius: 25}
mesh: {size: 8, chord_tolerance: 0.5}
solver: {order: 1}
probes:
  - {name: grid, type: plane, center: [0, 0, 1], normal: [0, 0, 1], size: [10, 4], points: [3, 2]}
sections:
  - {name: inside, type: rectangle, center: [0, 0, 1], normal: [0, 0, 1], size: [6, 4]}
  - {name: equator, type: disk, center: [0, 0, 0], normal: [0, 0, -1], radius: 15}
)";

std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

} // namespace

TEST(SectionResults, CsvAndSummaryContracts) {
  const auto run = run_case_3d(read_case(test::write_temp_case("sections_app.yaml", sphere_case)));
  const auto dir = std::filesystem::temp_directory_path() / "magfem_tests" / "sections_app_out";
  std::filesystem::remove_all(dir);
  write_outputs_3d(*run, dir);
  const std::string csv = read_text(dir / "sections.csv");
  std::istringstream lines(csv);
  std::vector<std::string> rows;
  for (std::string l; std::getline(lines, l);)
    rows.push_back(l);
  ASSERT_EQ(rows.size(), 6u) << csv;
  EXPECT_EQ(rows[0], "section,region,region_id,flux_Wb,area_m2,Bn_avg_T,B_avg_T");
  EXPECT_EQ(rows[1].rfind("inside,ball,0,", 0), 0u) << rows[1];
  EXPECT_EQ(rows[2].rfind("inside,total,,", 0), 0u) << rows[2];
  EXPECT_EQ(rows[3].rfind("equator,air,-1,", 0), 0u) << rows[3];
  EXPECT_EQ(rows[4].rfind("equator,ball,0,", 0), 0u) << rows[4];
  EXPECT_EQ(rows[5].rfind("equator,total,,", 0), 0u) << rows[5];

  const auto j = nlohmann::json::parse(read_text(dir / "summary.json"));
  ASSERT_EQ(j["sections"].size(), 2u);
  const auto& eq = j["sections"][1];
  EXPECT_EQ(eq["name"], "equator");
  EXPECT_EQ(eq["type"], "disk");
  EXPECT_NEAR(eq["area_m2"].get<double>(), pi * 0.015 * 0.015, 1e-15);
  ASSERT_EQ(eq["regions"].size(), 2u);
  EXPECT_EQ(eq["regions"][1]["name"], "ball");
  EXPECT_EQ(eq["regions"][1]["region_id"], 0);
  // The normal points down: the ball's flux (B up inside) counts negative.
  EXPECT_LT(eq["regions"][1]["flux_Wb"].get<double>(), 0);
  EXPECT_NEAR(j["sections"][0]["Bn_avg_T"].get<double>(), 2.0 / 3, 0.1); // coarse P1

  const std::string grid = read_text(dir / "grid.csv");
  EXPECT_EQ(grid.substr(0, grid.find('\n')), "u,v,x,y,z,Bx,By,Bz,Bn,region_id");
}

TEST(SectionResults, SectionOutsideTheFacetedBoundaryIsRefusedWithItsLine) {
  std::string text = sphere_case;
  const std::string from = "radius: 15}";
  text.replace(text.find(from), from.size(), "radius: 24.9}");
  try {
    run_case_3d(read_case(test::write_temp_case("sections_outside.yaml", text)));
    ADD_FAILURE() << "accepted a section beyond the faceted boundary";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 15) << e.what();
    EXPECT_EQ(e.field(), "sections[1]") << e.what();
    EXPECT_NE(std::string(e.what()).find("leaves the meshed domain"), std::string::npos)
        << e.what();
  }
}

// A solenoid in air (r 10..12 mm, length 60 mm, 600 turns, 2 A; no iron): the flux through
// the mid-plane disk of radius rho = 8 mm is I times the mutual inductance of that disk's rim
// (a loop) and the coil, (N / A) int int M(rho, R, z) dR dz over the winding (Maxwell's loop
// formula, Gauss-Legendre 16 x 64: smooth, as the loop stays 2 mm from the winding). The
// long-solenoid value mu0 N I / L pi rho^2 is 6.2 % higher (the ends) and only printed.
// Tolerance: the element error. B is the coil's source field minus grad phi, and phi is not
// zero (it carries the field across the open boundary's shell), so its P1 error shows:
// measured +2.6e-4 on this mesh (size 12 mm, 21k tets, under a second), +2.4e-5 at size 6
// (115k tets). 5e-4 allows the first; a field read at the wrong point, a flux of mu0 H in
// the wrong direction or of the source field alone at the wrong scale fails by far more.
TEST(SectionResults, SolenoidMidPlaneFluxEqualsMaxwellsMutualInductance) {
  const auto path = test::write_temp_case("sections_solenoid.yaml", R"(dimension: 3
unit: mm
regions:
  - {name: bore, shape: cylinder, r_outer: 5, height: 10, material: air,
     placement: {translate: [0, 0, -5]}}
coils:
  - {name: coil, shape: solenoid, r_inner: 10, r_outer: 12, length: 60, center: [0, 0, 0],
     axis: [0, 0, 1], turns: 600, current: 2}
boundary: {type: open, radius: 45}
mesh: {size: 12, chord_tolerance: 1}
solver: {order: 1}
output: {vtu: false, inductance: false}
sections:
  - {name: mid, type: disk, center: [0, 0, 0], normal: [0, 0, 1], radius: 8}
)");
  const auto run = run_case_3d(read_case(path));
  ASSERT_EQ(run->sections.size(), 1u);
  const double rho = 8e-3, r1 = 10e-3, r2 = 12e-3, len = 60e-3, turns = 600, current = 2;
  const QuadratureRule qr = gauss_legendre(16, r1, r2), qz = gauss_legendre(64, -len / 2, len / 2);
  double m = 0;
  for (std::size_t i = 0; i < qr.x.size(); ++i)
    for (std::size_t k = 0; k < qz.x.size(); ++k)
      m += qr.w[i] * qz.w[k] * loop_mutual_inductance(rho, qr.x[i], qz.x[k]);
  const double exact = current * turns / ((r2 - r1) * len) * m;
  const double flux = run->sections[0].total.flux_Wb;
  std::printf("solenoid mid-plane flux: FE %.7g Wb, Maxwell %.7g Wb (%+.1e), long-solenoid "
              "%.7g Wb, %zu tets\n",
              flux, exact, flux / exact - 1, mu0 * turns * current / len * pi * rho * rho,
              run->mesh.n_tets());
  EXPECT_NEAR(flux, exact, 5e-4 * exact);
}

// `magfem analytic` computes fields at points only: each section is named in the notes
// (console and summary.json) instead of being dropped without a word.
TEST(SectionResults, AnalyticRunNamesEverySectionItDoesNotCompute) {
  const auto run = run_case_analytic(
      read_case(test::write_temp_case("sections_analytic.yaml", sphere_case)), {});
  int named = 0;
  for (const auto& note : run->scene.notes)
    named += note.find("section inside:") == 0 || note.find("section equator:") == 0;
  EXPECT_EQ(named, 2);
}
