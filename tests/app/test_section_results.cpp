// Sections through the 3D pipeline: the sections.csv and summary.json contracts, and a
// section inside the boundary radius but outside the faceted outer sphere refused after the
// solve with the section's line (a coarse order-1 sphere, well under a second).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "app/run3d.hpp"
#include "app/section_results.hpp"
#include "case_helpers.hpp"
#include "core/constants.hpp"
#include "core/input_error.hpp"

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
