// Bad input of axisymmetric cases: each gives one InputError naming the file, the line and the
// field; through the CLI, exit code 2 and no outputs.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "tests/case_helpers.hpp"
#include "core/constants.hpp"
#include "core/input_error.hpp"
#include "tests/test_paths.hpp"
#include "analytic/coil_closed_forms.hpp"

using namespace magfem;

namespace {

// A valid case; each test breaks one thing in it.
const std::string good = R"(dimension: axi
unit: mm
materials:
  pm: {kind: magnet, B_r: 1.0, mu_r: 1.0}
regions:
  - name: magnet
    shape: rectangle
    center: [3, 0]
    width: 6
    height: 6
    material: pm
    magnetization: {type: parallel}
  - {name: coil, shape: rectangle, center: [6, 10], width: 4, height: 4, turns: 10, current: 1}
boundary: {type: open, radius: 25}
mesh: {size: 3}
probes:
  - {name: axis, type: line, start: [0, -20], end: [0, 20], points: 41}
  - {name: arc, type: circle, center: [0, 0], radius: 12, angle_start: -90, angle_end: 90}
forces:
  - {name: f, type: lorentz, regions: [coil]}
)";

std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto pos = text.find(from);
  if (pos == std::string::npos)
    throw std::logic_error("pattern not in case: " + from);
  return text.replace(pos, from.size(), to);
}

void expect_input_error(const std::string& name, const std::string& text, int line,
                        const std::string& field) {
  const auto path = test::write_temp_case(name + ".yaml", text);
  try {
    auto spec = read_case(path);
    run_case_2d(std::move(spec));
    FAIL() << name << ": no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path) << name;
    EXPECT_EQ(e.line(), line) << name << ": " << e.what();
    EXPECT_NE(e.field().find(field), std::string::npos) << name << ": " << e.what();
  }
}

} // namespace

TEST(AxiBadInput, TheGoodCaseRuns) {
  const auto run = run_case_2d(read_case(test::write_temp_case("axi_good.yaml", good)));
  EXPECT_TRUE(run->report.converged);
}

TEST(AxiBadInput, RegionsCrossingTheAxis) {
  expect_input_error("axi_rect_cross", replace(good, "center: [3, 0]", "center: [2, 0]"), 7,
                     "regions[0].shape");
  // A disk off the axis reaching r < 0 (a disk centred on the axis is a ball: allowed).
  expect_input_error("axi_disk_cross",
                     replace(good, "shape: rectangle, center: [6, 10], width: 4, height: 4",
                             "shape: disk, center: [1, 10], radius: 2"),
                     13, "regions[1].shape");
}

TEST(AxiBadInput, RadialMagnetizationCentreOffTheAxis) {
  expect_input_error("axi_radial_off",
                     replace(good, "{type: parallel}", "{type: radial, center: [1, 0]}"), 12,
                     "magnetization.center");
}

TEST(AxiBadInput, ProbesAtNegativeRadius) {
  expect_input_error("axi_probe_line", replace(good, "start: [0, -20]", "start: [-1, -20]"), 17,
                     "probes[0].start");
  expect_input_error("axi_probe_arc", replace(good, "angle_start: -90", "angle_start: -100"), 18,
                     "probes[1]");
}

TEST(AxiBadInput, ForcesAndSettingsThatDoNotApply) {
  expect_input_error("axi_stress_off_axis",
                     replace(good, "{name: f, type: lorentz, regions: [coil]}",
                             "{name: f, type: circle, center: [1, 0], radius: 8}"),
                     20, "forces[0].center");
  expect_input_error("axi_band",
                     replace(good, "{name: f, type: lorentz, regions: [coil]}",
                             "{name: f, type: band, r_inner: 7, r_outer: 8}"),
                     20, "forces[0].type");
  expect_input_error("axi_stack", replace(good, "unit: mm\n", "unit: mm\nstack_length: 10\n"), 3,
                     "stack_length");
}

TEST(AxiBadInput, CliExitsWithCode2AndWritesNothing) {
  const auto path =
      test::write_temp_case("axi_cli_bad.yaml", replace(good, "center: [3, 0]", "center: [2, 0]"));
  const auto out = std::filesystem::temp_directory_path() / "magfem_tests" / "axi_cli_bad_out";
  std::filesystem::remove_all(out);
  const std::string cmd = std::string(magfem::test::magfem_binary()) + " solve " + path +
                          " --out " + out.string() + " 2>/dev/null";
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  EXPECT_FALSE(std::filesystem::exists(out / "summary.json"));
  EXPECT_FALSE(std::filesystem::exists(out / "axis.csv"));
}

// Issue 11 lists "a coil on the axis with zero inner radius where that is singular". It is not
// singular here: a uniform J_phi on a region touching the axis is a bounded current density
// whose field is finite and smooth (the on-axis closed form has no singularity at r_i = 0), and
// the weak form's r weighting integrates it like any other load. So the case is accepted, and
// its on-axis field must equal the closed form. The FE's error there is that of the P2 field
// near the kinks of B_z at the coil's end faces (dB_z/dz jumps where the current ends): 0.78 %
// of the peak measured at these sizes (40 points, none on an end face), no larger than for a
// ring r 2..4 mm on the same mesh (its pointwise rms 0.41 % vs 0.8 % here); tolerance 2.5 %.
// Dropping the load of the elements on the axis (r < 0.5 mm: the innermost loops, which
// give the most field per ampere on the axis) would move B there by several %.
TEST(AxiBadInput, CoilTouchingTheAxisIsAcceptedAndExact) {
  const auto path = test::write_temp_case("axi_coil_on_axis.yaml", R"(dimension: axi
unit: mm
regions:
  - {name: coil, shape: rectangle, center: [2, 0], width: 4, height: 6, turns: 100, current: 1,
     mesh_size: 0.5}
boundary: {type: open, radius: 20}
mesh: {size: 1.5}
probes:
  - {name: axis, type: line, start: [0, -10], end: [0, 10], points: 40}
)");
  const auto run = run_case_2d(read_case(path));
  const auto& t = test::probe(*run, "axis");
  const CoaxialCoil coil{0, 4e-3, -3e-3, 3e-3, 100};
  double err = 0, peak = 0;
  for (const auto& row : t.rows) {
    const double exact = mu0 * coaxial_coil_axial_H(coil, 1.0, row[t.column("z")] * 1e-3);
    err = std::max(err, std::abs(row[t.column("Bz")] - exact));
    peak = std::max(peak, std::abs(exact));
  }
  std::printf("coil touching the axis: max |Bz - exact| / peak = %.2e\n", err / peak);
  EXPECT_LT(err, 2.5e-2 * peak);
}
