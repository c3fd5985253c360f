// The option table: values reach their handler in order, flags take no value, a missing value
// or an unknown option is an InputError naming it, and a near miss is suggested.
#include <gtest/gtest.h>

#include "core/option_table.hpp"

namespace {

struct Opts {
  std::string out;
  double scale = 1;
  bool quiet = false;
  std::vector<std::string> params;
};

const magfem::OptionTable<Opts>& table() {
  using S = const std::string&;
  static const auto t =
      magfem::OptionTable<Opts>("solve")
          .value("--out", "DIR", [](Opts& o, S, S v) { o.out = v; })
          .value("--mesh-scale", "S", [](Opts& o, S, S v) { o.scale = std::stod(v); })
          .flag("--quiet", [](Opts& o, S, S) { o.quiet = true; })
          .value("--param", "N=V", [](Opts& o, S, S v) { o.params.push_back(v); });
  return t;
}

std::string error_of(const std::vector<std::string>& args) {
  Opts o;
  try {
    table().parse(args, o);
  } catch (const magfem::InputError& e) {
    return e.field() + ": " + e.reason();
  }
  return "";
}

TEST(OptionTable, ValuesFlagsAndPositionalsInOrder) {
  Opts o;
  const auto positional = table().parse(
      {"case.yaml", "--mesh-scale", "2.5", "--quiet", "--param", "a=1", "--param", "b=2", "x"}, o);
  EXPECT_EQ(positional, (std::vector<std::string>{"case.yaml", "x"}));
  EXPECT_EQ(o.scale, 2.5);
  EXPECT_TRUE(o.quiet);
  EXPECT_EQ(o.params, (std::vector<std::string>{"a=1", "b=2"})); // repeatable, in order
  EXPECT_EQ(o.out, "");                                          // not given: untouched
}

TEST(OptionTable, AFlagDoesNotSwallowTheNextArgument) {
  Opts o;
  const auto positional = table().parse({"--quiet", "case.yaml"}, o);
  EXPECT_EQ(positional, std::vector<std::string>{"case.yaml"});
}

TEST(OptionTable, MissingValueAndUnknownOptionsAreNamed) {
  EXPECT_EQ(error_of({"case.yaml", "--out"}), "--out: missing value (DIR)");
  EXPECT_EQ(error_of({"--mesh-scle", "2"}),
            "--mesh-scle: unknown option for solve (did you mean --mesh-scale?)");
  // Far from every option: no guess rather than a misleading one.
  EXPECT_EQ(error_of({"--angles", "0:10:90"}), "--angles: unknown option for solve");
}

TEST(OptionTable, NearestOptionIsATypoNotAnotherWord) {
  const std::vector<magfem::OptionInfo> known = {{"--order", "1|2"}, {"--out", "DIR"}};
  EXPECT_EQ(magfem::nearest_option("--ordre", known), "--order");
  EXPECT_EQ(magfem::nearest_option("--ot", known), "--out");
  EXPECT_EQ(magfem::nearest_option("--resume", known), "");
}

TEST(OptionTable, OptionsListTheTableInOrder) {
  const auto infos = table().options();
  ASSERT_EQ(infos.size(), 4u);
  EXPECT_EQ(infos[0].name, "--out");
  EXPECT_EQ(infos[2].name, "--quiet");
  EXPECT_TRUE(infos[2].value.empty()); // a flag
  EXPECT_EQ(infos[3].value, "N=V");
}

} // namespace
