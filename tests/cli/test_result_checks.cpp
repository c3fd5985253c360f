// Numerical guards (pipeline/result_checks.hpp, issue 15): a solution with NaN or Inf stops the run
// (exit 3, nothing written); a B-H curve used beyond its table is reported in summary.json
// `warnings`; a stress-tensor surface that cuts a magnet or iron region is an input error
// naming the force and the region, found on the mesh before the solve.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <regex>
#include <sstream>
#include <string>
#include <utility>

#include <sys/wait.h>

#include "casefile/case_spec.hpp"
#include "core/input_error.hpp"
#include "pipeline/run3d.hpp"
#include "tests/case_helpers.hpp"
#include "tests/run_cli.hpp"

namespace fs = std::filesystem;

namespace magfem {
namespace {

// Iron bar (a custom B-H table that ends at 1.0 T) between the two sides of a coil of
// `ampere_turns`, 2D per metre; a stress circle of `circle_mm` about the bar.
std::string iron_case(double ampere_turns, double circle_mm) {
  char text[2048];
  std::snprintf(text, sizeof text, R"(title: iron bar in a coil
unit: mm
materials:
  short_table: {kind: soft, bh: [[0, 0], [100, 0.5], [400, 1.0]]}
regions:
  - {name: iron, shape: rectangle, center: [0, 0], width: 10, height: 30, material: short_table,
     mesh_size: 2}
  - {name: go, shape: rectangle, center: [-10, 0], width: 4, height: 30, turns: 1,
     current: %g, mesh_size: 2}
  - {name: back, shape: rectangle, center: [10, 0], width: 4, height: 30, turns: 1,
     current: %g, mesh_size: 2}
boundary: {type: open, radius: 60}
mesh: {size: 6}
solver: {order: 1, method: newton, tolerance: 1e-8}
forces:
  - {name: on_bar, type: circle, center: [0, 0], radius: %g}
)",
                ampere_turns, -ampere_turns, circle_mm);
  return text;
}

std::unique_ptr<Run2D> solve_2d(const std::string& name, const std::string& text) {
  return run_case_2d(read_case(test::write_temp_case(name, text)));
}

bool mentions(const std::vector<std::string>& warnings, const std::string& a,
              const std::string& b) {
  for (const auto& w : warnings)
    if (w.find(a) != std::string::npos && w.find(b) != std::string::npos)
      return true;
  return false;
}

// The bar saturates far beyond 1.0 T at 20 kA-turns (the coil field alone is ~ mu0 NI / 30
// mm ~ 0.8 T, times the bar's permeability); at 10 A-turns it stays far below (B ~ 0.01 T).
// The warning carries the region's peak B (the same number as summary.json's peak_B_T):
// it would fail if the check compared H with B, looked at the wrong region, or missed the
// table's end.
TEST(ResultChecks, BhTableExceededIsAWarningWithThePeakB) {
  const auto hot = solve_2d("bh_hot.yaml", iron_case(20000, 25));
  double peak = 0;
  for (const auto& r : hot->energy.regions)
    if (r.name == "iron")
      peak = r.peak_B_T;
  ASSERT_GT(peak, 1.0);
  char expected[64];
  std::snprintf(expected, sizeof expected, "B reaches %.4g T", peak);
  EXPECT_TRUE(mentions(hot->warnings, "region 'iron'", expected))
      << (hot->warnings.empty() ? "no warning" : hot->warnings.front());

  const auto cold = solve_2d("bh_cold.yaml", iron_case(10, 25));
  for (const auto& w : cold->warnings)
    EXPECT_EQ(w.find("B-H table"), std::string::npos) << w;
}

void expect_cut(const std::function<void()>& run, const std::string& force,
                const std::string& region) {
  try {
    run();
    ADD_FAILURE() << "a stress surface cutting " << region << " was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("force '" + force + "'"), std::string::npos) << what;
    EXPECT_NE(what.find(region), std::string::npos) << what;
    EXPECT_EQ(e.field(), "forces." + force) << what;
  }
}

// A stress circle of 8 mm about the 10 x 30 mm bar cuts it (and the coil sides, which are
// air and do not count); one of 25 mm lies in air around bar and coils.
TEST(ResultChecks, StressCircleCuttingIronIsAnError) {
  expect_cut([] { solve_2d("circle_cut.yaml", iron_case(10, 8)); }, "on_bar", "iron region 'iron'");
  EXPECT_NO_THROW(solve_2d("circle_clear.yaml", iron_case(10, 25)));
}

// 3D: a magnetized sphere of radius 10 mm; a stress sphere of 6 mm cuts it, one of 15 mm is
// in air. Coarse order-1 mesh: the check looks at the elements, before the solve.
TEST(ResultChecks, StressSphereCuttingAMagnetIsAnError) {
  auto text = [](double r) {
    char t[1024];
    std::snprintf(t, sizeof t, R"(title: magnet ball
dimension: 3
unit: mm
materials:
  pm: {kind: magnet, B_r: 1.0, mu_r: 1.05}
regions:
  - {name: ball, shape: spherical_segment, r_inner: 0, r_outer: 10, material: pm,
     magnetization: {type: parallel, direction: [0, 0, 1]}, mesh_size: 4}
boundary: {type: open, radius: 25, shell_ratio: 1.5}
mesh: {size: 8, chord_tolerance: 0.5}
solver: {order: 1}
forces:
  - {name: ball_f, type: sphere, radius: %g}
)",
                  r);
    return std::string(t);
  };
  expect_cut([&] { run_case_3d(read_case(test::write_temp_case("sphere_cut.yaml", text(6)))); },
             "ball_f", "magnet region 'ball'");
  const auto clear = run_case_3d(read_case(test::write_temp_case("sphere_clear.yaml", text(15))));
  EXPECT_TRUE(clear->warnings.empty()) << clear->warnings.front();
}

// NaN or Inf: a remanence of 1e308 T overflows the load vector (the solution is Inf/NaN);
// 1e200 T gives a finite solution whose energy (~ B^2) overflows. Both exit 3 through the
// binary, say why, and write nothing (not even the output directory).
TEST(ResultChecks, NanOrInfStopsTheRunWithExit3AndNoOutputs) {
  for (const auto& [remanence, what] :
       {std::pair<std::string, std::string>{"1e308", "solution"}, {"1e200", "energy"}}) {
    const std::string path = test::write_temp_case("overflow_" + remanence + ".yaml",
                                                   R"(unit: mm
materials:
  pm: {kind: magnet, B_r: )" + remanence + R"(, mu_r: 1.0}
regions:
  - {name: m, shape: rectangle, center: [0, 0], width: 10, height: 10, material: pm,
     magnetization: {type: parallel, angle: 90}, mesh_size: 3}
boundary: {type: open, radius: 40}
mesh: {size: 8}
solver: {order: 1}
)");
    const fs::path out = fs::temp_directory_path() / "magfem_tests" / ("overflow_" + remanence);
    fs::remove_all(out);
    const auto [status, text] = test::run_cli("solve " + path + " --out " + out.string());
    EXPECT_EQ(status, 3) << text;
    EXPECT_NE(text.find("NaN or Inf"), std::string::npos) << text;
    EXPECT_NE(text.find(what), std::string::npos) << text;
    EXPECT_FALSE(fs::exists(out)) << remanence;
  }
}

// Issue 36: `--mesh-scale` above gap_layers leaves order-1 elements wider than an air gap.
// The run goes on, and says so on stderr and in summary.json `warnings`, naming the gap's width
// and both parts (a 1 mm gap between two spheres, gap_layers 2, scale 2.5: 1.25 mm elements).
// It would fail if the mesher's warnings were dropped on the way to either output.
TEST(ResultChecks, GapWithoutAnElementAcrossIsWarnedOnStderrAndInTheSummary) {
  const std::string path = test::write_temp_case("gap_scale.yaml", R"(dimension: 3
unit: mm
materials:
  pm: {kind: magnet, B_r: 1.0, mu_r: 1.0}
  core: {kind: linear, mu_r: 100}
regions:
  - {name: magnet, shape: spherical_segment, r_inner: 0, r_outer: 6, material: pm,
     magnetization: {type: parallel, direction: [1, 0, 0]}}
  - {name: iron, shape: spherical_segment, r_inner: 0, r_outer: 5, material: core,
     placement: {translate: [12, 0, 0]}}
boundary: {type: open, radius: 25, shell_ratio: 1.5}
mesh: {size: 8, chord_tolerance: 0.1, gap_layers: 2}
solver: {order: 1}
)");
  const fs::path out = fs::temp_directory_path() / "magfem_tests" / "gap_scale";
  fs::remove_all(out);
  const auto [status, text] =
      test::run_cli("solve " + path + " --mesh-scale 2.5 --quiet --out " + out.string());
  EXPECT_EQ(status, 0) << text;
  // "magfem: warning:" is the stderr line (the console summary on stdout says "warning  ").
  EXPECT_NE(text.find("magfem: warning: the 1 mm air gap between parts 'magnet' and 'iron'"),
            std::string::npos)
      << text;
  std::ifstream summary(out / "summary.json");
  std::stringstream json;
  json << summary.rdbuf();
  EXPECT_NE(json.str().find("1 mm air gap between parts 'magnet' and 'iron'"), std::string::npos)
      << json.str();
}

} // namespace
} // namespace magfem
