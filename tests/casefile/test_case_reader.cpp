// casefile/: what a case file says arrives in SI, in the global frame, with every shape,
// placement, sign and radial centre as documented; bad input names the exact line and
// dotted field path.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <regex>
#include <string>

#include "casefile/case_spec.hpp"
#include "core/input_error.hpp"

using namespace magfem;

namespace {

constexpr double pi = std::numbers::pi;

std::string write_case(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::temp_directory_path() / "magfem_tests" / "casefile";
  std::filesystem::create_directories(dir);
  const auto path = dir / name;
  std::ofstream(path) << text;
  return path.string();
}

// In centimetres, so that a missed unit conversion is a factor 10 off, not 1000 (a factor
// that could hide behind mm defaults).
const char* case3d = R"(dimension: 3
unit: cm
materials:
  pm: {kind: magnet, B_r: 1.2, mu_r: 1.05}
regions:
  - name: ball
    shape: spherical_segment
    r_outer: 1
    theta: [0, 90]
    material: pm
    magnetization: {type: radial, center: [0, 0, 0.5], sign: -1}
    placement: {translate: [0, 0, 2], rotate: {axis: [0, 1, 0], angle: 90}}
  - name: can
    shape: cylinder
    r_inner: 0.5
    r_outer: 1
    height: 2
    material: pm
    magnetization: {type: axial}
    placement: {translate: [0, 0, -4]}
    group: arm
  - name: brick
    shape: box
    size: [1, 2, 3]
    material: pm
    magnetization: {type: parallel, direction: [3, 0, 4]}
    placement: {translate: [4, 0, 0]}
    mesh_size: 0.25
boundary: {type: open, radius: 8}
mesh: {size: 2, shell_size: 3}
forces:
  - {name: on_ball, type: sphere, center: [0, 0, 2], radius: 1.5, check_radius: 1.7,
     torque_point: [0, 0, 1]}
  - {name: on_brick, type: box, center: [4, 0, 0], size: [2, 3, 4]}
)";

} // namespace

TEST(CaseReader3D, ShapesPlacementsAndMagnetizationsArriveInSiAndTheGlobalFrame) {
  const auto spec = read_case(write_case("case3d.yaml", case3d));
  ASSERT_EQ(spec.dimension, 3);
  EXPECT_DOUBLE_EQ(spec.length_unit, 0.01);
  const auto& parts = spec.geometry3d.parts;
  ASSERT_EQ(parts.size(), 3u);

  const auto& ball = std::get<SphericalSegment>(parts[0].shape);
  EXPECT_DOUBLE_EQ(ball.r_inner, 0);
  EXPECT_DOUBLE_EQ(ball.r_outer, 0.01);
  EXPECT_DOUBLE_EQ(ball.theta_min, 0);
  EXPECT_DOUBLE_EQ(ball.theta_max, pi / 2);
  EXPECT_DOUBLE_EQ(ball.phi_max - ball.phi_min, 2 * pi); // default: the full azimuth
  // Rotated 90 degrees about +y (right-hand rule): local +z points along global +x; then
  // moved to z = 2 cm.
  const Vec3 tip = parts[0].placement.to_global(Vec3(0, 0, 0.01));
  EXPECT_LT((tip - Vec3(0.01, 0, 0.02)).norm(), 1e-15);
  // The radial centre (0, 0, 0.5) cm local is (0.5, 0, 2) cm global, and sign -1 points
  // the remanence at it: just beyond it along +x the direction is -x.
  const auto& radial = spec.regions[0].magnetization;
  const Vec3 centre(0.005, 0, 0.02);
  EXPECT_LT((radial.unit_at(centre + Vec3(1e-4, 0, 0)) - Vec3(-1, 0, 0)).norm(), 1e-12);
  EXPECT_LT((radial.unit_at(centre + Vec3(0, 0, 1e-4)) - Vec3(0, 0, -1)).norm(), 1e-12);

  const auto& can = std::get<Cylinder>(parts[1].shape);
  EXPECT_DOUBLE_EQ(can.r_inner, 0.005);
  EXPECT_DOUBLE_EQ(can.r_outer, 0.01);
  EXPECT_DOUBLE_EQ(can.height, 0.02);
  EXPECT_EQ(parts[1].group, "arm");
  EXPECT_LT((parts[1].placement.translation - Vec3(0, 0, -0.04)).norm(), 1e-15);
  EXPECT_LT((spec.regions[1].magnetization.unit_at(Vec3(0.007, 0, -0.03)) - Vec3::UnitZ()).norm(),
            1e-15); // axial: the cylinder's axis

  const auto& brick = std::get<Box>(parts[2].shape);
  EXPECT_LT((brick.size - Vec3(0.01, 0.02, 0.03)).norm(), 1e-15);
  EXPECT_DOUBLE_EQ(parts[2].max_size, 0.0025);
  EXPECT_LT((spec.regions[2].magnetization.unit_at(Vec3::Zero()) - Vec3(0.6, 0, 0.8)).norm(),
            1e-15); // normalised

  EXPECT_DOUBLE_EQ(spec.geometry3d.outer.radius, 0.08);
  EXPECT_DOUBLE_EQ(spec.geometry3d.options.default_size, 0.02);
  EXPECT_DOUBLE_EQ(spec.geometry3d.options.shell_size, 0.03);
  ASSERT_EQ(spec.regions[0].material->name, "pm");
  EXPECT_DOUBLE_EQ(spec.regions[0].material->B_r, 1.2);
}

TEST(CaseReader3D, ForceSpecsConvertLengthsAndKeepTheirLines) {
  const auto spec = read_case(write_case("case3d_forces.yaml", case3d));
  ASSERT_EQ(spec.forces.size(), 2u);
  const auto& s = spec.forces[0];
  EXPECT_EQ(s.kind, ForceSpec::Kind::sphere);
  EXPECT_LT((s.center - Vec3(0, 0, 0.02)).norm(), 1e-15);
  EXPECT_DOUBLE_EQ(s.radius, 0.015);
  EXPECT_DOUBLE_EQ(s.check_radius, 0.017);
  EXPECT_LT((s.torque_point - Vec3(0, 0, 0.01)).norm(), 1e-15);
  EXPECT_EQ(s.line, 32);
  const auto& b = spec.forces[1];
  EXPECT_EQ(b.kind, ForceSpec::Kind::box);
  EXPECT_LT((b.size - Vec3(0.02, 0.03, 0.04)).norm(), 1e-15);
  EXPECT_LT((b.center - Vec3(0.04, 0, 0)).norm(), 1e-15);
}

TEST(CaseReader2D, MagnetizationAnglesSignsAndMetres) {
  const auto spec = read_case(write_case("case2d.yaml", R"(unit: m
materials:
  pm: {kind: magnet, B_r: 1.0, mu_r: 1.0}
regions:
  - {name: a, shape: disk, center: [0, 0], radius: 0.01, material: pm,
     magnetization: {type: parallel, angle: 30}}
  - {name: b, shape: disk, center: [0.03, 0], radius: 0.01, material: pm,
     magnetization: {type: parallel, angle: 120, sign: -1}}
  - {name: c, shape: annulus, center: [0, 0.04], r_inner: 0.005, r_outer: 0.01, material: pm,
     magnetization: {type: radial, center: [0, 0.04]}}
boundary: {type: open, radius: 0.1}
mesh: {size: 0.01}
)"));
  EXPECT_DOUBLE_EQ(spec.length_unit, 1.0);
  const double c30 = std::cos(pi / 6), s30 = 0.5;
  EXPECT_LT((spec.regions[0].magnetization.unit_at(Vec3::Zero()) - Vec3(c30, s30, 0)).norm(),
            1e-15);
  // 120 degrees, reversed: 300 degrees.
  EXPECT_LT((spec.regions[1].magnetization.unit_at(Vec3::Zero()) - Vec3(0.5, -c30, 0)).norm(),
            1e-15);
  EXPECT_LT((spec.regions[2].magnetization.unit_at(Vec3(-0.007, 0.04, 0)) - Vec3(-1, 0, 0)).norm(),
            1e-15);
  EXPECT_DOUBLE_EQ(spec.geometry2d.outer.radius, 0.1);
}

// Each edit of the good 3D case is an InputError at the line and field path it names.
TEST(CaseReader3D, BadInputNamesTheExactLineAndFieldPath) {
  struct Bad {
    std::string from, to;
    int line;
    std::string field;
  };
  const std::vector<Bad> cases{
      {"r_outer: 1\n", "r_outer: -1\n", 8, "regions[0].r_outer"},
      {"angle: 90}", "angle: ninety}", 12, "regions[0].placement.rotate.angle"},
      {"direction: [3, 0, 4]", "direction: [0, 0, 0]", 26, "regions[2].magnetization.direction"},
      {"radius: 1.5,", "radius: 0,", 32, "forces[0].radius"},
      {"size: [1, 2, 3]", "size: [1, 2]", 24, "regions[2].size"},
      {"theta: [0, 90]", "theta: [0, 200]", 9, "regions[0].theta"},
      {"sign: -1}", "sign: 2}", 11, "regions[0].magnetization.sign"},
      {"height: 2\n", "hieght: 2\n", 17, "regions[1].hieght"},
      {"shape: box", "shape: cube", 23, "regions[2].shape"},
      {"unit: cm", "unit: furlong", 2, "unit"},
      {"shell_size: 3}", "shell_size: 0}", 30, "mesh.shell_size"},
      {"type: open, radius: 8}", "type: dirichlet, radius: 8}", 30, "mesh.shell_size"},
  };
  for (const auto& bad : cases) {
    std::string text = case3d;
    const auto at = text.find(bad.from);
    ASSERT_NE(at, std::string::npos) << bad.from;
    text.replace(at, bad.from.size(), bad.to);
    try {
      read_case(write_case("bad3d.yaml", text));
      ADD_FAILURE() << "accepted: " << bad.to;
    } catch (const InputError& e) {
      EXPECT_EQ(e.line(), bad.line) << e.what();
      EXPECT_EQ(e.field(), bad.field) << e.what();
      EXPECT_NE(std::string(e.what()).find("bad3d.yaml"), std::string::npos) << e.what();
    }
  }
}

// Slips a new user makes get the answer in the message: a British spelling, a material name
// without its hyphen, a dimension misspelt (the choices listed).
TEST(CaseReader, SlipsAreAnsweredWithTheNearestNameOrTheChoices) {
  struct Slip {
    std::string from, to, field, want;
  };
  const std::vector<Slip> slips{
      {"magnetization: {type: axial}", "magnetisation: {type: axial}", "regions[1].magnetisation",
       "did you mean 'magnetization'?"},
      {"material: pm\n    magnetization: {type: axial}",
       "material: M19\n    magnetization: {type: axial}", "regions[1].material",
       "did you mean 'M-19'?"},
      {"dimension: 3", "dimension: axisymetric", "dimension",
       "dimension must be 2 | 3 | axi | axisymmetric (got 'axisymetric')"},
  };
  for (const auto& slip : slips) {
    std::string text = case3d;
    const auto at = text.find(slip.from);
    ASSERT_NE(at, std::string::npos) << slip.from;
    text.replace(at, slip.from.size(), slip.to);
    try {
      read_case(write_case("slip.yaml", text));
      ADD_FAILURE() << "accepted: " << slip.to;
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), slip.field) << e.what();
      EXPECT_NE(std::string(e.what()).find(slip.want), std::string::npos) << e.what();
    }
  }
}

// `dimension: axisymmetric`, the word the docs and messages use, is a spelling of `axi`: the
// same case (dimension 2 in the r-z half plane); a third spelling is still an error at the
// dimension's own line (line 3 here, after two comment lines).
TEST(CaseReader, AxisymmetricIsASpellingOfAxi) {
  const std::string body = R"(
regions:
  - {name: coil, shape: rectangle, center: [12.5, 0], width: 5, height: 30, turns: 500, current: 2}
boundary: {type: open, radius: 40}
mesh: {size: 2}
)";
  const std::string head = "# a coil\n# in r-z\n";
  const auto axi = read_case(write_case("axi.yaml", head + "dimension: axi" + body));
  const auto spelled =
      read_case(write_case("axisym.yaml", head + "dimension: axisymmetric" + body));
  EXPECT_TRUE(axi.axisymmetric());
  EXPECT_TRUE(spelled.axisymmetric());
  EXPECT_EQ(spelled.dimension, 2);
  try {
    read_case(write_case("axisym_typo.yaml", head + "dimension: axisymetric" + body));
    ADD_FAILURE() << "accepted 'axisymetric'";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 3) << e.what();
    EXPECT_EQ(e.field(), "dimension") << e.what();
    const std::string what = e.what();
    EXPECT_NE(what.find("axisym_typo.yaml"), std::string::npos) << what;
    EXPECT_NE(what.find("2 | 3 | axi | axisymmetric"), std::string::npos) << what;
  }
}

// cut_phi (the spherical actuator's hemispherical array, issue 10): the 32-segment layout
// centred on phi = 0, +-45, .. cut at phi = +-90 keeps 4 x 3 whole segments and 4 x 2 halves;
// each keeps the name, sign and direction of its uncut segment (a half at phi = 90 still
// points at phi = 90, not at its own centre 78.75), and segments wholly outside are dropped.
TEST(CaseReader, SegmentArrayCutKeepsTheUncutLayout) {
  const auto spec = read_case(write_case("cut.yaml", R"(dimension: 3
unit: mm
materials:
  pm: {kind: magnet, B_r: 1.3, mu_r: 1.0}
regions:
  - {name: m, shape: segment_array, r_inner: 53, r_outer: 63, theta: [0, 180],
     phi: [-112.5, 247.5], p_theta: 4, p_phi: 8, cut_phi: [-90, 90], material: pm,
     pattern: {type: parallel_alternating}}
boundary: {type: open, radius: 100}
mesh: {size: 5}
)"));
  const auto& parts = spec.geometry3d.parts;
  ASSERT_EQ(parts.size(), 20u);
  const double deg = std::numbers::pi / 180;
  int halves = 0;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const auto& seg = std::get<SphericalSegment>(parts[i].shape);
    EXPECT_GE(seg.phi_min, -90 * deg - 1e-12);
    EXPECT_LE(seg.phi_max, 90 * deg + 1e-12);
    const double width = (seg.phi_max - seg.phi_min) / deg;
    halves += std::abs(width - 22.5) < 1e-9;
    EXPECT_TRUE(std::abs(width - 22.5) < 1e-9 || std::abs(width - 45) < 1e-9) << width;
  }
  EXPECT_EQ(halves, 8);
  // Segment (1, 5) spans phi 67.5..90 after the cut, centred on 90 before it: theta centre
  // 22.5 deg, direction (0, sin 22.5, cos 22.5), sign (-1)^(1+5) = +1.
  for (std::size_t i = 0; i < parts.size(); ++i)
    if (spec.regions[i].name == "m_1_5") {
      const auto& m = spec.regions[i].magnetization;
      const Eigen::Vector3d want(0, std::sin(22.5 * deg), std::cos(22.5 * deg));
      EXPECT_LT((m.sign * m.direction - want).norm(), 1e-12);
      return;
    }
  FAIL() << "no segment m_1_5";
}

// cell_fraction (the segmented back-iron, thesis sec. 5.4): each segment is its cell shrunk
// about the cell's centre before the cut. At 7/9 (xi = 35 deg of 45) the iron behind magnet
// (1, 1), centred on theta 22.5 and phi -90, spans theta 5..40 and, cut, phi -90..-72.5: a
// shrink after the cut (about the half cell's centre -78.75) would give -87.5..-70, and one
// about the cell's corner would not be symmetric about 22.5 in theta. Exact angles (1e-12 rad
// is round-off of degrees to radians).
TEST(CaseReader, SegmentArrayCellFractionShrinksEachCellAboutItsCentreBeforeTheCut) {
  const std::string layout = R"(dimension: 3
unit: mm
materials:
  iron: {kind: linear, mu_r: 4000}
regions:
  - {name: b, shape: segment_array, r_inner: 43, r_outer: 53, theta: [0, 180],
     phi: [-112.5, 247.5], p_theta: 4, p_phi: 8, cut_phi: [-90, 90], material: iron,
     cell_fraction: FRACTION}
boundary: {type: open, radius: 100}
mesh: {size: 5}
)";
  auto with = [&](const std::string& fraction) {
    std::string text = layout;
    text.replace(text.find("FRACTION"), 8, fraction);
    return text;
  };
  const auto spec = read_case(write_case("shrunk.yaml", with("${35 / 45}")));
  const auto& parts = spec.geometry3d.parts;
  ASSERT_EQ(parts.size(), 20u); // still one segment behind each of the 20 (half) magnets
  const double deg = std::numbers::pi / 180;
  auto range = [&](const std::string& name) {
    for (const auto& p : parts)
      if (p.name == name)
        return std::get<SphericalSegment>(p.shape);
    throw std::runtime_error("no part " + name);
  };
  const auto corner = range("b_1_1");
  EXPECT_NEAR(corner.theta_min, 5 * deg, 1e-12);
  EXPECT_NEAR(corner.theta_max, 40 * deg, 1e-12);
  EXPECT_NEAR(corner.phi_min, -90 * deg, 1e-12);
  EXPECT_NEAR(corner.phi_max, -72.5 * deg, 1e-12);
  const auto inner = range("b_3_3"); // theta 90..135, phi -22.5..22.5
  EXPECT_NEAR(inner.theta_min, 95 * deg, 1e-12);
  EXPECT_NEAR(inner.theta_max, 130 * deg, 1e-12);
  EXPECT_NEAR(inner.phi_min, -17.5 * deg, 1e-12);
  EXPECT_NEAR(inner.phi_max, 17.5 * deg, 1e-12);
  EXPECT_DOUBLE_EQ(inner.r_inner, 43e-3);
  EXPECT_DOUBLE_EQ(inner.r_outer, 53e-3);

  // Out of (0, 1]: an InputError at the key's line (8) and field.
  for (const std::string bad : {"0", "1.2", "-0.5"}) {
    try {
      read_case(write_case("bad_fraction.yaml", with(bad)));
      ADD_FAILURE() << "accepted cell_fraction " << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(e.line(), 8) << e.what();
      EXPECT_EQ(e.field(), "regions[0].cell_fraction") << e.what();
    }
  }
}

namespace {

// case3d (lines 1-34) with sections and a plane probe from line 35 on.
std::string case3d_sections() {
  return std::string(case3d) + R"(sections:
  - {name: plate, type: rectangle, center: [0, 0, 1], normal: [0, 0, 2], size: [3, 2]}
  - {name: tilted, type: rectangle, center: [1, 0, 0], normal: [1, 1, 0], u: [0, 0, 1],
     size: [1, 4]}
  - {name: ring, type: disk, center: [0, 1, 0], normal: [0, 1, 0], radius: 2}
probes:
  - {name: grid, type: plane, center: [0, 0, 1], normal: [1, 0, 0], size: [4, 2],
     points: [5, 3]}
)";
}

} // namespace

// Lengths in the case unit (cm here) arrive in metres; normals are normalised; u defaults to
// the coordinate axis least aligned with the normal, projected (z -> u = x; x -> u = y).
TEST(CaseReader3D, SectionsAndPlaneProbesArriveInSi) {
  using Vec3 = Eigen::Vector3d;
  const auto spec = read_case(write_case("case3d_sections.yaml", case3d_sections()));
  ASSERT_EQ(spec.sections.size(), 3u);
  const auto& plate = spec.sections[0];
  EXPECT_EQ(plate.kind, SectionSpec::Kind::rectangle);
  EXPECT_EQ(plate.line, 36);
  EXPECT_LT((plate.frame.center - Vec3(0, 0, 0.01)).norm(), 1e-15);
  EXPECT_LT((plate.frame.n - Vec3(0, 0, 1)).norm(), 1e-15);
  EXPECT_LT((plate.frame.u - Vec3(1, 0, 0)).norm(), 1e-15);
  EXPECT_LT((plate.frame.v - Vec3(0, 1, 0)).norm(), 1e-15);
  EXPECT_DOUBLE_EQ(plate.size_u, 0.03);
  EXPECT_DOUBLE_EQ(plate.size_v, 0.02);
  EXPECT_NEAR(plate.area(), 6e-4, 1e-18);
  const auto& tilted = spec.sections[1];
  EXPECT_LT((tilted.frame.u - Vec3(0, 0, 1)).norm(), 1e-15);
  EXPECT_LT((tilted.frame.n - Vec3(1, 1, 0) / std::sqrt(2.0)).norm(), 1e-15);
  EXPECT_LT((tilted.frame.v - tilted.frame.n.cross(tilted.frame.u)).norm(), 1e-15);
  const auto& ring = spec.sections[2];
  EXPECT_EQ(ring.kind, SectionSpec::Kind::disk);
  EXPECT_DOUBLE_EQ(ring.radius, 0.02);
  EXPECT_LT((ring.frame.u - Vec3(1, 0, 0)).norm(), 1e-15);
  ASSERT_EQ(spec.probes.size(), 1u);
  const auto& grid = spec.probes[0];
  EXPECT_EQ(grid.kind, ProbeSpec::Kind::plane);
  EXPECT_EQ(grid.u_steps, 5);
  EXPECT_EQ(grid.v_steps, 3);
  EXPECT_EQ(grid.points, 15);
  EXPECT_DOUBLE_EQ(grid.size_u, 0.04);
  EXPECT_LT((grid.plane.u - Vec3(0, 1, 0)).norm(), 1e-15);
  EXPECT_LT((grid.plane.v - Vec3(0, 0, 1)).norm(), 1e-15);
}

TEST(CaseReader3D, BadSectionsAndPlaneProbesNameLineAndField) {
  struct Bad {
    std::string from, to;
    int line;
    std::string field;
  };
  const std::vector<Bad> cases{
      {"normal: [0, 0, 2]", "normal: [0, 0, 0]", 36, "sections[0].normal"},
      {"size: [3, 2]", "size: [3, -2]", 36, "sections[0].size"},
      {"size: [3, 2]", "size: [3, 0]", 36, "sections[0].size"},
      {"size: [3, 2]", "size: [3]", 36, "sections[0].size"},
      // A corner at |(1.5, 1, 7.9)| = 8.1 cm, beyond the boundary radius 8 cm.
      {"center: [0, 0, 1], normal: [0, 0, 2]", "center: [0, 0, 7.9], normal: [0, 0, 2]", 36,
       "sections[0].size"},
      {"u: [0, 0, 1]", "u: [1, 0, 1]", 37, "sections[1].u"},
      {"radius: 2}", "radius: 7.95}", 39, "sections[2].radius"},
      {"radius: 2}", "radius: -2}", 39, "sections[2].radius"},
      {"type: disk", "type: annulus", 39, "sections[2].type"},
      {"name: ring", "name: plate", 39, "sections[2].name"},
      {"name: ring", "name: \"ring,a\"", 39, "sections[2].name"},
      {"size: [3, 2]}", "size: [3, 2], radius: 1}", 36, "sections[0].radius"},
      {"points: [5, 3]}", "points: [5, 0]}", 42, "probes[0].points"},
      {"points: [5, 3]}", "points: [5]}", 42, "probes[0].points"},
      {"normal: [1, 0, 0], size", "normal: [0, 0, 0], size", 41, "probes[0].normal"},
      {"size: [4, 2],", "size: [16, 2],", 41, "probes[0]"},
  };
  for (const auto& bad : cases) {
    std::string text = case3d_sections();
    const auto at = text.find(bad.from);
    ASSERT_NE(at, std::string::npos) << bad.from;
    text.replace(at, bad.from.size(), bad.to);
    try {
      read_case(write_case("bad_sections.yaml", text));
      ADD_FAILURE() << "accepted: " << bad.to;
    } catch (const InputError& e) {
      EXPECT_EQ(e.line(), bad.line) << e.what();
      EXPECT_EQ(e.field(), bad.field) << e.what();
      EXPECT_NE(std::string(e.what()).find("bad_sections.yaml"), std::string::npos) << e.what();
    }
  }
}
