// Bad input of axisymmetric cases: each gives one InputError naming the file, the line and the
// field; through the CLI, exit code 2 and no outputs.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "case_helpers.hpp"
#include "core/input_error.hpp"

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
  const std::string cmd =
      std::string(MAGFEM_BINARY) + " solve " + path + " --out " + out.string() + " 2>/dev/null";
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  EXPECT_FALSE(std::filesystem::exists(out / "summary.json"));
  EXPECT_FALSE(std::filesystem::exists(out / "axis.csv"));
}
