// Symmetry planes in 2D and axisymmetric cases (issue 36): a half or quarter model stands for
// the whole device.
//   - two diametrically magnetized cylinders side by side (planar, both along +x, attracting)
//     as a half (x: normal) and a quarter (x: normal, y: parallel) model: energy, the field at
//     probes on both sides of the planes and the stress-circle force on each cylinder against
//     the full model and the exact line-dipole solution;
//   - conductor pairs (planar): the same current on a `normal` plane attracts, go-and-return
//     on a `parallel` plane repels, by mu0 I^2 / (2 pi d) (Lorentz force on the meshed wire
//     and, through the mirror, on its image), and a conductor the plane cuts feels no F_x;
//   - axisymmetric: the solenoid cut at z = 0 (its winding its own image, `normal`): energy,
//     flux linkage and inductance equal the full model's; a pair of axial magnets about
//     z = 0, attracting (`normal`) and repelling (`parallel`): energy, probes and the contour
//     force on each magnet against the full model;
//   - refusals before meshing, naming the region and its line: a part without its mirror, a
//     magnetization or a current the plane's condition contradicts, a plane the dimension
//     does not have (coil pairs mirrored into each other: test_mirror_coils_axi.cpp).
// Planted bugs the tests caught (see the report of branch sym2d): A = 0 on `normal` planes
// instead of `parallel`, the energy factor dropped, the mirror map's sign flipped.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>

#include "core/constants.hpp"
#include "core/input_error.hpp"
#include "pipeline/run2d.hpp"
#include "tests/case_helpers.hpp"

using namespace magfem;

namespace {

std::unique_ptr<Run2D> solve(const char* text, const std::string& symmetry,
                             const std::string& name) {
  const std::string t = std::regex_replace(text, std::regex("SYMMETRY"), symmetry);
  return run_case_2d(read_case(test::write_temp_case(name, t)));
}

// Two cylinders of radius 5 mm at x = +-15 mm, B_r = 1 T, mu_r = 1, both magnetized along +x.
const char* cylinders_case = R"(
unit: mm
materials:
  pm: {kind: magnet, B_r: 1.0, mu_r: 1.0}
regions:
  - {name: right, shape: disk, center: [15, 0], radius: 5, material: pm,
     magnetization: {type: parallel, angle: 0}, mesh_size: 0.6}
  - {name: left, shape: disk, center: [-15, 0], radius: 5, material: pm,
     magnetization: {type: parallel, angle: 0}, mesh_size: 0.6}
  # Air bands, finer, where the stress circles and the probe circle lie.
  - {name: band_right, shape: annulus, center: [15, 0], r_inner: 6, r_outer: 8, mesh_size: 0.4}
  - {name: band_left, shape: annulus, center: [-15, 0], r_inner: 6, r_outer: 8, mesh_size: 0.4}
  - {name: band_probe, shape: annulus, r_inner: 28, r_outer: 32, mesh_size: 0.8}
boundary: {type: open, radius: 40, shell_ratio: 1.5SYMMETRY}
mesh: {size: 2.5, chord_tolerance: 0.001}
solver: {order: 2}
probes:
  - {name: circle, type: circle, center: [0, 0], radius: 30, points: 37}
forces:
  - {name: on_right, type: circle, center: [15, 0], radius: 7}
  - {name: on_left, type: circle, center: [-15, 0], radius: 7}
)";

const Run2D& full_cylinders() {
  static const auto run = solve(cylinders_case, "", "sym2d_cyl_full.yaml");
  return *run;
}

// Outside a uniformly magnetized cylinder the field is a line dipole's, moment per length
// m = B_r pi a^2 / mu0; two such dipoles along x at distance d attract with
// F = mu0 m^2 / (pi d^3) per metre (the gradient of m . B of the other).
double exact_pair_force() {
  const double a = 5e-3, d = 30e-3, m = pi * a * a / mu0;
  return mu0 * m * m / (pi * d * d * d);
}

// Energy of each cylinder alone is B_r^2 pi a^2 / (4 mu0) (examples/2d/diametric_cylinder),
// plus the interaction -m . B_other = -mu0 m^2 / (2 pi d^2) (B_other's mean over a disk is
// its value at the centre: it is harmonic there).
double exact_pair_energy() {
  const double a = 5e-3, d = 30e-3, m = pi * a * a / mu0;
  return 2 * pi * a * a / (4 * mu0) - mu0 * m * m / (2 * pi * d * d);
}

double max_probe_difference(const ProbeTable& a, const ProbeTable& b, bool axi = false) {
  const std::size_t bx = a.column(axi ? "Br" : "Bx"), by = a.column(axi ? "Bz" : "By");
  double worst = 0;
  for (std::size_t i = 0; i < a.rows.size(); ++i)
    worst =
        std::max(worst, std::hypot(a.rows[i][bx] - b.rows[i][bx], a.rows[i][by] - b.rows[i][by]));
  return worst;
}

void expect_cylinder_model(const Run2D& run, double factor) {
  const Run2D& full = full_cylinders();
  ASSERT_EQ(run.mesh.symmetry.size(), factor == 2 ? 1u : 2u);
  // The whole device's energy: the full and the cut model differ by their meshes only
  // (the estimated error is 0.01 %).
  EXPECT_NEAR(run.energy.total_J_per_m, full.energy.total_J_per_m,
              2e-4 * full.energy.total_J_per_m);
  // Probes all round both planes, read through the mirror (|B| 2..30 mT here; the meshes
  // differ by their element error, about 1e-5 T).
  EXPECT_LT(max_probe_difference(run.probes.at(0), full.probes.at(0)), 1e-4);
  // The stress circles: the left one lies wholly beyond x = 0, read at its image.
  const double f = exact_pair_force();
  ASSERT_EQ(run.forces.size(), 2u);
  EXPECT_NEAR(run.forces[0].force.x(), -f, 0.01 * f);
  EXPECT_NEAR(run.forces[1].force.x(), f, 0.01 * f);
  EXPECT_NEAR(run.forces[0].force.y(), 0, 1e-3 * f);
  EXPECT_NEAR(run.forces[1].force.x(), full.forces[1].force.x(), 2e-3 * f);
}

TEST(Symmetry2D, FullCylinderPairMatchesLineDipoles) {
  const Run2D& full = full_cylinders();
  // The magnets are polygons 0.03 % smaller than their circles (chord tolerance 1 um), which
  // lowers the energy about twice as much; the element error is below 0.01 %.
  EXPECT_NEAR(full.energy.total_J_per_m, exact_pair_energy(), 1e-3 * exact_pair_energy());
  EXPECT_NEAR(full.forces[0].force.x(), -exact_pair_force(), 0.01 * exact_pair_force());
}

TEST(Symmetry2D, CylinderPairHalfModel) {
  const auto half =
      solve(cylinders_case, ", symmetry: [{plane: x, field: normal}]", "sym2d_cyl_half.yaml");
  EXPECT_LT(half->mesh.n_triangles(), 0.6 * full_cylinders().mesh.n_triangles());
  expect_cylinder_model(*half, 2);
}

TEST(Symmetry2D, CylinderPairQuarterModel) {
  const auto quarter =
      solve(cylinders_case, ", symmetry: [{plane: x, field: normal}, {plane: y, field: parallel}]",
            "sym2d_cyl_quarter.yaml");
  EXPECT_LT(quarter->mesh.n_triangles(), 0.35 * full_cylinders().mesh.n_triangles());
  expect_cylinder_model(*quarter, 4);
  // Per part: the right cylinder is whole in the model but cut by y = 0 (factor 2).
  double right_area = 0;
  for (const auto& r : quarter->energy.regions)
    if (r.name == "right")
      right_area = r.area_m2;
  EXPECT_NEAR(right_area, pi * 25e-6, 5e-4 * pi * 25e-6); // polygon vs circle: 0.03 %
}

// Two round conductors (radius 1 mm, 2000 A as ampere-turns, so exactly that over the
// polygon) at x = +-5 mm, and a rectangular one across x = 0 far above them.
const char* wires_case = R"(
unit: mm
regions:
  - {name: right, shape: disk, center: [5, 0], radius: 1, turns: 1, current: 2000,
     mesh_size: 0.25}
  - {name: left, shape: disk, center: [-5, 0], radius: 1, turns: 1, current: ILEFT,
     mesh_size: 0.25}
  - {name: bar, shape: rectangle, center: [0, 30], width: 6, height: 2, turns: 1, current: IBAR,
     mesh_size: 0.5}
boundary: {type: open, radius: 50SYMMETRY}
mesh: {size: 3, chord_tolerance: 0.002}
solver: {order: 2}
forces:
  - {name: on_right, type: lorentz, regions: [right]}
  - {name: on_left, type: lorentz, regions: [left]}
  - {name: on_bar, type: lorentz, regions: [bar]}
  - {name: on_both, type: lorentz, regions: [right, left]}
)";

std::unique_ptr<Run2D> solve_wires(double i_left, double i_bar, const std::string& symmetry,
                                   const std::string& name) {
  std::string t = std::regex_replace(wires_case, std::regex("ILEFT"), std::to_string(i_left));
  t = std::regex_replace(t, std::regex("IBAR"), std::to_string(i_bar));
  return solve(t.c_str(), symmetry, name);
}

TEST(Symmetry2D, ConductorPairsThroughTheMirror) {
  const double current = 2000;
  // The two wires interact as line currents, mu0 I^2 / (2 pi d); the bar (500 A at 30.4 mm)
  // pulls each towards x = 0 by mu0 I I_bar / (2 pi r^2) * 5 mm as well (its quadrupole
  // correction, (3 mm / 30 mm)^2 of that, stays below 0.02 %).
  const double f = mu0 * current * current / (2 * pi * 10e-3);
  const double f_bar = mu0 * current * 500 / (2 * pi * (25e-6 + 900e-6)) * 5e-3;
  const auto same =
      solve_wires(current, 500, ", symmetry: [{plane: x, field: normal}]", "sym2d_wires_same.yaml");
  const auto same_full = solve_wires(current, 500, "", "sym2d_wires_same_full.yaml");
  // Attraction; the element self-force stays below 1 %.
  EXPECT_NEAR(same->forces[0].force.x(), -f - f_bar, 0.01 * f);
  EXPECT_NEAR(same->forces[1].force.x(), f + f_bar, 0.01 * f);
  for (int k = 0; k < 4; ++k) // the same as the full model, both components, to 0.2 %
    EXPECT_LT((same->forces[k].force - same_full->forces[k].force).norm(), 2e-3 * f) << k;
  // The bar is cut by x = 0: F_x cancels, F_y (pulled down by the wires) doubles the share's.
  EXPECT_NEAR(same->forces[2].force.x(), 0, 1e-9 * f);
  EXPECT_LT(same->forces[2].force.y(), 0);
  EXPECT_NEAR(same->forces[3].force.x(), 0, 1e-9 * f);

  const auto opposite = solve_wires(-current, 0, ", symmetry: [{plane: x, field: parallel}]",
                                    "sym2d_wires_opposite.yaml");
  EXPECT_NEAR(opposite->forces[0].force.x(), f, 0.01 * f); // go and return repel
  EXPECT_NEAR(opposite->forces[1].force.x(), -f, 0.01 * f);
  EXPECT_NEAR(opposite->forces[0].force.y(), 0, 1e-3 * f);
}

// examples/axi/solenoid.yaml at a coarser mesh.
const char* solenoid_case = R"(
dimension: axi
unit: mm
regions:
  - {name: winding, shape: rectangle, center: [12.5, 0], width: 5, height: 30, turns: 500,
     current: 2.0, mesh_size: 1.5}
boundary: {type: open, radius: 40, shell_ratio: 1.5SYMMETRY}
mesh: {size: 3, chord_tolerance: 0.005}
solver: {order: 2}
probes:
  - {name: bore, type: line, start: [5, -30], end: [5, 30], points: 31}
sections:
  - {name: bore_z5, type: line, start: [0, -5], end: [10, -5]}
  - {name: midplane, type: line, start: [0, 0], end: [10, 0]}
)";

TEST(Symmetry2D, AxisymmetricSolenoidHalfModel) {
  const auto full = solve(solenoid_case, "", "sym2d_sol_full.yaml");
  const auto half =
      solve(solenoid_case, ", symmetry: [{plane: z, field: normal}]", "sym2d_sol_half.yaml");
  // The winding is its own image: its linkage (N times the mean of 2 pi r A) and inductance
  // need no factor, the energy 2; all equal the full model's within the meshes' difference
  // (estimated energy error 1e-4 %).
  EXPECT_NEAR(half->energy.total_J_per_m, full->energy.total_J_per_m,
              1e-5 * full->energy.total_J_per_m);
  ASSERT_EQ(half->coil_results.size(), 1u);
  EXPECT_NEAR(half->coil_results[0].flux_linkage_Wb, full->coil_results[0].flux_linkage_Wb,
              1e-5 * full->coil_results[0].flux_linkage_Wb);
  EXPECT_NEAR(half->coil_results[0].inductance_H, full->coil_results[0].inductance_H,
              1e-5 * full->coil_results[0].inductance_H);
  // L I^2 / 2 is the energy (linear, no magnets): the ampere-turns spread over the whole coil.
  EXPECT_NEAR(0.5 * half->coil_results[0].inductance_H * 4.0, half->energy.total_J_per_m,
              1e-4 * half->energy.total_J_per_m);
  // The bore field is 0.04 T; at mesh size 1.5 mm the two meshes' element errors differ by
  // about 2e-4 T.
  EXPECT_LT(max_probe_difference(half->probes.at(0), full->probes.at(0), true), 5e-4);
  // The section below the plane is read at its image; the one on the plane by the model.
  for (int k = 0; k < 2; ++k)
    EXPECT_NEAR(half->sections[k].total.flux_Wb, full->sections[k].total.flux_Wb,
                1e-4 * std::abs(full->sections[k].total.flux_Wb))
        << k;
}

// Two axial disk magnets (r 0..8 mm, z 3..9 mm and its mirror), B_r 1.2 T, facing each
// other with the same (MLOWER = 90 degrees: attracting) or opposite (-90: repelling)
// magnetization.
const char* magnets_case = R"(
dimension: axi
unit: mm
materials:
  pm: {kind: magnet, B_r: 1.2, mu_r: 1.05}
regions:
  - {name: upper, shape: rectangle, center: [4, 6], width: 8, height: 6, material: pm,
     magnetization: {type: parallel, angle: 90}, mesh_size: 0.6}
  - {name: lower, shape: rectangle, center: [4, -6], width: 8, height: 6, material: pm,
     magnetization: {type: parallel, angle: MLOWER}, mesh_size: 0.6}
boundary: {type: open, radius: 40, shell_ratio: 1.5SYMMETRY}
mesh: {size: 1.2, chord_tolerance: 0.005}
solver: {order: 2}
probes:
  - {name: across, type: line, start: [2, -14.5], end: [2, 14.5], points: 30}
forces:
  - {name: on_upper, type: contour, region: upper, margin: 1}
  - {name: on_lower, type: contour, region: lower, margin: 1}
)";

void expect_magnet_pair(const std::string& lower_angle, const std::string& field,
                        double force_sign) {
  const std::string text = std::regex_replace(magnets_case, std::regex("MLOWER"), lower_angle);
  const auto full = solve(text.c_str(), "", "sym2d_mag_full.yaml");
  const auto half =
      solve(text.c_str(), ", symmetry: [{plane: z, field: " + field + "}]", "sym2d_mag_half.yaml");
  // Both meshes' estimated energy error is 0.04 %; they differ by 0.01 %.
  EXPECT_NEAR(half->energy.total_J_per_m, full->energy.total_J_per_m,
              5e-4 * full->energy.total_J_per_m);
  // |B| up to 0.5 T; points off the magnets' faces (a jump there), element error ~1e-3 T.
  EXPECT_LT(max_probe_difference(half->probes.at(0), full->probes.at(0), true), 2e-3);
  const double f = std::abs(full->forces[0].force.z());
  // Attracting: the upper magnet is pulled down (F_z < 0); repelling: pushed up. The lower
  // one, beyond the plane, read through the mirror, feels the opposite.
  EXPECT_EQ(std::signbit(full->forces[0].force.z()), force_sign < 0);
  for (int k = 0; k < 2; ++k)
    EXPECT_NEAR(half->forces[k].force.z(), full->forces[k].force.z(), 0.01 * f) << k;
  EXPECT_NEAR(half->forces[1].force.z(), -half->forces[0].force.z(), 1e-9 * f);
}

TEST(Symmetry2D, AxisymmetricMagnetPairAttracting) {
  expect_magnet_pair("90", "normal", -1);
}

TEST(Symmetry2D, AxisymmetricMagnetPairRepelling) {
  expect_magnet_pair("-90", "parallel", 1);
}

// The refusal as the CLI would print it (exit 2): file, line and the region's name.
void expect_refused(const std::string& text, const std::string& name, int line,
                    const std::string& what) {
  const std::string path = test::write_temp_case(name, text);
  try {
    run_case_2d(read_case(path));
    FAIL() << "accepted " << name;
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(path + ":" + std::to_string(line)), std::string::npos) << msg;
    EXPECT_NE(msg.find(what), std::string::npos) << msg;
  }
}

TEST(Symmetry2D, RefusedWhenNotSymmetric) {
  // The left cylinder missing: 'right' has no mirror image.
  std::string one =
      std::regex_replace(cylinders_case, std::regex("  - \\{name: left[^\n]*\n[^\n]*\n"), "");
  one = std::regex_replace(one, std::regex("  - \\{name: on_left[^\n]*\n"), "");
  one = std::regex_replace(one, std::regex("SYMMETRY"), ", symmetry: [{plane: x, field: normal}]");
  expect_refused(one, "sym2d_bad_part.yaml", 6,
                 "region 'right' is not symmetric about the "
                 "symmetry plane x = 0 (field: normal): the mirror "
                 "image of its point");
  // Magnetized along x: about y = 0 that is `parallel`, not `normal`.
  const std::string wrong_m = std::regex_replace(cylinders_case, std::regex("SYMMETRY"),
                                                 ", symmetry: [{plane: y, field: normal}]");
  expect_refused(wrong_m, "sym2d_bad_m.yaml", 6,
                 "region 'right' is not symmetric about the "
                 "symmetry plane y = 0 (field: normal): its "
                 "magnetization");
  // Go and return on a `normal` plane.
  std::string wires = std::regex_replace(wires_case, std::regex("ILEFT"), "-2000");
  wires = std::regex_replace(wires, std::regex("IBAR"), "0");
  wires =
      std::regex_replace(wires, std::regex("SYMMETRY"), ", symmetry: [{plane: x, field: normal}]");
  expect_refused(wires, "sym2d_bad_j.yaml", 4,
                 "region 'right' is not symmetric about the "
                 "symmetry plane x = 0 (field: normal): its "
                 "current density");
  // Planes the dimension does not have.
  expect_refused(std::regex_replace(solenoid_case, std::regex("SYMMETRY"),
                                    ", symmetry: [{plane: x, field: normal}]"),
                 "sym2d_bad_axi_plane.yaml", 7, "an axisymmetric case has one symmetry plane, z");
  expect_refused(std::regex_replace(cylinders_case, std::regex("SYMMETRY"),
                                    ", symmetry: [{plane: z, field: normal}]"),
                 "sym2d_bad_planar_plane.yaml", 14, "its planes are x and y");
}

} // namespace
