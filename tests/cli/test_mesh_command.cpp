// `magfem mesh`: the mesh it shows is the one `magfem solve` would solve on (same elements and
// unknowns, --mesh-scale and --order honoured), and its per-region measures add up to the
// geometry: the axisymmetric solenoid's winding volume 2 pi r_mean A exactly (straight edges
// of a rectangle), the 3D sphere's volume to its faceting.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "cli/mesh_command.hpp"
#include "core/constants.hpp"
#include "core/input_error.hpp"
#include "pipeline/run2d.hpp"
#include "tests/case_helpers.hpp"

using namespace magfem;

namespace {

nlohmann::json mesh_summary(const std::vector<std::string>& args, const std::string& out) {
  const auto dir = std::filesystem::temp_directory_path() / "magfem_tests" / out;
  std::vector<std::string> all = args;
  all.insert(all.end(), {"--out", dir.string()});
  EXPECT_EQ(run_mesh_command(all), 0);
  // mesh.vtu's XML: region_id stored as the integer it is, and the regions named (per cell
  // for ParaView's legend, and as a table indexed by region_id).
  std::ifstream vtu(dir / "mesh.vtu");
  const std::string xml((std::istreambuf_iterator<char>(vtu)), std::istreambuf_iterator<char>());
  EXPECT_NE(xml.find(R"(<DataArray type="Int32" Name="region_id")"), std::string::npos);
  EXPECT_NE(xml.find(R"(<Array type="String" Name="region" )"), std::string::npos);
  EXPECT_NE(xml.find(R"(<Array type="String" Name="region_names" )"), std::string::npos);
  return nlohmann::json::parse(std::ifstream(dir / "summary.json"));
}

const nlohmann::json& region(const nlohmann::json& summary, const std::string& name) {
  for (const auto& r : summary["regions"])
    if (r["name"] == name)
      return r;
  throw std::runtime_error("no region " + name);
}

} // namespace

TEST(MeshCommand, IsTheMeshTheSolveUsesAtEveryScaleAndOrder) {
  const std::string file = test::example("axi/solenoid.yaml");
  for (const double scale : {1.0, 2.0}) {
    for (const int order : {1, 2}) {
      const auto s = mesh_summary(
          {file, "--mesh-scale", std::to_string(scale), "--order", std::to_string(order)},
          "mesh_command_axi");
      RunOverrides ov;
      ov.mesh_scale = scale;
      ov.order = order;
      const auto run = run_case_2d(read_case(file), ov);
      EXPECT_EQ(s["elements"].get<std::size_t>(), run->mesh.n_triangles()) << scale;
      EXPECT_EQ(s["unknowns"].get<int>(), run->dofs->n_dofs()) << scale << " " << order;
    }
  }
}

TEST(MeshCommand, AxisymmetricRegionVolumesAreTheSolidsOfRevolution) {
  // solenoid.yaml's winding: r 10..15 mm, z -15..15 mm: V = pi (R2^2 - R1^2) h, exactly for a
  // mesh of straight-sided triangles filling a rectangle (Pappus per triangle is exact).
  const auto s = mesh_summary({test::example("axi/solenoid.yaml")}, "mesh_command_volume");
  const double exact = pi * (0.015 * 0.015 - 0.010 * 0.010) * 0.030;
  EXPECT_NEAR(region(s, "winding")["volume_m3"].get<double>(), exact, 1e-12 * exact);
  EXPECT_LE(region(s, "winding")["edge_max_m"].get<double>(), 1.0e-3 * (1 + 1e-9));
}

TEST(MeshCommand, SphereVolumeWithinItsFaceting) {
  const char* text = R"(dimension: 3
unit: mm
materials:
  pm: {kind: magnet, B_r: 1.0, mu_r: 1.0}
regions:
  - {name: ball, shape: spherical_segment, r_outer: 10, material: pm,
     magnetization: {type: parallel, direction: [0, 0, 1]}, mesh_size: 3}
boundary: {type: open, radius: 20, shell_ratio: 1.5}
mesh: {size: 6, chord_tolerance: 0.1}
solver: {order: 1}
)";
  const auto file = test::write_temp_case("mesh_command_sphere.yaml", text);
  const auto s = mesh_summary({file, "--plane", "z"}, "mesh_command_sphere");
  const double ball = region(s, "ball")["volume_m3"].get<double>();
  const double exact = 4.0 / 3 * pi * 1e-6; // R = 10 mm
  // An inscribed polyhedron with chord gap g loses at most 3 g / R of the volume (0.1/10 x 3).
  EXPECT_LT(ball, exact);
  EXPECT_GT(ball, exact * (1 - 3 * 0.1 / 10));
  EXPECT_EQ(s["unknowns"].get<int>(), s["nodes"].get<int>()); // order 1: one per node
  EXPECT_GT(s["shell_elements"].get<int>(), 0);
  EXPECT_EQ(s["picture_plane"], "z = 0");
  EXPECT_EQ(s["mesh_split_radius_mm"].get<double>(), 0.0); // a small mesh: one TetGen call
}

// A large spherical case is meshed as two pieces cut at its magnets' outer sphere (55 mm),
// and the summary says where (planted: the radius left in metres -> 0.055 -> fails).
TEST(MeshCommand, SaysWhereALargeMeshWasCut) {
  const auto s = mesh_summary(
      {test::example("3d/benchmark32_parallel.yaml"), "--mesh-scale", "2", "--order", "1"},
      "mesh_command_split");
  EXPECT_GT(s["elements"].get<long>(), 400000);
  EXPECT_DOUBLE_EQ(s["mesh_split_radius_mm"].get<double>(), 55.0);
}

TEST(MeshCommand, BadOptionsAreNamed) {
  const std::string file = test::example("axi/solenoid.yaml");
  try {
    run_mesh_command({file, "--plane", "w"});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "--plane");
  }
  try {
    run_mesh_command({file, "--mesh-scael", "2"});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean --mesh-scale?"), std::string::npos);
  }
}
