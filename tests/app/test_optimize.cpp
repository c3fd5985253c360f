// magfem optimize (issue 14): NLopt on the analytic model finds an optimum known in closed
// form. A uniformly magnetized sphere (radius a, a point dipole m = 4/3 pi a^3 M) at the
// centre of a radial hemispherical shell (a + g .. R) feels T = mu0 m (M/2) ln(R/(a+g)) at
// 90 deg (test_axisymmetric_interaction checks this to round-off), so the torque is
// maximal where d/da [a^3 ln(R/(a+g))] = 0, i.e. 3 ln(R/(a+g)) = a/(a+g).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "app/optimize.hpp"
#include "core/input_error.hpp"

using namespace magfem;

namespace {

std::string write_case() {
  const auto dir = std::filesystem::temp_directory_path() / "magfem_tests" / "optimize";
  std::filesystem::create_directories(dir);
  const auto path = dir / "dipole_in_shell.yaml";
  std::ofstream(path) << R"(dimension: 3
unit: mm
parameters:
  a: 20
  gap: 1
  R: 50
materials:
  pm: {kind: magnet, B_r: 1.2, mu_r: 1.0}
regions:
  - {name: ball, shape: spherical_segment, r_outer: ${a}, theta: [0, 180], material: pm,
     magnetization: {type: parallel, direction: [0, 0, 1]}}
  - {name: shell, shape: spherical_segment, r_inner: ${a + gap}, r_outer: ${R},
     theta: [0, 90], material: pm, magnetization: {type: radial}, group: shell}
boundary: {type: open, radius: 80}
mesh: {size: 8}
)";
  return path.string();
}

} // namespace

TEST(Optimize, FindsTheClosedFormOptimumOfTheDipoleInAShell) {
  const auto options = parse_optimize_options({write_case(), "--vary", "a=5:45", "--maximize",
                                               "peak_torque", "--rotate", "shell", "--axis", "y",
                                               "--angles", "90", "--xtol", "1e-7"});
  const auto r = run_optimize(options);
  // The optimum by bisection on 3 ln(R/(a+g)) - a/(a+g), decreasing in a (mm).
  double lo = 5, hi = 45;
  for (int i = 0; i < 100; ++i) {
    const double a = 0.5 * (lo + hi);
    (3 * std::log(50 / (a + 1)) - a / (a + 1) > 0 ? lo : hi) = a;
  }
  ASSERT_EQ(r.optimum.size(), 1u);
  // xtol 1e-7 relative on a; the objective is flat at the optimum (quadratic), so COBYLA's
  // stopping leaves ~sqrt of the objective's resolution: 1e-3 mm is ample and still 1e-4.
  EXPECT_NEAR(r.optimum[0], lo, 1e-3) << r.stop;
  EXPECT_EQ(r.method, "harmonic_interaction");
  const double M = 1.2 / (4e-7 * M_PI), a = lo * 1e-3;
  const double expected =
      4e-7 * M_PI * 4.0 / 3.0 * M_PI * a * a * a * M * 0.5 * M * std::log(0.050 / (a + 0.001));
  EXPECT_NEAR(r.objective, expected, 1e-9 * expected);
  RecordProperty("optimum_a_mm", std::to_string(r.optimum[0]));
  RecordProperty("closed_form_a_mm", std::to_string(lo));
  RecordProperty("evaluations", r.evaluations);
}

TEST(Optimize, BadOptionsNameTheOption) {
  const std::string c = write_case();
  auto field_of = [&](std::vector<std::string> args) {
    args.insert(args.begin(), c);
    try {
      run_optimize(parse_optimize_options(args));
    } catch (const InputError& e) {
      return e.field();
    }
    return std::string("accepted");
  };
  const std::vector<std::string> rest{"--rotate", "shell", "--axis", "y", "--angles", "90"};
  auto with = [&](std::vector<std::string> head) {
    head.insert(head.end(), rest.begin(), rest.end());
    return head;
  };
  EXPECT_EQ(field_of(with({"--vary", "b=1:2", "--maximize", "peak_torque"})), "--param");
  EXPECT_EQ(field_of(with({"--vary", "a=5:5", "--maximize", "peak_torque"})), "--vary");
  EXPECT_EQ(field_of(with({"--vary", "a=5:45"})), "--maximize");
  EXPECT_EQ(field_of(with({"--maximize", "peak_torque"})), "--vary");
}
