// magfem study (issue 14): a grid over case-file parameters with the analytic sweep inside.
// The parametric compensator reproduces the Table 4.2 torque at R_in 29, R_out 43 mm and the
// sec. 4.4.1 elbow design; the grid is fast enough to design with; bad options are
// InputErrors naming the option.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "analytic/exterior_field_interaction.hpp"
#include "analytic/interaction_cases.hpp"
#include "core/input_error.hpp"
#include "pipeline/analytic_scene.hpp"
#include "studies/study.hpp"
#include "tests/case_helpers.hpp"

using namespace magfem;

namespace {

StudyOptions compensator_study(const std::vector<std::string>& params) {
  std::vector<std::string> args{test::example("3d/compensator_study.yaml"),
                                "--objective",
                                "peak_torque",
                                "--objective",
                                "torque_at:90",
                                "--rotate",
                                "outer",
                                "--axis",
                                "y",
                                "--angles",
                                "0:10:180"};
  for (const auto& p : params)
    args.push_back("--param"), args.push_back(p);
  return parse_study_options(args);
}

// Width of a PNG (IHDR, big-endian at byte 16): which of the two plots was drawn.
unsigned png_width(const std::filesystem::path& png) {
  std::ifstream in(png, std::ios::binary);
  unsigned char b[20] = {};
  in.read(reinterpret_cast<char*>(b), sizeof b);
  return (b[16] << 24) | (b[17] << 16) | (b[18] << 8) | b[19];
}

// The charge interaction's converged Table 4.2 peak torque (test_charge_gravity_compensator,
// equal to the harmonic form to 1e-9: test_axisymmetric_interaction).
constexpr double table42_torque = 12.3653;

} // namespace

TEST(Study, ParametricCompensatorReproducesTable42AndTheElbowDesign) {
  // Table 4.2 through the parameters: the same torque as examples/3d/compensator_table42.yaml.
  const auto t42 = run_study(compensator_study({"R_in=29", "R_out=43"}));
  ASSERT_EQ(t42.size(), 1u);
  ASSERT_TRUE(t42[0].ok) << t42[0].error;
  EXPECT_EQ(t42[0].method, "harmonic_interaction");
  EXPECT_NEAR(t42[0].objectives[0], table42_torque, 1e-4);
  EXPECT_NEAR(t42[0].objectives[1], table42_torque, 1e-4); // the peak is at 90 deg

  // Sec. 4.4.1: at R_in 35 mm the elbow design R_out 49.6 mm gives 1.58 x the Table 4.2
  // torque (5 %: the tolerance paper_targets gives the thesis's torque figures). Then the
  // inverse: the R_out where the curve crosses 1.58 x 12.37 N m, by linear interpolation on a
  // 0.2 mm grid, within 1 mm of the published 49.6 mm (a 5 % torque band is ~+-1.5 mm there).
  const auto elbow = run_study(compensator_study({"R_out=49.6"}));
  ASSERT_TRUE(elbow[0].ok) << elbow[0].error;
  const double ratio = elbow[0].objectives[0] / table42_torque;
  EXPECT_NEAR(ratio, 1.58, 0.05 * 1.58);
  RecordProperty("elbow_ratio", std::to_string(ratio));

  const auto curve = run_study(compensator_study({"R_out=44:0.2:60"}));
  const double target = 1.58 * table42_torque;
  double crossing = 0;
  for (std::size_t i = 1; i < curve.size(); ++i) {
    ASSERT_TRUE(curve[i].ok) << curve[i].error;
    const double a = curve[i - 1].objectives[0], b = curve[i].objectives[0];
    EXPECT_GT(b, a); // the torque amplitude grows with R_out (Fig. 4.10)
    if (a < target && b >= target)
      crossing = curve[i - 1].parameters[0] +
                 (target - a) / (b - a) * (curve[i].parameters[0] - curve[i - 1].parameters[0]);
  }
  EXPECT_NEAR(crossing, 49.6, 1.0);
  RecordProperty("R_out_for_1.58x_mm", std::to_string(crossing));
}

TEST(Study, TwentyByTwentyGrid) {
  // Issue 14's 20 x 20 study of the torque amplitude over R_in and R_out. Its speed target
  // (<= 10 s) is printed by scripts/benchmark.sh, not asserted: a loaded CI machine is no clock.
  const auto options = compensator_study({"R_in=25:0.5:34.5", "R_out=45:1:64"});
  const auto t0 = std::chrono::steady_clock::now();
  const auto designs = run_study(options);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_EQ(designs.size(), 400u);
  for (const auto& d : designs)
    ASSERT_TRUE(d.ok) << d.error;
  // A larger inner magnet at the same R_out gives more torque (Fig. 4.11's trend) here.
  EXPECT_GT(designs[399].objectives[0], designs[19].objectives[0]);
  RecordProperty("seconds_400_designs", std::to_string(seconds));
  const std::string csv = study_csv(options, designs);
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "R_in,R_out,peak_torque_Nm,torque_at_90deg_Nm");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 401);
}

TEST(Study, ADesignWhoseGeometryIsImpossibleFailsAlone) {
  // R_out 30 < R_in + gap = 36: the reader refuses that design; the others go on.
  const auto designs = run_study(compensator_study({"R_out=30,45"}));
  ASSERT_EQ(designs.size(), 2u);
  EXPECT_FALSE(designs[0].ok);
  EXPECT_NE(designs[0].error.find("compensator_study.yaml"), std::string::npos) << designs[0].error;
  EXPECT_TRUE(designs[1].ok) << designs[1].error;
}

TEST(Study, BadOptionsNameTheOption) {
  auto field_of = [](const std::vector<std::string>& params) {
    try {
      run_study(compensator_study(params));
    } catch (const InputError& e) {
      return e.field();
    }
    return std::string("accepted");
  };
  EXPECT_EQ(field_of({"R_mid=1:1:2"}), "--param"); // not a parameter of the file
  EXPECT_EQ(field_of({"R_out=50:0:60"}), "--param");
  EXPECT_EQ(field_of({"R_out"}), "--param");
  EXPECT_THROW(parse_study_options({"case.yaml", "--param", "a=1", "--objective", "volume",
                                    "--rotate", "g", "--axis", "y"}),
               InputError);
  EXPECT_THROW(parse_study_options({"case.yaml", "--param", "a=1", "--objective", "peak_torque",
                                    "--rotate", "g", "--axis", "y"}), // no --angles
               InputError);
  for (const std::string bad : {"--order=1.5", "--mesh-scale=0"}) {
    const auto eq = bad.find('=');
    try {
      parse_study_options({"case.yaml", "--param", "a=1", "--objective", "torque_at:90", "--rotate",
                           "g", "--axis", "y", bad.substr(0, eq), bad.substr(eq + 1)});
      ADD_FAILURE() << bad << " accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), bad.substr(0, eq));
    }
  }
}

TEST(Study, CommandWritesTheCsvThePlotAndTheSummary) {
  auto options = compensator_study({"R_out=44:4:56", "R_in=30,35"});
  const auto dir = std::filesystem::temp_directory_path() / "magfem_tests" / "study_command";
  std::filesystem::remove_all(dir);
  options.out_dir = dir.string();
  ASSERT_EQ(run_study_command(options), 0);
  std::ifstream csv(dir / "study.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "R_out,R_in,peak_torque_Nm,torque_at_90deg_Nm");
  std::ifstream summary(dir / "summary.json");
  const std::string text((std::istreambuf_iterator<char>(summary)), {});
  EXPECT_NE(text.find("\"method\": \"harmonic_interaction\""), std::string::npos) << text;
  EXPECT_NE(text.find("\"designs\": 8"), std::string::npos) << text;
  if (std::system("command -v gnuplot > /dev/null 2>&1") == 0) {
    EXPECT_GT(std::filesystem::file_size(dir / "study.png"), 1000u);
    // Two parameters with several values each: a contour map per objective (620 px wide
    // each), not lines (600 px each).
    EXPECT_EQ(png_width(dir / "study.png"), 2 * 620u);
  }
}

TEST(Study, OneParameterIsPlottedAsLines) {
  if (std::system("command -v gnuplot > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "no gnuplot";
  auto options = compensator_study({"R_out=44:4:56"});
  const auto dir = std::filesystem::temp_directory_path() / "magfem_tests" / "study_lines";
  std::filesystem::remove_all(dir);
  options.out_dir = dir.string();
  ASSERT_EQ(run_study_command(options), 0);
  EXPECT_EQ(png_width(dir / "study.png"), 2 * 600u);
}

TEST(Study, PrototypeHeightExampleIsTheDocumentedLayout) {
  // examples/3d/compensator_prototype_height_study.yaml builds the layout its comments state
  // (180 cylinders, pitch 5.14 mm on the 27.9 mm sphere, B_r 1.305 / 1.345 T), which
  // analytic/interaction_cases.cpp builds in code: the study's torque at 90 deg equals the
  // exterior-field interaction on that arrangement to round-off and tolerance (1e-8).
  const std::string file = test::example("3d/compensator_prototype_height_study.yaml");
  const AnalyticScene scene = analytic_scene(read_case(file, {{"height", 12.5}}));
  EXPECT_EQ(scene.magnets.size(), 181u);
  const auto designs =
      run_study(parse_study_options({file, "--param", "height=12.5", "--objective", "torque_at:90",
                                     "--rotate", "outer", "--axis", "y"}));
  ASSERT_EQ(designs.size(), 1u);
  ASSERT_TRUE(designs[0].ok) << designs[0].error;
  EXPECT_EQ(designs[0].method, "exterior_field_interaction");
  const InteractionCase c = prototype_case(0.0125, 90);
  const double expected =
      exterior_field_interaction(c.on, c.by, Eigen::Vector3d::Zero()).on.torque.y();
  EXPECT_NEAR(designs[0].objectives[0], expected, 1e-8 * std::abs(expected));
  EXPECT_GT(designs[0].torque_accuracy, 0); // the estimate is recorded
}

// The checkpoint's identity names the FE mesh scale "as in the case" (0, the command line's
// default) as 1 (Python's default): the same mesh, so either can resume the other's run
// (tests/python/test_resume.py shows it for a sweep); another scale stays another run.
TEST(Study, CheckpointIdentityNamesTheDefaultMeshScaleAsOne) {
  const auto options_at = [](double scale) {
    StudyOptions o = parse_study_options({test::example("3d/compensator_study.yaml"), "--param",
                                          "R_out=40,50", "--objective", "torque_at:90", "--rotate",
                                          "outer", "--axis", "y", "--fe"});
    o.sweep.mesh_scale = scale;
    return o;
  };
  EXPECT_EQ(study_checkpoint_options(options_at(0)), study_checkpoint_options(options_at(1)));
  EXPECT_NE(study_checkpoint_options(options_at(2)), study_checkpoint_options(options_at(1)));
  SweepOptions sweep;
  sweep.group = "outer";
  const auto sweep_at = [&](double scale) {
    sweep.mesh_scale = scale;
    return sweep_checkpoint_options(sweep, "y", "", "");
  };
  EXPECT_EQ(sweep_at(0), sweep_at(1));
  EXPECT_NE(sweep_at(2), sweep_at(1));
}
