// casefile/ parameters (issue 14): `parameters:` and `${expression}` substituted at read time,
// lengths in parameter units converted once to the case's unit and then to SI with the rest,
// overrides from the command line; undefined names, cycles and expressions that are not
// numbers are InputErrors naming the file, line and dotted field.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "casefile/case_spec.hpp"
#include "casefile/parameter_expression.hpp"
#include "core/input_error.hpp"

using namespace magfem;

namespace {

std::string write_case(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::temp_directory_path() / "magfem_tests" / "casefile";
  std::filesystem::create_directories(dir);
  const auto path = dir / name;
  std::ofstream(path) << text;
  return path.string();
}

// A two-shell case in mm whose radii come from parameters of three kinds: a plain number, a
// value in cm (converted to mm), expressions of other parameters, quoted or not, in block
// and flow collections.
const char* parametric = R"(dimension: 3
unit: mm
title: "shell ${R_out} mm"
parameters:
  R_in: {value: 2.9, unit: cm}
  gap: 1
  R_out: ${R_in + gap + 13}
  half: {value: ${(R_out - R_in) / 2}, unit: mm}
materials:
  pm: {kind: magnet, B_r: 1.3, mu_r: 1.0}
regions:
  - name: inner
    shape: spherical_segment
    r_outer: ${R_in}
    theta: [0, 90]
    material: pm
    magnetization: {type: parallel, direction: [0, 0, 1]}
  - name: outer
    shape: spherical_segment
    r_inner: "${R_in + gap}"
    r_outer: ${R_out}
    theta: [0, ${90 - 0}]
    material: pm
    magnetization: {type: radial, sign: -1}
    group: outer
boundary: {type: open, radius: ${2 * R_out - half * 2}}  # quoted or not
mesh: {size: 8}
)";

double r_outer(const CaseSpec& spec, int i) {
  return std::get<SphericalSegment>(spec.geometry3d.parts[i].shape).r_outer;
}

} // namespace

TEST(ParameterExpression, PrecedenceParenthesesUnaryMinusAndNames) {
  const NameLookup x = [](const std::string& n) -> double {
    if (n == "x")
      return 4;
    throw ExpressionError(ExpressionError::Kind::undefined_name, "no " + n, n);
  };
  EXPECT_DOUBLE_EQ(evaluate_expression("1 + 2 * 3", x), 7);
  EXPECT_DOUBLE_EQ(evaluate_expression("(1 + 2) * 3", x), 9);
  EXPECT_DOUBLE_EQ(evaluate_expression("8 / 4 / 2", x), 1); // left to right
  EXPECT_DOUBLE_EQ(evaluate_expression("-x - -1", x), -3);
  EXPECT_DOUBLE_EQ(evaluate_expression(" 2.5e1 * x ", x), 100);
  EXPECT_THROW(evaluate_expression("1 +", x), ExpressionError);
  EXPECT_THROW(evaluate_expression("(1", x), ExpressionError);
  EXPECT_THROW(evaluate_expression("2 ^ 3", x), ExpressionError);
  EXPECT_THROW(evaluate_expression("y", x), ExpressionError);
  EXPECT_THROW(evaluate_expression("1 / (x - 4)", x), ExpressionError); // not finite
  // Nesting is bounded (a stack overflow otherwise): 200 levels pass, 100000 are an error.
  EXPECT_DOUBLE_EQ(evaluate_expression(std::string(199, '(') + "x" + std::string(199, ')'), x), 4);
  EXPECT_THROW(evaluate_expression(std::string(100000, '(') + "1", x), ExpressionError);
  EXPECT_THROW(evaluate_expression(std::string(100000, '-') + "1", x), ExpressionError);
}

TEST(CaseParameters, SubstitutedConvertedAndOverridden) {
  const auto spec = read_case(write_case("param.yaml", parametric));
  // R_in 2.9 cm = 29 mm, R_out = 29 + 1 + 13 = 43 mm; everything then in metres.
  EXPECT_NEAR(r_outer(spec, 0), 0.029, 1e-15);
  EXPECT_NEAR(std::get<SphericalSegment>(spec.geometry3d.parts[1].shape).r_inner, 0.030, 1e-15);
  EXPECT_NEAR(r_outer(spec, 1), 0.043, 1e-15);
  EXPECT_NEAR(std::get<SphericalSegment>(spec.geometry3d.parts[1].shape).theta_max, M_PI / 2,
              1e-15);
  EXPECT_NEAR(spec.geometry3d.outer.radius, 2 * 0.043 - 0.014, 1e-15);
  ASSERT_EQ(spec.parameters.size(), 4u);
  EXPECT_EQ(spec.parameters[0].name, "R_in");
  EXPECT_DOUBLE_EQ(spec.parameters[0].value, 29); // in the case's mm
  EXPECT_EQ(spec.parameters[0].unit, "cm");
  EXPECT_EQ(spec.parameters[2].name, "R_out");
  EXPECT_DOUBLE_EQ(spec.parameters[2].value, 43);
  // Overrides are in the parameter's own unit and flow into the expressions.
  const auto big = read_case(write_case("param.yaml", parametric), {{"R_in", 3.5}, {"gap", 2}});
  EXPECT_NEAR(r_outer(big, 0), 0.035, 1e-15);
  EXPECT_NEAR(r_outer(big, 1), 0.035 + 0.002 + 0.013, 1e-15);
  // Overriding an expression replaces it.
  const auto set = read_case(write_case("param.yaml", parametric), {{"R_out", 49.6}});
  EXPECT_NEAR(r_outer(set, 1), 0.0496, 1e-15);
}

// Each edit is an InputError at the line and field path it names.
TEST(CaseParameters, BadParametersNameTheLineAndField) {
  struct Bad {
    std::string from, to;
    int line;
    std::string field;
    std::string says;
  };
  const std::vector<Bad> cases{
      {"r_outer: ${R_out}", "r_outer: ${R_outer}", 21, "regions[1].r_outer", "undefined"},
      {"gap: 1", "gap: ${half}", 6, "parameters.gap", "gap -> half -> R_out -> gap"},
      {"r_outer: ${R_in}", "r_outer: ${R_in * }", 14, "regions[0].r_outer", "expected"},
      {"r_outer: ${R_in}", "r_outer: ${R_in / (gap - 1)}", 14, "regions[0].r_outer", "finite"},
      {"r_outer: ${R_in}", "r_outer: ${R_in", 14, "regions[0].r_outer", "closing"},
      {"gap: 1", "gap: one", 6, "parameters.gap", "number"},
      {"r_outer: ${R_in}", "r_outer: x${R_in}", 14, "regions[0].r_outer", "number"},
  };
  for (const auto& bad : cases) {
    std::string text = parametric;
    const auto at = text.find(bad.from);
    ASSERT_NE(at, std::string::npos) << bad.from;
    text.replace(at, bad.from.size(), bad.to);
    try {
      read_case(write_case("badparam.yaml", text));
      ADD_FAILURE() << "accepted: " << bad.to;
    } catch (const InputError& e) {
      EXPECT_EQ(e.line(), bad.line) << e.what();
      EXPECT_EQ(e.field(), bad.field) << e.what();
      EXPECT_NE(std::string(e.what()).find("badparam.yaml"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(bad.says), std::string::npos) << e.what();
    }
  }
  try {
    read_case(write_case("param.yaml", parametric), {{"R_mid", 1}});
    ADD_FAILURE() << "accepted an unknown override";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "--param");
    EXPECT_NE(std::string(e.what()).find("R_mid"), std::string::npos) << e.what();
  }
}
