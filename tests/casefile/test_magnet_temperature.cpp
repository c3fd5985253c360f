// casefile/: a magnet region's `temperature_C` and `HcJ_kApm` give the region its grade at
// that temperature (the solve's B_r and the knee's H_cJ); keys that cannot apply are errors
// naming the line and field.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "casefile/case_spec.hpp"
#include "core/input_error.hpp"

using namespace magfem;

namespace {

const char* good = R"(dimension: 2
unit: mm
materials:
  plain: {kind: magnet, B_r: 1.0, mu_r: 1.05}
  own: {kind: magnet, B_r: 1.2, mu_r: 1.0, HcJ_kApm: 800, alpha_Br_pct_per_K: -0.1}
regions:
  - {name: hot, shape: disk, center: [0, 0], radius: 2, material: N42,
     magnetization: {type: parallel, angle: 90}, temperature_C: 100}
  - {name: cold, shape: disk, center: [5, 0], radius: 2, material: N42,
     magnetization: {type: parallel, angle: 90}, HcJ_kApm: 1200}
  - {name: mine, shape: disk, center: [10, 0], radius: 2, material: own,
     magnetization: {type: parallel, angle: 90}, temperature_C: 70}
  - {name: steel, shape: disk, center: [15, 0], radius: 2, material: steel_1010}
boundary: {type: open, radius: 30}
mesh: {size: 2}
)";

CaseSpec read_text(const std::string& text) {
  return read_case_text(text, "temp.yaml");
}

TEST(MagnetTemperature, RegionsGetTheirGradeAtTheirTemperature) {
  const CaseSpec c = read_text(good);
  const Material& hot = *c.regions[0].material;
  EXPECT_DOUBLE_EQ(hot.temperature_C, 100);
  EXPECT_NEAR(hot.B_r, 1.31 * (1 - 0.0012 * 80), 1e-12); // the solve sees B_r(100 C)
  EXPECT_NEAR(*hot.coercivity_Apm(), 955e3 * (1 - 0.0075 * 80), 1e-6);
  const Material& cold = *c.regions[1].material;
  EXPECT_DOUBLE_EQ(cold.B_r, 1.31);
  EXPECT_DOUBLE_EQ(*cold.coercivity_Apm(), 1200e3); // the region's H_cJ, not the grade's
  const Material& mine = *c.regions[2].material;
  EXPECT_NEAR(mine.B_r, 1.2 * (1 - 0.001 * 50), 1e-12);
  EXPECT_FALSE(mine.knee_T()); // no beta: H_cJ at 70 C unknown
  // The region's own material does not change the case's (or the library's) grade.
  EXPECT_DOUBLE_EQ(c.materials.at("own").B_r, 1.2);
}

TEST(MagnetTemperature, KeysThatCannotApplyNameLineAndField) {
  struct Bad {
    std::string from, to;
    int line;
    std::string field;
  };
  const std::vector<Bad> cases = {
      // a grade without alpha cannot be taken to 80 C
      {"material: N42,\n     magnetization: {type: parallel, angle: 90}, temperature_C: 100",
       "material: plain,\n     magnetization: {type: parallel, angle: 90}, temperature_C: 80", 8,
       "regions[0].temperature_C"},
      // not a magnet
      {"material: steel_1010}", "material: steel_1010, temperature_C: 50}", 13,
       "regions[3].temperature_C"},
      {"material: steel_1010}", "material: steel_1010, HcJ_kApm: 900}", 13, "regions[3].HcJ_kApm"},
      {"HcJ_kApm: 1200}", "HcJ_kApm: -5}", 10, "regions[1].HcJ_kApm"},
      {"temperature_C: 100}", "temperature_C: -300}", 8, "regions[0].temperature_C"},
      // far enough that beta -0.75 %/K takes H_cJ through zero
      {"temperature_C: 100}", "temperature_C: 160}", 8, "regions[0].temperature_C"},
  };
  for (const auto& bad : cases) {
    std::string text = good;
    const auto at = text.find(bad.from);
    ASSERT_NE(at, std::string::npos) << bad.from;
    text.replace(at, bad.from.size(), bad.to);
    try {
      read_text(text);
      ADD_FAILURE() << "accepted: " << bad.to;
    } catch (const InputError& e) {
      EXPECT_EQ(e.line(), bad.line) << e.what();
      EXPECT_EQ(e.field(), bad.field) << e.what();
    }
  }
}

} // namespace
