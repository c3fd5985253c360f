// The coil-pitch study of thesis sec. 5.3 (magfem actuator --coil-pitch): the coil array rule,
// the tabulated radial field it runs on, and the physics of the averaged copper loss.
//
// What would make these fail: a coil array that overlaps, has the wrong count for a pitch or
// the wrong size (eqs. 5.5-5.7 less 10 %); an interpolation table that is off (wrong pole
// continuation, wrong index order, too coarse a step) - it is checked against the direct
// charge-model torque constants; a loss average that is not quadratic in the demanded torque
// or that grows when back-iron is added; a command that writes on bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <sys/wait.h>

#include "studies/actuator_coil_pitch.hpp"
#include "tests/case_helpers.hpp"
#include "core/constants.hpp"
#include "core/input_error.hpp"

using namespace magfem;

namespace {

const std::string topology = test::example("3d/spherical_actuator_topology.yaml");
const std::string design = test::example("3d/spherical_actuator_design.yaml");

ActuatorOptions options() {
  ActuatorOptions o;
  o.case_file = topology;
  o.rotor = "rotor";
  o.analytic = true;
  return o;
}

CaseSpec topology_case(double magnet_iron_mu_r, double coil_iron_mu_r) {
  return read_case(topology,
                   {{"magnet_iron_mu_r", magnet_iron_mu_r}, {"coil_iron_mu_r", coil_iron_mu_r}});
}

Eigen::Vector3d axis_of(const Coil3D& c) {
  return c.placement.rotation.col(2);
}

// The table step of the default tests' studies: coarse and cheap. Their assertions compare
// losses that differ by tens of percent, far above this step's error (measured below).
constexpr double test_step_deg = 2.0;

} // namespace

// Eqs. 5.5-5.7 and the coil counts the thesis states (14 coils for 40..51 deg, 12 for 52..60,
// 10 for 61..70); no two coils overlap (their axes at least two outer radii apart); at 52 deg
// the array is the one examples/3d/spherical_actuator_design.yaml lays out by hand.
TEST(CoilPitch, ArrayFollowsTheThesisRule) {
  const CaseSpec spec = read_case(design);
  const Coil3D& tpl = spec.geometry3d.coils.front();
  const std::pair<double, std::size_t> counts[] = {{40, 14}, {51, 14}, {52, 12},
                                                   {60, 12}, {61, 10}, {70, 10}};
  for (const auto& [pitch, n] : counts) {
    const auto array = thesis_coil_array(tpl, pitch * deg_to_rad);
    ASSERT_EQ(array.size(), n) << pitch;
    const auto& s = std::get<SphericalCoil>(array.front().shape);
    const double outer = 0.9 * std::sqrt(2.0) / 4 * pitch * deg_to_rad;
    EXPECT_NEAR(s.alpha_max, outer, 1e-12);
    EXPECT_NEAR(s.alpha_min, 0.25 * (s.alpha_max - s.alpha_min), 1e-12);
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = a + 1; b < n; ++b) {
        const double angle =
            std::acos(std::clamp(axis_of(array[a]).dot(axis_of(array[b])), -1.0, 1.0));
        EXPECT_GE(angle, 2 * outer - 1e-12)
            << pitch << " deg: " << array[a].name << ", " << array[b].name;
      }
  }
  const auto array = thesis_coil_array(tpl, 52 * deg_to_rad);
  for (const auto& c : spec.geometry3d.coils) {
    double closest = 1e9;
    for (const auto& d : array)
      closest = std::min(closest, (axis_of(c) - axis_of(d)).norm());
    EXPECT_LT(closest, 1e-9) << c.name;
  }
}

// The interpolated B_r table against the charge model evaluated at every quadrature point:
// the torque constants of the 12-coil array at three orientations. Printed for the steps
// 2 and 1 deg (measured 8e-4 and 7e-5 of the largest constant; 0.5 deg gives 6e-6 but costs
// 30 s here); asserted for the default step (1 deg) at 2e-4: a cubic rule's error falls 16x
// per halving, so a table off by an index or a pole continuation would not pass, and 2e-4 is
// below the coil quadrature's own 1e-3 (analytic/torque_constants.hpp). Asserted for the 2 deg step
// of the tests below at 2e-3: far below the tens of percent their losses differ by.
TEST(CoilPitch, TableMatchesDirectTorqueConstants) {
  const CaseSpec spec = topology_case(1, 1);
  std::vector<std::string> notes;
  const FieldAtPoints b = analytic_rotor_field(spec, "rotor", notes);
  std::vector<CoilField> coils;
  for (const auto& c : thesis_coil_array(spec.geometry3d.coils.front(), 52 * deg_to_rad))
    coils.emplace_back(c);
  const std::vector<Eigen::Matrix3d> rot{rotor_rotation({0, 0, 0}), rotor_rotation({17, -31, 8}),
                                         rotor_rotation({-40, 12, 44})};
  const CoilRule rule;
  const auto direct = torque_constants_rotating(coils, rot, b, rule);
  double scale = 0;
  for (const auto& g : direct)
    scale = std::max(scale, g.cwiseAbs().maxCoeff());
  const auto radii = quadrature_radii(coils, rule);
  EXPECT_EQ(radii.size(), static_cast<std::size_t>(rule.n_r));
  for (const double step : {test_step_deg, coil_pitch_table_step_deg}) {
    const RadialFieldTable table(b, radii, step * deg_to_rad);
    const auto tabulated = torque_constants_rotating(
        coils, rot, [&table](const std::vector<Eigen::Vector3d>& x) { return table(x); }, rule);
    double err = 0;
    for (std::size_t i = 0; i < rot.size(); ++i)
      err = std::max(err, (tabulated[i] - direct[i]).cwiseAbs().maxCoeff() / scale);
    std::printf(
        "table step %.2f deg: largest torque-constant error %.2e of the largest (%.4g N m/A)\n",
        step, err, scale);
    EXPECT_LT(err, step == coil_pitch_table_step_deg ? 2e-4 : 2e-3) << step << " deg";
  }
  // A point off the tabulated spheres is refused, not silently interpolated.
  const RadialFieldTable table(b, radii, 5 * deg_to_rad);
  EXPECT_THROW(table({Eigen::Vector3d(0.07, 0, 0)}), std::invalid_argument);
}

// Eq. 5.4 is linear in T_d and the loss quadratic in the currents: the averaged loss scales
// as |T_d|^2 exactly (to round-off: 1e-12 relative).
TEST(CoilPitch, LossScalesAsTheSquareOfTheTorque) {
  const CaseSpec spec = topology_case(4000, 1);
  const auto grid = parse_orientations("rx=-30,30,ry=-20,25,rz=10");
  const auto one = run_coil_pitch_study(spec, options(), {48, 58}, grid, 1.0, test_step_deg);
  const auto two = run_coil_pitch_study(spec, options(), {48, 58}, grid, 2.5, test_step_deg);
  for (std::size_t r = 0; r < 2; ++r)
    for (int d = 0; d < 3; ++d) {
      EXPECT_GT(one.rows[r].P_W[d], 0);
      EXPECT_NEAR(two.rows[r].P_W[d], 6.25 * one.rows[r].P_W[d], 1e-12 * two.rows[r].P_W[d]);
    }
}

// Sec. 5.3.3: back-iron behind the magnets raises the gap field (+26 %), iron behind the coils
// as well (+80 % together), so at the same pitch the loss for each torque direction falls:
// none > magnet iron > magnet and coil iron, for every pitch and axis (the thesis's 32 % and
// 66 % decreases leave margins far above the 2e-3 table error; 27 orientations suffice).
TEST(CoilPitch, BackIronLowersTheLossAtEveryPitch) {
  const auto grid = parse_orientations("rx=-45:45:45,ry=-45:45:45,rz=-45:45:45");
  const std::vector<double> pitches{40, 50, 55, 60, 70};
  auto run = [&](double m, double c) {
    return run_coil_pitch_study(topology_case(m, c), options(), pitches, grid, 1.0, test_step_deg);
  };
  const auto none = run(1, 1), magnet = run(4000, 1), both = run(4000, 4000);
  for (std::size_t r = 0; r < pitches.size(); ++r) {
    for (int d = 0; d < 3; ++d) {
      EXPECT_LT(magnet.rows[r].P_W[d], none.rows[r].P_W[d]) << pitches[r] << " deg, axis " << d;
      EXPECT_LT(both.rows[r].P_W[d], magnet.rows[r].P_W[d]) << pitches[r] << " deg, axis " << d;
    }
    std::printf("pitch %g deg: P_mean none %.2f, magnet iron %.2f, magnet and coil iron %.2f W\n",
                pitches[r], none.rows[r].mean_W(), magnet.rows[r].mean_W(), both.rows[r].mean_W());
  }
}

// Over 40..70 deg the least mean loss (no iron) is at an interior pitch, as in Fig. 5.9 (the
// thesis: 58 deg): too small a pitch gives small coils, too large a pitch too few coils. On
// the 7 x 7 x 7 grid (15 deg steps) the ends lie 8 % and 12 % above the minimum (measured);
// on the thesis's 15 x 15 x 15 grid 32 % and 3.5 % (the long-tier study below).
TEST(CoilPitch, LeastLossIsAtAnInteriorPitch) {
  const auto grid = parse_orientations("rx=-45:15:45,ry=-45:15:45,rz=-45:15:45");
  const auto none = run_coil_pitch_study(topology_case(1, 1), options(),
                                         {40, 45, 50, 55, 60, 65, 70}, grid, 1.0, test_step_deg);
  const double p_min = none.minimum().pitch_deg;
  std::printf("least P_mean %.2f W at %g deg (40 deg: %.2f W, 70 deg: %.2f W)\n",
              none.minimum().mean_W(), p_min, none.rows.front().mean_W(),
              none.rows.back().mean_W());
  EXPECT_GT(p_min, 40);
  EXPECT_LT(p_min, 70);
}

// The thesis's study itself (sec. 5.3.3): 31 pitches x 3375 orientations ("15 rotations about
// each axis" over +-45 deg) for the three back-iron configurations, printed against Tables 5.4
// and 5.5. Long tier: about 5 min per configuration on 2 cores. Run with
//   build/tests/studies/test_studies_actuator_coil_pitch --gtest_filter=*LongThesisStudy*
//   (or bash scripts/test.sh --long, which runs every long check)
// Asserted: the physics the thesis reports, not its levels (whose fill factor it does not
// state; validation/catalogue.yaml thesis.c5.power.*): the minima lie at interior pitches,
// the 12-coil range holds them as in Table 5.4 (58-60 deg), and the decreases of Table 5.5
// (32 % / 66 %) are met within its 10 % tolerance (paper_targets D).
TEST(CoilPitch, LongThesisStudy) {
  const double s = 90.0 / 14;
  std::vector<Orientation> grid;
  for (int i = 0; i < 15; ++i)
    for (int j = 0; j < 15; ++j)
      for (int k = 0; k < 15; ++k)
        grid.push_back({-45 + i * s, -45 + j * s, -45 + k * s});
  std::vector<double> pitches;
  for (int p = 40; p <= 70; ++p)
    pitches.push_back(p);
  const double published[3] = {29.6, 20.1, 9.8}, published_pitch[3] = {58, 60, 59};
  const double irons[3][2] = {{1, 1}, {4000, 1}, {4000, 4000}};
  double minimum[3];
  for (int t = 0; t < 3; ++t) {
    const auto study =
        run_coil_pitch_study(topology_case(irons[t][0], irons[t][1]), options(), pitches, grid);
    const auto& m = study.minimum();
    minimum[t] = m.mean_W();
    std::printf("configuration %d: least P_mean %.2f W at %g deg (Table 5.4: %.1f W at %g deg), "
                "%.0f s\n",
                t, m.mean_W(), m.pitch_deg, published[t], published_pitch[t],
                study.table_seconds + study.study_seconds);
    EXPECT_GE(m.pitch_deg, 52);
    EXPECT_LE(m.pitch_deg, 60);
  }
  const double decrease[2] = {100 * (1 - minimum[1] / minimum[0]),
                              100 * (1 - minimum[2] / minimum[0])};
  std::printf("decrease: magnet iron %.1f %% (Table 5.5: 32 %%), magnet and coil iron %.1f %% "
              "(66 %%)\n",
              decrease[0], decrease[1]);
  EXPECT_NEAR(decrease[0], 32, 3.2);
  EXPECT_NEAR(decrease[1], 66, 6.6);
}

// The command end to end on a tiny grid, and its refusals (exit 2, nothing written): no
// --analytic, a --torque, a pitch outside 10..120 deg, a malformed pitch list.
TEST(CoilPitch, CommandWritesItsOutputsAndRefusesBadInput) {
  const auto out = std::filesystem::temp_directory_path() / "magfem_tests" / "coil_pitch_cli";
  std::filesystem::remove_all(out);
  const std::string exe = magfem::test::magfem_binary();
  const std::string base = exe + " actuator " + topology + " --rotor rotor --orientations rx=0,20 ";
  ASSERT_EQ(std::system((base + "--analytic --coil-pitch 50:10:60 --out " + out.string() +
                         " > /dev/null 2>&1")
                            .c_str()),
            0);
  std::ifstream in(out / "coil_pitch.csv");
  const std::string csv{std::istreambuf_iterator<char>(in), {}};
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "coil_pitch_deg,n_coils,G_w_deg,C_w_deg,P_x_W,P_y_W,P_z_W,P_mean_W,n_ill_x,n_ill_y,"
            "n_ill_z");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 3);
  EXPECT_TRUE(std::filesystem::exists(out / "summary.json"));

  const auto bad = std::filesystem::temp_directory_path() / "magfem_tests" / "coil_pitch_bad";
  auto refuses = [&](const std::string& args) {
    std::filesystem::remove_all(bad);
    const std::string cmd = base + args + " --out " + bad.string() + " 2> /dev/null";
    const int rc = std::system(cmd.c_str());
    EXPECT_TRUE(WIFEXITED(rc) && WEXITSTATUS(rc) == 2) << cmd;
    EXPECT_FALSE(std::filesystem::exists(bad)) << cmd;
  };
  refuses("--coil-pitch 50:10:60");
  refuses("--analytic --coil-pitch 50:10:60 --torque 0,0,1");
  refuses("--analytic --coil-pitch 5:5:60");
  refuses("--analytic --coil-pitch 50:x:60");
}
